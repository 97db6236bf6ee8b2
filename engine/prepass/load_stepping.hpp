// One stage of the prepass: Newton (KINSOL, with line search) on the implicit problem, its
// out-of-balance force at the start applied in load steps, cut back when Newton fails.
#pragma once

#include <chrono>
#include <functional>

#include <string>
#include <vector>

#include "prepass/implicit_problem.hpp"
#include "prepass/prepass.hpp"

namespace edem {

// Solves the problem from its start (p.u0, p.stress0): R0, the out-of-balance force there, is
// applied in steps; at load factor a the system is force(u) - (1 - a) R0 = 0. On return p.u0 and
// p.stress0 are the solution, and `yielded` (per problem zone) has the state bits of every
// converged step or'ed in. A stage whose step fails after the cut-backs is solved again from its
// start in twice as many steps, settings.restarts times; throws edem::Error naming `stage` when the
// last attempt fails too (settings.keep_on_failure: returns with log.failure set instead).
// `step_done`, if given, hears of every load step tried: the load factor reached and the stage's
// Newton iterations so far (progress reports).
using StepDone = std::function<void(double reached, int iterations)>;
// The stage fails, saying so, once `deadline` has passed (checked at every Newton iteration).
StageLog solve_stage(const Mechanics& m, ImplicitProblem& p, const NewtonSettings& settings, const std::string& stage,
                     std::vector<std::uint8_t>& yielded, const StepDone& step_done = {},
                     std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

}  // namespace edem
