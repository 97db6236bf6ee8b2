// The explicit cycle: zones (strain rate, mixed discretisation, constitutive update, nodal
// forces), then nodes (sum forces, damping, integrate).
#pragma once

#include <vector>

#include "state/mechanics.hpp"
#include "state/motion.hpp"

namespace edem {

// Runs `count` cycles (>= 1) on prepared mechanics, each taking its step off a running release;
// the last one measures. Deterministic: the same bits for any thread count.
Measure run_cycles(Mechanics& m, int count);

// Measures the current state without moving anything: the unbalanced forces of the current
// stresses and loads (for the ratio before any cycle).
Measure measure_state(const Mechanics& m);

// The forces the zones' stresses and the contacts put on the nodes now, without a step [N/m, by
// dof]: no weight, loads or bolts. Adds their magnitudes to *applied when given.
std::vector<double> standing_forces(const Mechanics& m, double* applied = nullptr);

}  // namespace edem
