// Blocks that meet within the tolerance meet exactly: one block's corner a hair from another's
// corner, or from another's edge, is moved onto it, and a corner a hair from one's own edge, or
// on it only to round-off, is put into that edge, whichever block came first. Blocks are zoned
// together where they touch, and two corners 1e-300 m apart, or a corner off an edge's line by
// round-off, made the mesh refine towards the gap without end.
#pragma once

#include <vector>

#include "core/vec2.hpp"

namespace edem {

// `blocks` snapped in order, each to those before it, within `tolerance` [m]; adds the corners
// moved or put in to `*snapped`.
std::vector<Polygon> snap_blocks_together(const std::vector<Polygon>& blocks, double tolerance, int* snapped);

}  // namespace edem
