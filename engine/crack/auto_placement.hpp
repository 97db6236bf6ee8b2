// Potential cracks placed where a prepass found the rock yielding (the seed paper's §2.2):
// the yielded zones grouped into regions of one failure mode and one principal direction, and in
// each region two sets of parallel cuts, clipped to the region's zones.
//
// Grouping: a yielded zone is a tension zone if it yielded in tension at any stage, else a shear
// zone. Zones touch when they share a corner's place (across a joint too). A region grows from the
// lowest-numbered zone not yet taken, through touching zones whose most compressive principal
// direction is within `similar` degrees of that first zone's (axes: 0 and 180 are the same), until
// none is left to add; then the next region starts. As the seed has it (its §2.2), regions are
// those of one principal direction, and each is a tension region where tension is the principal
// reason: where its tension zones cover more than half its area; else a shear region. With
// `by_mode`, a region also keeps to the mode of its first zone: then a few zones of the other mode
// carve a region into ragged pieces whose outlines, glued, break the cuts near an opening's wall.
//
// Orientation, from the region's mean principal direction (area-weighted, as axes): the major
// principal plane is normal to the most compressive stress. Shear regions get two sets at
// +-(45 + phi/2) from that plane (the Coulomb failure planes, phi the regions' mean friction);
// tension regions one set along the plane and one across it.
//
// Cuts: lines `spacing` apart, one through the region's centroid, kept where they run through the
// region's zones; a piece shorter than the region's mean zone edge (one section at most) is left
// out. The region's outline (the zone edges on the boundary of its zones' union that are not on a
// block's boundary already) becomes a glued cut too, as a region{}'s does: a piece ends on it and
// so splits a block (a piece that ended inside a block would be dropped, as UDEC drops it).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/vec2.hpp"
#include "geom/mesh.hpp"

namespace edem {

struct YieldedZone {
  int zone = -1;          // mesh zone
  bool tension = false;   // tension governs (it yielded in tension), else shear
  double angle = 0.0;     // direction of the most compressive principal stress, from +x [deg]
  double friction = 0.0;  // friction angle of the rock that judges it [deg]
};

using Cut = std::array<Vec2, 2>;

struct CrackRegion {
  bool tension = false;
  double principal = 0.0;       // mean most compressive principal direction, (-90, 90] [deg]
  double friction = 0.0;        // mean friction angle [deg]
  std::vector<double> angles;   // the two sets, [0, 180) [deg]
  std::vector<int> zones;       // mesh zones, ascending
  Vec2 origin;                  // one cut of each set passes through it: as given, else centroid [m]
  std::vector<Cut> cuts;
  std::vector<Cut> outline;     // the boundary edges of the union of its zones
};

// Difference between two directions taken as axes, in [0, 90] [deg].
double axis_difference(double a, double b);

// The regions of the yielded zones (see above), in order of their first zone.
std::vector<CrackRegion> group_yielded(const Mesh& mesh, const std::vector<YieldedZone>& zones,
                                       double similar, bool by_mode = false);

// The two set directions of a region from its mode, principal direction and friction.
std::vector<double> crack_angles(bool tension, double principal, double friction);

// The pieces of the lines at `angle` [deg], `spacing` apart and one through `origin`, that lie inside
// the union of `zones`; pieces shorter than `shortest` are left out. Ordered by line, then along it.
std::vector<Cut> cuts_in_zones(const Mesh& mesh, const std::vector<int>& zones, double angle, double spacing,
                               Vec2 origin, double shortest);

// The edges of `zones` on the boundary of their union (an edge two of them share, by its places,
// is inside), less those on a block's boundary. In zone order, each counter-clockwise about its zone.
std::vector<Cut> union_outline(const Mesh& mesh, const std::vector<int>& zones);

// group_yielded, then the angles, cuts and outline of every region (regions with no cut left are dropped).
// The cuts of every set pass through `origin` if given, else through their region's centroid; a
// region no line through `origin` crosses is cut through its centroid.
std::vector<CrackRegion> place_cracks(const Mesh& mesh, const std::vector<YieldedZone>& zones,
                                      double spacing, double similar,
                                      const std::optional<Vec2>& origin = std::nullopt,
                                      bool by_mode = false);

}  // namespace edem
