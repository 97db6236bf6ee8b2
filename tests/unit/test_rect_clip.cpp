// Cutting what a picture draws to a rectangle of the canvas.
#include <gtest/gtest.h>

#include <cmath>

#include "io/rect_clip.hpp"

namespace edem {
namespace {

const Rect kBox{0, 0, 10, 10};

double area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(twice);
}

TEST(RectClip, ASegmentInsideIsKeptWhole) {
  const auto piece = clip_segment({1, 2}, {3, 4}, kBox);
  ASSERT_TRUE(piece);
  EXPECT_EQ(piece->first.x, 1);
  EXPECT_EQ(piece->second.y, 4);
}

TEST(RectClip, ASegmentFromFarAwayIsCutAtTheSides) {
  const auto piece = clip_segment({-1e12, 5}, {1e12, 5}, kBox);
  ASSERT_TRUE(piece);
  EXPECT_DOUBLE_EQ(piece->first.x, 0);
  EXPECT_DOUBLE_EQ(piece->second.x, 10);
  EXPECT_DOUBLE_EQ(piece->first.y, 5);
}

TEST(RectClip, ASegmentOutsideOrAlongOutsideIsDropped) {
  EXPECT_FALSE(clip_segment({-5, -1}, {20, -1}, kBox));
  EXPECT_FALSE(clip_segment({11, -5}, {20, 30}, kBox));
  EXPECT_FALSE(clip_segment({-3, 8}, {4, 18}, kBox));  // passes the corner outside
}

TEST(RectClip, APolygonCoveringTheBoxBecomesTheBox) {
  const auto out = clip_polygon({{-1e12, -1e12}, {1e12, -1e12}, {1e12, 1e12}, {-1e12, 1e12}}, kBox);
  EXPECT_EQ(out.size(), 4u);
  EXPECT_DOUBLE_EQ(area(out), 100.0);
}

TEST(RectClip, APolygonAcrossASideKeepsItsAreaInside) {
  // A triangle with half its area left of x = 0.
  const auto out = clip_polygon({{-4, 2}, {4, 2}, {0, 6}}, kBox);
  EXPECT_DOUBLE_EQ(area(out), 8.0);
  for (const Vec2& p : out) EXPECT_GE(p.x, 0.0);
}

TEST(RectClip, APolygonOutsideIsEmpty) {
  EXPECT_TRUE(clip_polygon({{20, 20}, {30, 20}, {30, 30}}, kBox).empty());
}

}  // namespace
}  // namespace edem
