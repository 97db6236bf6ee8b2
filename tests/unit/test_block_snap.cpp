// Blocks that meet within the tolerance are made to meet exactly.
#include <gtest/gtest.h>

#include "geom/block_snap.hpp"
#include "geom/polygon.hpp"
#include "model/model.hpp"

namespace edem {
namespace {

TEST(BlockSnap, BlocksThatShareTheirCornersExactlyAreLeftAlone) {
  int snapped = 0;
  const auto out = snap_blocks_together({{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {{0, 1}, {2, 1}, {2, 2}, {0, 2}}}, 1e-6, &snapped);
  EXPECT_EQ(snapped, 0);
  EXPECT_EQ(out[1], (Polygon{{0, 1}, {2, 1}, {2, 2}, {0, 2}}));
}

TEST(BlockSnap, ACornerAHairFromAnotherIsMovedOntoIt) {
  int snapped = 0;
  const auto out =
      snap_blocks_together({{{0, -1}, {2, -1}, {2, 0}, {0, 0}}, {{1e-300, 0}, {2, 0}, {2, 1}, {0, 1}}}, 1e-6, &snapped);
  EXPECT_EQ(snapped, 1);
  EXPECT_EQ(out[1][0].x, 0.0);
  EXPECT_EQ(out[1][0].y, 0.0);
}

TEST(BlockSnap, ACornerAHairAboveAnEdgeIsMovedOntoItsLine) {
  int snapped = 0;
  const auto out =
      snap_blocks_together({{{0, -1}, {4, -1}, {4, 0}, {0, 0}}, {{1, 1e-9}, {3, 1e-9}, {3, 1}, {1, 1}}}, 1e-6, &snapped);
  EXPECT_EQ(snapped, 2);
  EXPECT_EQ(out[1][0].y, 0.0);
  EXPECT_EQ(out[1][1].y, 0.0);
  EXPECT_EQ(out[1][0].x, 1.0);
}

TEST(BlockSnap, AnEarlierCornerAHairFromANewEdgeIsPutIntoIt) {
  // The second block's bottom edge passes 1e-9 m below the first block's corner (2, 0).
  int snapped = 0;
  const auto out =
      snap_blocks_together({{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {{0, -1e-9}, {4, -1e-9}, {4, -1}, {0, -1}}}, 1e-6, &snapped);
  EXPECT_GE(snapped, 1);
  bool has_corner = false;
  for (const Vec2& p : out[1]) has_corner |= p.x == 2.0 && p.y == 0.0;
  EXPECT_TRUE(has_corner);
}

TEST(BlockSnap, ANewCornerOnAnEarlierEdgeOnlyToRoundOffIsPutIntoThatEdge) {
  // (0.05, -0.05 * 0.01) is no distance in doubles from the edge (0, 0)-(1, -0.01), and 3e-20 m
  // off its line exactly.
  const Vec2 corner{0.05, -0.05 * 0.01};
  ASSERT_EQ(segment_distance(corner, {0, 0}, {1, -0.01}), 0.0);
  ASSERT_FALSE(on_line_exactly(corner, {0, 0}, {1, -0.01}));
  int snapped = 0;
  const auto out = snap_blocks_together(
      {{{0, 0}, {1, -0.01}, {1, 1}, {0, 1}}, {{0, -1}, {0.05, -1}, corner, {0, 0}}}, 1e-6, &snapped);
  EXPECT_EQ(snapped, 1);
  EXPECT_EQ(out[0], (Polygon{{0, 0}, corner, {1, -0.01}, {1, 1}, {0, 1}}));
}

TEST(BlockSnap, ACornerExactlyOnAnEarlierEdgeLeavesThatEdgeWhole) {
  int snapped = 0;
  const auto out = snap_blocks_together(
      {{{-3, -1}, {8, -1}, {8, 0}, {-3, 0}}, {{-1, 0}, {1, 0}, {1, 1}, {-1, 1}}}, 1e-6, &snapped);
  EXPECT_EQ(snapped, 0);
  EXPECT_EQ(out[0], (Polygon{{-3, -1}, {8, -1}, {8, 0}, {-3, 0}}));
}

// Four blocks at a slipped crossing on a joint falling 1 in 100, the upper two meeting on it
// at a point that lies on the lower right block's top only to round-off: the mesh refined
// towards that point without end.
TEST(BlockSnap, BlocksMeetingOnASlantedEdgeToRoundOffAreZonedAtOnce) {
  Model model(ModelDef{"slipped crossing"});
  model.add_block(BlockDef{{{-1, -1}, {0, -1}, {0, 0}, {-1, 0}}});
  model.add_block(BlockDef{{{0, -1}, {1, -1}, {1, -0.01}, {0, 0}}});
  model.add_block(BlockDef{{{-1, 0}, {0, 0}, {0.05, -0.05 * 0.01}, {0.05, 1}, {-1, 1}}});
  model.add_block(BlockDef{{{0.05, -0.05 * 0.01}, {1, -0.01}, {1, 1}, {0.05, 1}}});
  ZoneDef zone;
  zone.edge = 0.25;
  model.zone(zone);
  EXPECT_GT(model.info().zones, 0);
  EXPECT_LT(model.info().zones, 400);  // 2 m x 2 m at 0.25 m
}

// A fuzzed script: block corners 1e-300 m apart made zoning refine towards the gap without end.
TEST(BlockSnap, BlocksWithCornersFarBelowTheToleranceApartAreZonedAtOnce) {
  Model model(ModelDef{"gap"});
  model.add_block(BlockDef{{{0, -1}, {2, -1}, {2, 0}, {0, 0}}});
  model.add_block(BlockDef{{{1e-300, 0}, {2, 0}, {2, 1}, {0, 1}}});
  ZoneDef zone;
  zone.edge = 0.25;
  model.zone(zone);
  EXPECT_LT(model.info().zones, 400);  // 2 m x 2 m at 0.25 m
  EXPECT_GE(model.info().snapped, 1);
}

}  // namespace
}  // namespace edem
