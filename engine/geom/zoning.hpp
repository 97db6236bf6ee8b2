// Zoning: meshing blocks into quality triangles with a graded size field.
//
// Constrained Delaunay refinement (CGAL, Ruppert's algorithm with Shewchuk's clusters). Blocks
// that touch along an edge, glued (EdgeOrigin::glued, region outlines) or not (joints, cracks),
// are meshed together in one triangulation, so that both sides of every shared edge get
// gridpoints at the same places; a block touching no other is meshed exactly as if it were
// alone. The target edge length is `edge` inside and next to the `near` polygons and grows
// linearly with distance, at rate `growth`, up to `far`.
//
// What zone_blocks() guarantees, block by block:
//  * gridpoints: every ring vertex is a gridpoint with its exact coordinates; the mesher adds
//    points on ring edges (midpoints, rounded) and inside. A block's boundary gridpoints come
//    first, in loop order, then its interior ones; interior gridpoints and zones are in
//    Z-order (spatially local). Each block has gridpoints of its own: those on an edge two
//    blocks share are there twice, once per block.
//  * shared edges: along every ring edge that two zoned blocks share, both blocks have the same
//    gridpoints: the same number, bit-identical coordinates. A solver merges them where the
//    edge is glued (either side marks it so) and keeps them apart across a joint or crack, whose
//    faces then start matched (a uniform joint stress gives a uniform closure). Blocks are
//    joined when an edge of one runs along an edge of the other the other way (same end
//    points, or, for blocks built by hand, a common stretch); blocks joined directly or through
//    others form a group, meshed together.
//  * boundary: block_boundary[b] holds the outer loop (counter-clockwise, from the outer ring's
//    first vertex) then one loop per hole (clockwise, from its first vertex); each segment
//    carries the EdgeOrigin of the ring edge it lies on.
//  * zones: counter-clockwise, positive area, tiling the block: their areas sum to its area
//    (to rounding, ~1e-15 relative).
//  * size: every zone's longest edge is at most SizeField::at(zone centroid), no slack factor.
//    A group takes the pointwise minimum of its blocks' distinct size fields (its shared
//    edges are split alike for both sides), so a block next to a finer one gets smaller zones
//    near it than its own field asks for; all blocks with one field share it unchanged.
//  * shape: every zone angle is at least kMinZoneAngle except where the block's own corner is
//    sharper. Precisely: a zone angle below kMinZoneAngle is always a whole block corner, i.e.
//    it sits at a ring vertex whose interior angle is that same angle (a sharp corner is never
//    split, so exactly one zone touches it). Checked on ~12000 random blocks (stars with spikes
//    and notches, combs, holes, jointed pieces): no exception found. Corners of 20 to 60 deg
//    need no exemption. One more exception in groups: a sharp corner (below the mesher's
//    shape bound, asin(sqrt(0.125)) = 20.7 deg) at a vertex that other blocks of its group
//    share is lopped, cut off by a short lid at most size / 2 from its apex and left out of
//    the refinement, which otherwise never ends there; the few zones inside that cut-off
//    triangle may have any angle. Every zone elsewhere keeps the rule, the neighbours' included.
//    Checked on ~1000 random fans of glued slices and ~400 random boxes cut by glued regions
//    and joints: no other exception found.
//  * cost: a corner of angle a (rad) needs about 5/a zones to grade down to it, so a 0.01 deg
//    wedge gets ~30000 zones; a group that would need more than max_zones_per_block zones in
//    all makes zone_blocks() throw edem::Error (naming a block of it) instead of running out of
//    time or memory.
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

// About how many zones `size` makes in `blocks`, before any meshing: the blocks' area over an
// equilateral zone's at the size there (sampled on a 200 x 200 grid over them), and for a block
// thinner than its zones its perimeter over twice its width (zones of good shape in a strip are
// no longer than it is wide).
double estimated_zone_count(const std::vector<Polygon>& blocks, const SizeField& size);

// Minimum zone angle the mesher guarantees away from sharp block corners [deg].
inline constexpr double kMinZoneAngle = 20.0;

// Most zones one block, or one group of touching blocks, may get; beyond it zoning stops with an
// error instead of running out of memory or time.
inline constexpr int kMaxZonesPerBlock = 5'000'000;

// Mesh the given blocks, each with its own size field, into one Mesh whose block numbering
// follows `blocks` (size_of_block.size() == blocks.blocks.size()). Gridpoints and zones are
// contiguous per block (block_first_gp, block_first_zone: CSR, size blocks + 1). Blocks with no
// size field (nullptr) get no zones, no gridpoints and no boundary loops, and join no group.
// Throws edem::Error for an invalid size field (edge <= 0, far < edge, growth < 0), a ring with
// fewer than 3 vertices or repeated consecutive vertices, crossing rings, overlapping blocks in
// a group, or a block or group over the zone budget.
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block);
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block,
                 int max_zones_per_block);

}  // namespace edem
