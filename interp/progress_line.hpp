// The progress line of a long cycle() or solve{}: where the run stands, how long it has run and
// about how long it has left, and what changed when the ratio jumped.
#pragma once

#include <string>

#include "core/physics_defs.hpp"

namespace edem {

// "cycle 5120 (5120 of 20000), ratio 2.93e-06 (to 1e-06), cracks 0, stage 0, 5111 cycles/s, 1 s
// run, about 2 s left; ratio up 12 times since the last line: 3 new cracks". `last` is the run's
// previous report (all zero for its first).
std::string progress_line(const RunProgress& last, const RunProgress& now);

// "prepass: stage 3 of 17 (warhead_arch_right), load factor 0.62, 240 Newton iterations, 12 s run".
std::string prepass_progress_line(const PrepassProgress& p);

// Seconds as "42 s", "3 min 05 s" or "2 h 07 min".
std::string clock_time(double seconds);

}  // namespace edem
