// Zoning: meshing blocks into quality triangles with a graded size field.
//
// Constrained Delaunay refinement (CGAL, Ruppert's algorithm with Shewchuk's clusters), each
// block on its own. The target edge length is `edge` inside and next to the `near` polygons
// and grows linearly with distance, at rate `growth`, up to `far`.
//
// What zone_blocks() guarantees, block by block:
//  * gridpoints: every ring vertex is a gridpoint with its exact coordinates; the mesher adds
//    points on ring edges (midpoints, rounded) and inside. A block's boundary gridpoints come
//    first, in loop order, then its interior ones; interior gridpoints and zones are in
//    Z-order (spatially local).
//  * boundary: block_boundary[b] holds the outer loop (counter-clockwise, from the outer ring's
//    first vertex) then one loop per hole (clockwise, from its first vertex); each segment
//    carries the EdgeOrigin of the ring edge it lies on.
//  * zones: counter-clockwise, positive area, tiling the block: their areas sum to its area
//    (to rounding, ~1e-15 relative).
//  * size: every zone's longest edge is at most SizeField::at(zone centroid), no slack factor.
//  * shape: every zone angle is at least kMinZoneAngle except where the block's own corner is
//    sharper. Precisely: a zone angle below kMinZoneAngle is always a whole block corner, i.e.
//    it sits at a ring vertex whose interior angle is that same angle (a sharp corner is never
//    split, so exactly one zone touches it). Checked on ~12000 random blocks (stars with spikes
//    and notches, combs, holes, jointed pieces): no exception found. Corners of 20 to 60 deg
//    need no exemption.
//  * cost: a corner of angle a (rad) needs about 5/a zones to grade down to it, so a 0.01 deg
//    wedge gets ~30000 zones; a block that would need more than max_zones_per_block zones makes
//    zone_blocks() throw edem::Error instead of running out of time or memory.
#pragma once

#include <vector>

#include "geom/block_set.hpp"
#include "geom/mesh.hpp"
#include "geom/polygon.hpp"

namespace edem {

struct SizeField {
  double edge = 1.0;          // target edge length near the `near` polygons [m]
  double far = 1.0;           // largest edge length, far from them [m]
  double growth = 0.2;        // increase of edge length per metre of distance [-]
  std::vector<Polygon> near;  // where the mesh is finest; empty: uniform `edge`
  // Target edge length at a point [m]: min(far, edge + growth * d), d the distance to the
  // nearest `near` polygon (0 inside it); `edge` everywhere when `near` is empty.
  double at(Vec2 point) const;
};

// Minimum zone angle the mesher guarantees away from sharp block corners [deg].
inline constexpr double kMinZoneAngle = 20.0;

// Most zones one block may get; beyond it zoning stops with an error instead of running out
// of memory or time.
inline constexpr int kMaxZonesPerBlock = 5'000'000;

// Mesh the given blocks, each with its own size field, into one Mesh whose block numbering
// follows `blocks` (size_of_block.size() == blocks.blocks.size()). Gridpoints and zones are
// contiguous per block (block_first_gp, block_first_zone: CSR, size blocks + 1). Blocks with no
// size field (nullptr) get no zones, no gridpoints and no boundary loops. Throws edem::Error for
// an invalid size field (edge <= 0, far < edge, growth < 0), a ring with fewer than 3 vertices
// or repeated consecutive vertices, crossing rings, or a block over the zone budget.
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block);
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block,
                 int max_zones_per_block);

}  // namespace edem
