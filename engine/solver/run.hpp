// Running cycles on prepared mechanics: the loop behind cycle() and solve().
#pragma once

#include "geom/mesh.hpp"
#include "state/mechanics.hpp"

namespace edem {

// Runs up to max_cycles cycles, stopping early when target_ratio > 0 and the unbalanced-force
// ratio (sum of |unbalanced force| over free components / sum of |every force contribution|,
// FLAC3D's "average ratio") is at most target_ratio; it is measured before the first cycle, so
// a model already in equilibrium takes none. Prepares the arrays first (and again when a
// callback changes the model). The watchdog throws edem::Error, naming the cycle, the place
// and the likely cause, when the run goes unstable; exceptions from callbacks pass through.
// With settle > 0, a state at target_ratio is solved on under adaptive damping to settle before
// it counts (and, judged at equilibrium, is judged); after a judgment that broke sections the
// next state is approached under the set damping again, which the solve gives back at its end.
SolveResult run_solver(Mechanics& m, const Mesh& mesh, long max_cycles, double target_ratio, long stall = 0,
                       double settle = 0.0, double balance = 0.0);

}  // namespace edem
