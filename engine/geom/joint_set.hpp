// Joint-set traces: parallel lines at given spacings, broken into traces and gaps, with
// optional uniform random deviations (UDEC's jset), covering a box.
#pragma once

#include <vector>

#include "geom/cutter.hpp"
#include "core/defs.hpp"

namespace edem {

// Traces of `def` that may cross `extent`, tagged as joints of set `set`. Each trace is
// clipped to clip polygon `clip` by the cutter (-1: none). Deterministic for a given seed.
std::vector<CutSegment> joint_set_traces(const JointSetDef& def, const Box& extent, int set,
                                         int clip);

}  // namespace edem
