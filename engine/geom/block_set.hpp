// The blocks of a model: faces of the arrangement of every cut, with the origin of each edge.
//
// Produced by cut_blocks() (cutter.hpp) from the model's inputs; owned by the Model and
// rebuilt whenever a geometry command changes the inputs. Coordinates are doubles that
// were computed exactly and rounded once.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/vec2.hpp"
#include "geom/polygon.hpp"

namespace edem {

// What made a block edge. Ordered by precedence: when several inputs lie along one edge,
// the lowest kind names it (a joint along the model boundary is still boundary).
enum class EdgeKind : std::uint8_t { boundary, joint, crack, region, potential };

std::string_view to_string(EdgeKind kind);

struct EdgeOrigin {
  EdgeKind kind = EdgeKind::boundary;
  int set = -1;        // joint set index (kind joint), else -1
  int source = -1;     // index of the input: block, joint set, crack or region
  bool glued = false;  // glued edges never fail or slide (region outlines)
};

// A closed loop of vertices; edges[i] joins points[i] to points[(i + 1) % n].
struct Ring {
  std::vector<Vec2> points;
  std::vector<EdgeOrigin> edges;
};

struct Block {
  Ring outer;               // counter-clockwise
  std::vector<Ring> holes;  // clockwise, inside `outer`
  double area = 0.0;        // [m^2], holes removed
  Vec2 centroid;            // [m]
  int base = -1;            // the block{} input it was cut from
  std::vector<int> regions; // indices of the named regions that contain it
};

struct BlockSet {
  std::vector<Block> blocks;
  int dropped_cuts = 0;      // cut pieces that crossed no block and were dropped (as UDEC does)
  int joint_edges = 0;       // arrangement edges made by joints between two blocks
  int snapped_vertices = 0;  // cut vertices moved by at most the tolerance to avoid slivers
  // Spots where required cuts could not be bent clear of a zone-size tolerance: slivers kept there.
  int slivers_kept = 0;
  int cuts_left_out = 0;     // optional and last-resort cut pieces left out: no bending kept them the
                             // tolerance apart
  int cuts_cut_back = 0;     // optional cut pieces cut back from a corner sharper than their min_angle
};

}  // namespace edem
