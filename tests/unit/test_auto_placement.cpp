// crack/auto_placement: grouping yielded zones, the seed's angles, cuts clipped to zones, outlines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "crack/auto_placement.hpp"

namespace edem {
namespace {

// A grid of nx x ny unit squares from the origin, each cut into two counter-clockwise triangles
// by its rising diagonal; zone 2k and 2k + 1 are square k (row by row).
Mesh grid(int nx, int ny) {
  Mesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.gp_position.push_back({static_cast<double>(i), static_cast<double>(j)});
  auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.zone_gp.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.zone_gp.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  mesh.zone_block.assign(mesh.zone_gp.size(), 0);
  mesh.gp_block.assign(mesh.gp_position.size(), 0);
  return mesh;
}

TEST(AutoPlacement, DirectionsCompareAsAxes) {
  EXPECT_DOUBLE_EQ(axis_difference(10, 170), 20);
  EXPECT_DOUBLE_EQ(axis_difference(-80, 80), 20);
  EXPECT_DOUBLE_EQ(axis_difference(0, 90), 90);
  EXPECT_DOUBLE_EQ(axis_difference(30, 210), 0);
}

// Biaxial compression, sigma1 vertical: the Coulomb planes rise at 45 + phi/2 from the horizontal
// (the major principal plane); tension cracks run along sigma1 and across it.
TEST(AutoPlacement, TheSeedsAngles) {
  const auto shear = crack_angles(false, 90.0, 30.0);
  EXPECT_NEAR(shear[0], 60.0, 1e-12);
  EXPECT_NEAR(shear[1], 120.0, 1e-12);
  const auto tension = crack_angles(true, 90.0, 30.0);
  EXPECT_NEAR(tension[0], 0.0, 1e-12);
  EXPECT_NEAR(tension[1], 90.0, 1e-12);
  const auto tilted = crack_angles(false, 30.0, 40.0);  // plane at 120: 120 +- 65
  EXPECT_NEAR(tilted[0], 5.0, 1e-12);
  EXPECT_NEAR(tilted[1], 55.0, 1e-12);
}

// A line through a strip of zones is one cut from edge to edge, joined across shared zone edges.
TEST(AutoPlacement, CutsRunThroughTheZonesAndStopAtTheirEdge) {
  const Mesh mesh = grid(4, 2);
  const std::vector<int> bottom_row = {0, 1, 2, 3, 4, 5, 6, 7};
  const auto cuts = cuts_in_zones(mesh, bottom_row, 0.0, 0.25, {0.0, 0.4}, 0.1);
  ASSERT_EQ(cuts.size(), 4u);  // y = 0.15, 0.4, 0.65, 0.9
  for (const Cut& cut : cuts) {
    EXPECT_NEAR(cut[0].x, 0.0, 1e-12);
    EXPECT_NEAR(cut[1].x, 4.0, 1e-12);
  }
  EXPECT_NEAR(cuts[1][0].y, 0.4, 1e-12);
  // A gap in the zones splits a line; a piece shorter than `shortest` is left out.
  const std::vector<int> with_gap = {0, 1, 4, 5, 6, 7};
  const auto split = cuts_in_zones(mesh, with_gap, 0.0, 10.0, {0.0, 0.5}, 0.1);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_NEAR(split[0][1].x, 1.0, 1e-12);
  EXPECT_NEAR(split[1][0].x, 2.0, 1e-12);
  EXPECT_TRUE(cuts_in_zones(mesh, {0}, 0.0, 10.0, {0.0, 0.5}, 0.6).empty());  // 0.5 long
}

TEST(AutoPlacement, TheOutlineIsTheUnionsBoundary) {
  const Mesh mesh = grid(2, 1);
  const auto outline = union_outline(mesh, {0, 1, 2, 3});
  EXPECT_EQ(outline.size(), 6u);  // the rectangle's six unit edges; the diagonals and x = 1 are inside
  double length = 0.0;
  for (const Cut& e : outline) length += norm(e[1] - e[0]);
  EXPECT_NEAR(length, 6.0, 1e-12);
}

// Zones of a similar principal direction that touch form a region, whatever their mode; a zone
// pointing elsewhere starts its own. The region is a tension region where its tension zones cover
// more than half its area (the seed's "principal reason").
TEST(AutoPlacement, GroupsByDirectionWithTheModeOfMostOfTheArea) {
  const Mesh mesh = grid(3, 1);
  std::vector<YieldedZone> zones = {
      {0, false, 80.0, 30.0}, {1, false, 88.0, 30.0}, {2, false, -85.0, 30.0},  // across +-90
      {3, true, 85.0, 30.0},                                                    // tension
      {4, false, 10.0, 30.0}, {5, false, 15.0, 30.0},                           // elsewhere
  };
  auto regions = group_yielded(mesh, zones, 15.0);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].zones, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_FALSE(regions[0].tension);  // a quarter of its area in tension
  EXPECT_EQ(regions[1].zones, (std::vector<int>{4, 5}));
  zones[1].tension = true;  // half: still shear
  EXPECT_FALSE(group_yielded(mesh, zones, 15.0)[0].tension);
  zones[0].tension = true;  // three quarters
  regions = group_yielded(mesh, zones, 15.0);
  EXPECT_TRUE(regions[0].tension);
  EXPECT_FALSE(regions[1].tension);
}

// With by_mode, a zone of the other mode starts its own region too.
TEST(AutoPlacement, GroupsByModeAndDirection) {
  const Mesh mesh = grid(3, 1);
  std::vector<YieldedZone> zones = {
      {0, false, 80.0, 30.0}, {1, false, 88.0, 30.0}, {2, false, -85.0, 30.0},  // one region, across +-90
      {3, true, 85.0, 30.0},                                                    // tension
      {4, false, 10.0, 30.0}, {5, false, 15.0, 30.0},                           // pointing elsewhere
  };
  const auto regions = group_yielded(mesh, zones, 15.0, true);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_EQ(regions[0].zones, (std::vector<int>{0, 1, 2}));
  EXPECT_FALSE(regions[0].tension);
  EXPECT_NEAR(axis_difference(regions[0].principal, 89.0), 0.0, 2.0);
  EXPECT_EQ(regions[1].zones, (std::vector<int>{3}));
  EXPECT_TRUE(regions[1].tension);
  EXPECT_EQ(regions[2].zones, (std::vector<int>{4, 5}));
}

// Every cut end is a vertex of the outline: rounded, it would never lie exactly on an edge, and
// the cutter would drop the cut as ending inside a block.
// All 32 zones of grid(4, 4) yielded in shear, their most compressive stress at `angle`.
std::vector<YieldedZone> all_in_shear(double angle) {
  std::vector<YieldedZone> zones;
  for (int z = 0; z < 32; ++z) zones.push_back({z, false, angle, 30.0});
  return zones;
}

TEST(AutoPlacement, CutEndsAreOutlineVertices) {
  const Mesh mesh = grid(4, 4);
  const auto regions = place_cracks(mesh, all_in_shear(90.0), 0.7, 15.0);
  ASSERT_EQ(regions.size(), 1u);
  ASSERT_FALSE(regions[0].cuts.empty());
  for (const Cut& cut : regions[0].cuts)
    for (const Vec2 end : cut) {
      const bool vertex = std::any_of(regions[0].outline.begin(), regions[0].outline.end(),
                                      [&](const Cut& e) { return e[0] == end || e[1] == end; });
      EXPECT_TRUE(vertex) << "cut end (" << end.x << ", " << end.y << ") is not an outline vertex";
    }
  double length = 0.0;
  for (const Cut& e : regions[0].outline) length += norm(e[1] - e[0]);
  EXPECT_NEAR(length, 16.0, 1e-9);  // the square's perimeter, split but not changed
}

// Every cut lies on a line of its set's grid: its distance from the grid's origin, across the
// cut, is a whole number of spacings.
bool on_grid(const Cut& cut, Vec2 origin, double spacing) {
  const Vec2 along = (1.0 / norm(cut[1] - cut[0])) * (cut[1] - cut[0]);
  const Vec2 d = cut[0] - origin;
  const double across = d.x * along.y - d.y * along.x;
  const double steps = across / spacing;
  return std::fabs(steps - std::round(steps)) < 1e-9;
}

TEST(AutoPlacement, CutsRunThroughTheCentroidOrTheOriginGiven) {
  const Mesh mesh = grid(4, 4);
  const std::vector<YieldedZone> zones = all_in_shear(30.0);
  const auto own = place_cracks(mesh, zones, 0.7, 15.0);
  ASSERT_EQ(own.size(), 1u);
  EXPECT_NEAR(own[0].origin.x, 2.0, 1e-12);
  EXPECT_NEAR(own[0].origin.y, 2.0, 1e-12);
  const Vec2 given{0.3, -0.1};
  const auto anchored = place_cracks(mesh, zones, 0.7, 15.0, given);
  ASSERT_EQ(anchored.size(), 1u);
  EXPECT_EQ(anchored[0].origin, given);
  ASSERT_FALSE(own[0].cuts.empty());
  ASSERT_FALSE(anchored[0].cuts.empty());
  int off_own_grid = 0;
  for (const Cut& cut : own[0].cuts) EXPECT_TRUE(on_grid(cut, own[0].origin, 0.7));
  for (const Cut& cut : anchored[0].cuts) {
    EXPECT_TRUE(on_grid(cut, given, 0.7));
    if (!on_grid(cut, own[0].origin, 0.7)) ++off_own_grid;
  }
  EXPECT_GT(off_own_grid, 0) << "the origin given moved the cuts";
}

// A group that no line through the point given crosses (here every line runs 43 m or more from
// the square) is cut through its own centroid instead of being left without potential cracks.
TEST(AutoPlacement, AGroupTheGridMissesIsCutThroughItsCentroid) {
  const Mesh mesh = grid(4, 4);
  const Vec2 far_off{52.0, 2.0};
  const auto regions = place_cracks(mesh, all_in_shear(90.0), 100.0, 15.0, far_off);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].origin, (Vec2{2.0, 2.0}));
  ASSERT_EQ(regions[0].cuts.size(), 2u);  // one a set, each through the centre
  for (const Cut& cut : regions[0].cuts) EXPECT_TRUE(on_grid(cut, Vec2{2.0, 2.0}, 100.0));
  for (const Cut& cut : regions[0].cuts) EXPECT_FALSE(on_grid(cut, far_off, 100.0));
}

