// Zones and gridpoints of the model: each block meshed into triangles on its own.
//
// Flat arrays indexed by integers. Gridpoints of one block are contiguous, and so are its
// zones; gridpoints on a joint are distinct on its two sides. Along a glued edge both blocks
// have gridpoints at the same places (zoning.hpp), which the solver merges into one node.
// Zones are counter-clockwise. A block's boundary is kept as ordered gridpoint loops so that
// contacts can walk it.
#pragma once

#include <array>
#include <vector>

#include "core/vec2.hpp"
#include "geom/block_set.hpp"

namespace edem {

struct BoundaryLoop {
  std::vector<int> gridpoints;      // ordered; the outer loop counter-clockwise, holes clockwise
  std::vector<EdgeOrigin> edges;    // edges[i] joins gridpoints[i] and gridpoints[i + 1]
};

struct Mesh {
  // gridpoints
  std::vector<Vec2> gp_position;    // [m]
  std::vector<int> gp_block;
  // zones: three gridpoints, counter-clockwise
  std::vector<std::array<int, 3>> zone_gp;
  std::vector<int> zone_block;
  // per block: [first, last) ranges, size blocks + 1
  std::vector<int> block_first_gp;
  std::vector<int> block_first_zone;
  std::vector<std::vector<BoundaryLoop>> block_boundary;  // outer loop first, then holes

  int zone_count() const { return static_cast<int>(zone_gp.size()); }
  int gp_count() const { return static_cast<int>(gp_position.size()); }
  double zone_area(int zone) const;
  Vec2 zone_centroid(int zone) const;
};

}  // namespace edem
