// Blocks that meet within the tolerance are made to meet exactly.
#include <gtest/gtest.h>

#include "geom/block_snap.hpp"
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
