// The explicit cycle: zones (strain rate, mixed discretisation, constitutive update, nodal
// forces), then nodes (sum forces, damping, integrate).
#pragma once

#include "state/mechanics.hpp"
#include "state/motion.hpp"

namespace edem {

// Runs `count` cycles (>= 1) on prepared mechanics, each taking its step off a running release;
// the last one measures. Deterministic: the same bits for any thread count.
Measure run_cycles(Mechanics& m, int count);

// Measures the current state without moving anything: the unbalanced forces of the current
// stresses and loads (for the ratio before any cycle).
Measure measure_state(const Mechanics& m);

}  // namespace edem