// A lone tension zone inside a shear region: grouped by mode it is a region of its own (dropped
// here: too small for a cut), and the shear region's outline, glued, rings the hole it leaves, so
// the cuts stop at it; grouped by direction there is one region, its outline the square's alone.
TEST(AutoPlacement, ALoneZoneOfTheOtherModeIsNotRingedByAnOutline) {
  const Mesh mesh = grid(4, 4);
  std::vector<YieldedZone> zones = all_in_shear(90.0);
  zones[10].tension = true;  // square (1, 1), the lower of its two triangles
  auto outline_length = [](const CrackRegion& r) {
    double length = 0.0;
    for (const Cut& e : r.outline) length += norm(e[1] - e[0]);
    return length;
  };
  const auto together = place_cracks(mesh, zones, 0.7, 15.0);
  ASSERT_EQ(together.size(), 1u);
  EXPECT_FALSE(together[0].tension);
  EXPECT_EQ(together[0].zones.size(), 32u);
  EXPECT_NEAR(outline_length(together[0]), 16.0, 1e-9);
  const auto apart = place_cracks(mesh, zones, 0.7, 15.0, std::nullopt, true);
  ASSERT_EQ(apart.size(), 1u);
  EXPECT_EQ(apart[0].zones.size(), 31u);
  EXPECT_NEAR(outline_length(apart[0]), 16.0 + 2.0 + std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace edem
