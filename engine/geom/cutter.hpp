// Cutting blocks: the arrangement of base polygons and cut segments, with exact predicates.
//
// Each base polygon is cut by every segment that crosses it. Faces inside the polygon become
// blocks. Pieces of cuts that end inside a block without splitting it are dropped and counted
// (UDEC's rule). Features smaller than the tolerance (a cut passing within `tolerance` of a
// vertex, a nearly parallel cut forming a sliver) are resolved by bending the cut through the
// vertex, so no block has an edge or a thickness below the tolerance and none has zero area; the
// tolerance at a point is the larger of `tolerance` and `local_tolerance` there.
// Where bending cannot resolve a feature, an optional cut taking part in it (the automatic
// potential cracks) is left out and counted; where none is, a last-resort cut (the outline of an
// automatic group) is, and counted with them. Where required cuts still keep coming closer (bent
// by optional ones that gave way since), the base starts again from the cuts as given, less the
// optional and last-resort ones near the spot, within a radius that doubles each time (counted
// too); where none is left to go, it fails with a message naming the cuts.
// An optional cut with a min_angle that would make a block corner sharper than that loses its
// stretch at the corner, back to its crossings either side (no thin wedge; counted too).
#pragma once

#include <functional>
#include <vector>

#include "geom/block_set.hpp"
#include "geom/polygon.hpp"

namespace edem {

struct CutSegment {
  Vec2 a, b;           // end points [m]
  EdgeOrigin origin;   // what it is
  int clip = -1;       // keep only the part inside clip_polygons[clip] (-1: no clipping)
  bool optional = false;  // may be left out where it cannot be laid without a feature below the tolerance
  // Optional cuts only: where one meets another edge at a corner sharper than this [deg], its
  // stretch there is cut back to the crossings on either side (0: never).
  double min_angle = 0.0;
  // May be left out as optional cuts are, but only where no optional cut taking part in the
  // feature is left to give way (a crackseed{ auto } group's outline: glued, it only ends the
  // group's cuts, and a stretch of it left out leaves the rock there whole).
  bool last_resort = false;
};

struct CutInput {
  std::vector<Polygon> bases;          // block{} inputs, validated, non-overlapping
  std::vector<CutSegment> cuts;        // joints, cracks
  std::vector<Polygon> clip_polygons;  // for CutSegment::clip
  std::vector<Polygon> regions;        // named regions: their outlines are cuts too
  std::vector<bool> region_glued;      // per region: outline edges never fail or slide
  double tolerance = 0.0;              // absolute [m]
  // A larger tolerance where the blocks will be zoned coarsely [m]: no block edge shorter than a
  // fraction of the zones there (Model::cut); empty: `tolerance` everywhere. `largest_tolerance`
  // bounds it.
  std::function<double(Vec2)> local_tolerance;
  double largest_tolerance = 0.0;
};

BlockSet cut_blocks(const CutInput& input);

}  // namespace edem
