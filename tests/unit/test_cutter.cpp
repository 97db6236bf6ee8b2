// Block cutting: counts, areas, edge origins and the degenerate cases exact predicates exist
// for (a cut through a vertex, along an edge, nearly parallel to another).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "geom/cutter.hpp"
#include "geom/joint_set.hpp"
#include "geom/zoning.hpp"
#include "model/model.hpp"

namespace edem {
namespace {

Polygon box(double x0, double x1, double y0, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

double total_area(const BlockSet& set) {
  double sum = 0.0;
  for (const Block& b : set.blocks) sum += b.area;
  return sum;
}

double ring_min_edge(const Ring& ring) {
  double shortest = INFINITY;
  for (size_t i = 0; i < ring.points.size(); ++i)
    shortest = std::min(shortest, norm(ring.points[(i + 1) % ring.points.size()] - ring.points[i]));
  return shortest;
}

// Every block: positive area, consistent rings, no edge shorter than the tolerance.
void expect_valid_blocks(const BlockSet& set, double tolerance) {
  for (size_t i = 0; i < set.blocks.size(); ++i) {
    const Block& b = set.blocks[i];
    EXPECT_GT(b.area, 0.0) << "block " << i;
    EXPECT_GT(signed_area(b.outer.points), 0.0) << "outer ring of block " << i << " not ccw";
    EXPECT_EQ(b.outer.points.size(), b.outer.edges.size());
    EXPECT_GE(b.outer.points.size(), 3u);
    EXPECT_GE(ring_min_edge(b.outer), tolerance) << "block " << i;
    for (const Ring& hole : b.holes) {
      EXPECT_LT(signed_area(hole.points), 0.0) << "hole of block " << i << " not cw";
      EXPECT_GE(ring_min_edge(hole), tolerance);
    }
  }
}

Model jointed_box(double size) {
  Model model;
  model.add_block({box(0, size, 0, size)});
  return model;
}

// A 100 x 100 box cut by horizontal and vertical joints 10 apart, through y = offset and x = offset.
Model box_with_two_sets(double offset) {
  Model model = jointed_box(100);
  JointSetDef horizontal;
  horizontal.angle = 0;
  horizontal.spacing = {10};
  horizontal.origin = {0, offset};
  model.add_joint_set(horizontal);
  JointSetDef vertical;
  vertical.angle = 90;
  vertical.spacing = {10};
  vertical.origin = {offset, 0};
  model.add_joint_set(vertical);
  return model;
}

// The joint-set origin lies on a joint (UDEC's convention). Joints through y = 0, 10, ..., 100
// and x = 0, ..., 100 cut a 100 x 100 box into 100 blocks; those at 0 and 100 lie along the
// boundary (a degenerate case) and add nothing.
TEST(Cutter, TwoOrthogonalSetsMakeAHundredBlocks) {
  Model model = box_with_two_sets(0);
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 100u);
  for (const Block& b : set.blocks) EXPECT_NEAR(b.area, 100.0, 1e-9);
  EXPECT_NEAR(total_area(set), 10000.0, 1e-9 * 10000.0);
  EXPECT_EQ(set.dropped_cuts, 0);
  EXPECT_EQ(set.joint_edges, 2 * 9 * 10);  // 9 interior lines per set, 10 edges each
  expect_valid_blocks(set, model.tolerance());
}

// With the origins at {0, 5} and {5, 0} the ten joints of each set lie at 5, 15, ..., 95:
// eleven rows and columns, half-width ones along the boundary.
TEST(Cutter, OffsetOriginsMakeHalfBlocksAlongTheBoundary) {
  Model model = box_with_two_sets(5);
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 121u);
  int full = 0;
  for (const Block& b : set.blocks) full += std::abs(b.area - 100.0) < 1e-9 ? 1 : 0;
  EXPECT_EQ(full, 81);
  EXPECT_NEAR(total_area(set), 10000.0, 1e-9 * 10000.0);
}

TEST(Cutter, JointThroughACornerSplitsIntoTwoTriangles) {
  Model model = jointed_box(10);
  JointSetDef diagonal;
  diagonal.angle = 45;
  diagonal.spacing = {100};  // one trace only
  diagonal.origin = {0, 0};
  model.add_joint_set(diagonal);
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 2u);
  for (const Block& b : set.blocks) {
    EXPECT_EQ(b.outer.points.size(), 3u);
    EXPECT_DOUBLE_EQ(b.area, 50.0);
  }
  EXPECT_EQ(set.dropped_cuts, 0);
}

TEST(Cutter, JointAlongTheBoundaryIsBoundary) {
  Model model = jointed_box(10);
  JointSetDef along;
  along.angle = 0;
  along.spacing = {10};
  along.origin = {0, 0};  // lines y = 0 and y = 10 lie on the boundary
  model.add_joint_set(along);
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 1u);
  EXPECT_DOUBLE_EQ(set.blocks[0].area, 100.0);
  for (const EdgeOrigin& e : set.blocks[0].outer.edges) EXPECT_EQ(e.kind, EdgeKind::boundary);
}

TEST(Cutter, ThreeJointsThroughOnePoint) {
  Model model = jointed_box(10);
  for (double angle : {0.0, 60.0, 120.0}) {
    JointSetDef set;
    set.angle = angle;
    set.spacing = {100};
    set.origin = {5, 5};
    model.add_joint_set(set);
  }
  const BlockSet& set = model.blocks();
  EXPECT_EQ(set.blocks.size(), 6u);
  EXPECT_NEAR(total_area(set), 100.0, 1e-12);
  expect_valid_blocks(set, model.tolerance());
}

TEST(Cutter, CrackAlongAnotherCrackMergesIntoOneEdge) {
  Model model = jointed_box(10);
  model.add_crack({{0, 5}, {10, 5}});
  model.add_crack({{2, 5}, {7, 5}});  // overlaps the first
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 2u);
  EXPECT_NEAR(total_area(set), 100.0, 1e-12);
}

TEST(Cutter, DanglingCutsAreDroppedAndCounted) {
  Model model = jointed_box(10);
  model.add_crack({{2, 2}, {4, 4}});  // entirely inside: splits nothing
  model.add_crack({{0, 5}, {4, 5}});  // from the boundary into the block, ends inside
  model.add_crack({{5, 0}, {5, 10}}); // splits the box
  const BlockSet& set = model.blocks();
  EXPECT_EQ(set.blocks.size(), 2u);
  EXPECT_EQ(set.dropped_cuts, 2);
  for (const Block& b : set.blocks) EXPECT_DOUBLE_EQ(b.area, 50.0);
}

TEST(Cutter, NearlyParallelCracksGiveValidBlocks) {
  // Two cracks crossing at angles from 1e-3 down to 1e-12 radians: thin wedges where they
  // are resolvable, merged into one edge where they are within the tolerance.
  for (double angle : {1e-3, 1e-6, 1e-9, 1e-12}) {
    Model model = jointed_box(10);
    model.add_crack({{0, 5}, {10, 5}});
    model.add_crack({{0, 5 - 5 * std::tan(angle)}, {10, 5 + 5 * std::tan(angle)}});
    const BlockSet& set = model.blocks();
    EXPECT_GE(set.blocks.size(), 2u) << angle;
    EXPECT_NEAR(total_area(set), 100.0, 1e-9 * 100.0) << angle;
    expect_valid_blocks(set, model.tolerance());
  }
}

TEST(Cutter, CutPassingNearACornerIsSnappedToIt) {
  for (double miss : {1e-8, 1e-12, 0.0, -1e-12, -1e-8}) {
    Model model = jointed_box(10);
    // A diagonal that misses the corner (10, 10) by `miss`.
    model.add_crack({{0, miss}, {10, 10 + miss}});
    const BlockSet& set = model.blocks();
    ASSERT_EQ(set.blocks.size(), 2u) << miss;
    EXPECT_NEAR(total_area(set), 100.0, 1e-12) << miss;
    expect_valid_blocks(set, model.tolerance());
  }
}

TEST(Cutter, CutPassingNearAJointCrossingIsSnapped) {
  Model model = jointed_box(10);
  model.add_crack({{0, 5}, {10, 5}});
  model.add_crack({{5, 0}, {5, 10}});
  model.add_crack({{0, 1e-11}, {10, 10 + 1e-11}});  // misses (5, 5) by ~7e-12
  const BlockSet& set = model.blocks();
  EXPECT_EQ(set.blocks.size(), 6u);
  EXPECT_GT(set.snapped_vertices, 0);
  EXPECT_NEAR(total_area(set), 100.0, 1e-12);
  expect_valid_blocks(set, model.tolerance());
}

// A cut that stops short of another by less than the tolerance reaches it and splits the block
// (a cut clipped to zones along a joint ends a rounding off it); short by more, it is dropped.
TEST(Cutter, ACutEndingWithinTheToleranceOfAnotherReachesIt) {
  const double tolerance = jointed_box(10).tolerance();
  for (double miss : {0.5, 1e-3, 1e-9, 0.0, -1e-9, -0.5}) {
    Model model = jointed_box(10);
    model.add_crack({{0, 5}, {10, 5}});
    model.add_crack({{5, 0}, {5, 5 - miss * tolerance}});  // negative: past it
    const BlockSet& set = model.blocks();
    EXPECT_EQ(set.blocks.size(), 3u) << miss;
    EXPECT_NEAR(total_area(set), 100.0, 1e-12) << miss;
    expect_valid_blocks(set, model.tolerance());
  }
  // Ending on a crack at a slope, where the end point as doubles has it: off the line by a rounding.
  Model sloped = jointed_box(10);
  const double slope = std::tan(0.3);
  sloped.add_crack({{0, 2}, {10, 2 + 10 * slope}});
  sloped.add_crack({{4.3, 10}, {4.3, 2 + 4.3 * slope}});
  EXPECT_EQ(sloped.blocks().blocks.size(), 3u);
  expect_valid_blocks(sloped.blocks(), sloped.tolerance());
  // Short by twice the tolerance: it ends inside the block and goes.
  Model short_of = jointed_box(10);
  short_of.add_crack({{0, 5}, {10, 5}});
  short_of.add_crack({{5, 0}, {5, 5 - 2 * tolerance}});
  EXPECT_EQ(short_of.blocks().blocks.size(), 2u);
  EXPECT_EQ(short_of.blocks().dropped_cuts, 1);
}

// The seed region's block and its main joint set (60 deg at 16, 12, 8 m), at tolerance 1e-3.
Model seed_region_coarse() {
  Model model(ModelDef{"", 1e-3});
  model.add_block({box(-100, 100, -90, 90)});
  JointSetDef main_set;
  main_set.angle = 60;
  main_set.spacing = {16, 12, 8};
  model.add_joint_set(main_set);
  return model;
}

// The seed region's joints with potential cracks across them at a coarse tolerance (0.269 m):
// dozens of cut crossings lie within the tolerance of another cut. Fixed one a round, they ran
// out of rounds; fixed together where they are apart, they take a few.
TEST(Cutter, ManySmallFeaturesAreSnappedTogether) {
  Model model = seed_region_coarse();
  JointSetDef cross;
  cross.angle = -30;
  cross.spacing = {16};
  model.add_joint_set(cross);
  model.add_region({"walls", box(-30, 30, -34, 18)});
  model.add_region({"roof", box(-30, 30, 18, 44)});
  model.add_crackseed({{"walls", {}}, {118, 0}, 4.8, {1.3, 0.7}, "", "", {}, {}});
  model.add_crackseed({{"roof", {}}, {0, 90}, 4.8, {1.3, 0.7}, "", "", {}, {}});
  const BlockSet& set = model.blocks();
  EXPECT_GT(set.snapped_vertices, 12);
  EXPECT_NEAR(total_area(set), 200.0 * 180.0, 1e-9 * 200.0 * 180.0);
  expect_valid_blocks(set, model.tolerance());
}

// Cuts crossing at half a degree stay closer than a coarse tolerance over metres: each fix makes
// another. The cutter gives up with a message naming the inputs, not after minutes.
TEST(Cutter, CutsAtAShallowAngleNameTheInputs) {
  Model model = seed_region_coarse();
  const size_t blocks_before = model.blocks().blocks.size();
  try {
    model.add_crackseed({{}, {60.5, 119.5}, 4.8, {1.3, 0.7}, "", "", {}, {}});
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("joint set 1"), std::string::npos) << what;
    EXPECT_NE(what.find("crackseed 1"), std::string::npos) << what;
  }
  EXPECT_EQ(model.blocks().blocks.size(), blocks_before);  // nothing half-applied
}

TEST(Cutter, EdgesKnowWhatMadeThem) {
  Model model = jointed_box(20);
  JointSetDef set;
  set.angle = 90;
  set.spacing = {7};
  set.origin = {3, 0};
  model.add_joint_set(set);
  model.add_crack({{0, 3}, {20, 3}});
  model.add_region({"hole", box(8, 12, 8, 12), true});
  bool seen[5] = {};
  bool glued_region = false;
  for (const Block& b : model.blocks().blocks)
    for (const EdgeOrigin& e : b.outer.edges) {
      seen[static_cast<int>(e.kind)] = true;
      if (e.kind == EdgeKind::joint) {
        EXPECT_EQ(e.set, 0);
      }
      if (e.kind == EdgeKind::region) glued_region |= e.glued;
    }
  EXPECT_TRUE(seen[static_cast<int>(EdgeKind::boundary)]);
  EXPECT_TRUE(seen[static_cast<int>(EdgeKind::joint)]);
  EXPECT_TRUE(seen[static_cast<int>(EdgeKind::crack)]);
  EXPECT_TRUE(seen[static_cast<int>(EdgeKind::region)]);
  EXPECT_TRUE(glued_region);
}

TEST(Cutter, RegionInsideABlockMakesAHole) {
  Model model = jointed_box(10);
  model.add_region({"inner", box(4, 6, 4, 6), true});
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 2u);
  int with_hole = 0, in_region = 0;
  for (const Block& b : set.blocks) {
    with_hole += b.holes.empty() ? 0 : 1;
    if (!b.regions.empty()) {
      ++in_region;
      EXPECT_DOUBLE_EQ(b.area, 4.0);
    }
  }
  EXPECT_EQ(with_hole, 1);
  EXPECT_EQ(in_region, 1);
  EXPECT_DOUBLE_EQ(total_area(set), 100.0);
}

TEST(Cutter, RegionMembershipWhenTheRegionLeavesTheBlock) {
  Model model = jointed_box(10);
  model.add_region({"right", box(5, 50, -20, 30), false});
  const BlockSet& set = model.blocks();
  ASSERT_EQ(set.blocks.size(), 2u);
  for (const Block& b : set.blocks)
    EXPECT_EQ(b.regions.empty(), b.centroid.x < 5) << b.centroid.x;
}

TEST(Cutter, JointSetRestrictedToARegionStopsAtItsOutline) {
  Model model = jointed_box(10);
  model.add_region({"left", box(0, 5, 0, 10), true});
  JointSetDef set;
  set.angle = 0;
  set.spacing = {2};
  set.origin = {0, 1};
  set.region = {"left", {}};
  model.add_joint_set(set);
  const BlockSet& blocks = model.blocks();
  EXPECT_EQ(blocks.blocks.size(), 7u);  // 5 traces: 6 strips on the left, one block on the right
  EXPECT_EQ(blocks.dropped_cuts, 0);
  EXPECT_DOUBLE_EQ(total_area(blocks), 100.0);
}

TEST(Cutter, TwoTouchingBasesAreCutSeparately) {
  Model model;
  model.add_block({box(0, 10, 0, 10)});
  model.add_block({box(10, 20, 0, 10)});
  model.add_crack({{0, 5}, {20, 5}});
  EXPECT_EQ(model.blocks().blocks.size(), 4u);
  EXPECT_THROW(model.add_block({box(5, 15, 5, 15)}), Error);
  EXPECT_EQ(model.blocks().blocks.size(), 4u);
}

TEST(Cutter, FailedCommandChangesNothing) {
  Model model = jointed_box(10);
  JointSetDef set;
  set.region = {"nowhere", {}};
  EXPECT_THROW(model.add_joint_set(set), Error);
  EXPECT_EQ(model.joint_set_count(), 0);
  EXPECT_EQ(model.blocks().blocks.size(), 1u);
}

TEST(Cutter, FiniteTracesAndGaps) {
  Model model = jointed_box(100);
  JointSetDef set;
  set.angle = 30;
  set.spacing = {5};
  set.trace = 20;
  set.gap = 5;
  model.add_joint_set(set);
  const BlockSet& blocks = model.blocks();
  EXPECT_GT(blocks.dropped_cuts, 0);  // isolated traces split nothing
  EXPECT_NEAR(total_area(blocks), 10000.0, 1e-9 * 10000.0);
}

// Property test: random polygons cut by random joint sets, cracks and regions keep their
// area to 1e-9 and give only valid blocks.
TEST(Cutter, AreaIsConservedForRandomConfigurations) {
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // A random star-shaped polygon around the origin.
    const int corners = 3 + static_cast<int>(u(rng) * 8);
    Polygon base;
    for (int k = 0; k < corners; ++k) {
      const double a = 2 * std::numbers::pi * (k + 0.3 * u(rng)) / corners;
      const double r = 30 + 70 * u(rng);
      base.push_back({r * std::cos(a), r * std::sin(a)});
    }
    Model model;
    model.add_block({base});
    const int sets = 1 + static_cast<int>(u(rng) * 3);
    for (int s = 0; s < sets; ++s) {
      JointSetDef def;
      def.angle = 180 * u(rng) - 90;
      def.spacing = {4 + 20 * u(rng), 4 + 20 * u(rng)};
      def.origin = {20 * u(rng) - 10, 20 * u(rng) - 10};
      if (u(rng) < 0.4) {
        def.trace = 10 + 60 * u(rng);
        def.gap = 10 * u(rng);
      }
      if (u(rng) < 0.3) def.angle_dev = 10 * u(rng);
      def.seed = seed * 7 + s;
      model.add_joint_set(def);
    }
    if (u(rng) < 0.5) model.add_region({"r", box(-20, 10 * u(rng), -15, 20 * u(rng)), true});
    if (u(rng) < 0.5) {
      model.add_crack({{100 * u(rng) - 50, 100 * u(rng) - 50}, {100 * u(rng) - 50, 100 * u(rng) - 50}});
    }
    const BlockSet& set = model.blocks();
    const double area = std::abs(signed_area(base));
    EXPECT_NEAR(total_area(set), area, 1e-9 * area) << "seed " << seed;
    expect_valid_blocks(set, model.tolerance());
  }
}


// Cuts `off` degrees off a joint set (tests/bad/crackseed_nearly_parallel_to_joints.lua, half a
// degree): at 1 degree over 200 m, bending them through each other's vertices goes round in
// circles. Required cuts fail, naming both inputs; optional ones (crackseed{ auto }'s) give way
// where they must, are counted, and the rest are laid. (At 2 degrees every cut is laid.)
// In `extent`, each cut laid as `kind` says (its origin and flags).
CutInput cuts_off_the_joints_in(const Box& extent, const CutSegment& kind, double off) {
  CutInput input;
  input.bases.push_back(box(extent.x0, extent.x1, extent.y0, extent.y1));
  input.tolerance = 1e-3 * std::hypot(200.0, 180.0);
  JointSetDef joints;
  joints.angle = 60;
  joints.spacing = {16, 12, 8};
  input.cuts = joint_set_traces(joints, extent, 0, -1);
  for (double angle : {60.0 + off, 120.0 - off}) {
    JointSetDef cracks;
    cracks.angle = angle;
    cracks.spacing = {4.8};
    cracks.origin = {1.3, 0.7};
    for (CutSegment cut : joint_set_traces(cracks, extent, -1, -1)) {
      cut.origin = kind.origin;
      cut.optional = kind.optional;
      cut.last_resort = kind.last_resort;
      input.cuts.push_back(cut);
    }
  }
  return input;
}

CutInput cuts_a_degree_off_the_joints(bool optional) {
  CutSegment kind{{}, {}, {EdgeKind::potential, -1, 0, true}};
  kind.optional = optional;
  return cuts_off_the_joints_in({-100, 100, -90, 90}, kind, 1.0);
}

TEST(Cutter, OptionalCutsThatCannotBeLaidClearAreLeftOutAndCounted) {
  try {
    cut_blocks(cuts_a_degree_off_the_joints(false));
    FAIL() << "required cuts 1 deg off the joints were laid";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("keep coming closer"), std::string::npos) << e.what();
  }
  const CutInput input = cuts_a_degree_off_the_joints(true);
  const BlockSet set = cut_blocks(input);
  EXPECT_GT(set.cuts_left_out, 0);
  expect_valid_blocks(set, input.tolerance);
  EXPECT_NEAR(total_area(set), 200.0 * 180.0, 1e-6 * 200.0 * 180.0);
  // What is laid: the potential-crack edges (each seen from its two blocks) against the cuts.
  double asked = 0.0, laid = 0.0;
  for (const CutSegment& c : input.cuts) {
    if (!c.optional) continue;
    // The part inside the box (Liang-Barsky).
    double t0 = 0.0, t1 = 1.0;
    const Vec2 d = c.b - c.a;
    const double p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {c.a.x + 100, 100 - c.a.x, c.a.y + 90, 90 - c.a.y};
    for (int k = 0; k < 4; ++k) {
      if (p[k] == 0.0) continue;
      const double t = q[k] / p[k];
      if (p[k] < 0.0) t0 = std::max(t0, t); else t1 = std::min(t1, t);
    }
    if (t1 > t0) asked += (t1 - t0) * norm(d);
  }
  for (const Block& b : set.blocks)
    for (size_t i = 0; i < b.outer.points.size(); ++i)
      if (b.outer.edges[i].kind == EdgeKind::potential)
        laid += 0.5 * norm(b.outer.points[(i + 1) % b.outer.points.size()] - b.outer.points[i]);
  EXPECT_GT(laid, 0.5 * asked) << "most of the cracks should still be laid";  // 80 % when written
  std::printf("cuts 1 deg off the joints: %d pieces left out; %.0f m of %.0f m laid, %zu blocks\n",
              set.cuts_left_out, laid, asked, set.blocks.size());
}


// A crackseed{ auto } group's outline (glued region cuts) is a last resort: where bending goes
// round in circles and no optional cut taking part is left to give way, a stretch of it does,
// counted with the cuts left out (the reduced study's mirrored Case 2 failed so: two stretches of
// one outline 0.13 m apart against a tolerance of 0.188 m). Where optional cuts can give way the
// outline is laid as before, to the bit.
CutInput a_degree_off_the_joints_as(bool cuts_optional, bool outline, bool last_resort) {
  CutSegment kind{{}, {}, {EdgeKind::potential, -1, 0, true}};
  if (outline) kind.origin = {EdgeKind::region, -1, -1, true};
  kind.optional = cuts_optional && !outline;
  kind.last_resort = outline && last_resort;
  return cuts_off_the_joints_in({-100, 100, -90, 90}, kind, 1.0);
}

TEST(Cutter, AnAutomaticGroupsOutlineGivesWayOnlyWhereNoOptionalCutCan) {
  try {
    cut_blocks(a_degree_off_the_joints_as(false, true, false));
    FAIL() << "required outline cuts 1 deg off the joints were laid";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("keep coming closer"), std::string::npos) << e.what();
  }
  const CutInput input = a_degree_off_the_joints_as(false, true, true);
  const BlockSet set = cut_blocks(input);
  EXPECT_GT(set.cuts_left_out, 0);
  expect_valid_blocks(set, input.tolerance);
  EXPECT_NEAR(total_area(set), 200.0 * 180.0, 1e-6 * 200.0 * 180.0);

  // Optional cuts 1 deg off the joints with an outline round them: the cuts give way, and the
  // outline, required or last resort, is laid the same.
  const auto with_outline = [](bool last_resort) {
    CutInput in = a_degree_off_the_joints_as(true, false, false);
    const Vec2 corners[4] = {{-15.3, -15.1}, {15.2, -15.3}, {15.1, 15.2}, {-15.2, 15.3}};
    for (int i = 0; i < 4; ++i) {
      CutSegment side{corners[i], corners[(i + 1) % 4], {EdgeKind::region, -1, -1, true}};
      side.last_resort = last_resort;
      in.cuts.push_back(side);
    }
    return cut_blocks(in);
  };
  const BlockSet required = with_outline(false), last = with_outline(true);
  EXPECT_GT(required.cuts_left_out, 0);
  EXPECT_EQ(last.cuts_left_out, required.cuts_left_out);
  ASSERT_EQ(last.blocks.size(), required.blocks.size());
  for (size_t i = 0; i < last.blocks.size(); ++i) {
    EXPECT_EQ(last.blocks[i].outer.points.size(), required.blocks[i].outer.points.size());
    EXPECT_EQ(last.blocks[i].area, required.blocks[i].area) << "block " << i;
  }
  std::printf("outline 1 deg off the joints: %d pieces left out, %zu blocks\n", set.cuts_left_out,
              set.blocks.size());
}

// A cut input written out as tests/unit/data's files have it: one line a base, region, cut, the
// zone request's size field (its local tolerance), near polygon or tolerance.
CutInput read_cut_input(const std::string& name) {
  std::ifstream file(std::string(EDEM_UNIT_DATA) + "/" + name);
  EXPECT_TRUE(file.good()) << name;
  CutInput input;
  SizeField size;
  double sliver = 0.0;
  std::string line;
  while (std::getline(file, line)) {
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    const auto polygon = [&in] {
      Polygon points;
      for (Vec2 p; in >> p.x >> p.y;) points.push_back(p);
      return points;
    };
    if (tag == "base") {
      input.bases.push_back(polygon());
    } else if (tag == "region") {
      int glued = 0;
      in >> glued;
      input.regions.push_back(polygon());
      input.region_glued.push_back(glued != 0);
    } else if (tag == "cut") {
      CutSegment cut;
      int kind = 0, glued = 0, optional = 0, last_resort = 0;
      in >> cut.a.x >> cut.a.y >> cut.b.x >> cut.b.y >> kind >> cut.origin.set >> cut.origin.source >> glued >>
          cut.clip >> optional >> cut.min_angle >> last_resort;
      cut.origin.kind = static_cast<EdgeKind>(kind);
      cut.origin.glued = glued != 0;
      cut.optional = optional != 0;
      cut.last_resort = last_resort != 0;
      input.cuts.push_back(cut);
    } else if (tag == "size") {
      in >> size.edge >> size.far >> size.growth >> sliver;
    } else if (tag == "near") {
      size.near.push_back(polygon());
    } else if (tag == "tol") {
      in >> input.tolerance;
    }
  }
  if (sliver > 0.0) {
    input.local_tolerance = [size, sliver](Vec2 p) { return sliver * size.at(p); };
    input.largest_tolerance = sliver * size.far;
  }
  return input;
}

// The cuts crackseed{ auto } gives the study's Case 3 at 158 m with its potential cracks through
// (3.67, 1.01) m. Bent to the exact crossings of cuts already bent, joint sets 1 and 2 come ever
// closer to each other near (41.31, 31.57) m, and only a fresh start without the optional cuts near
// there lays them; bent to rounded points, every cut is laid at the first try, and so are the same
// cuts all required. (The fresh start stays for inputs that still go round in circles; the cuts of
// the tests above that do have nothing optional near the spot to leave out.)
TEST(Cutter, JointsBentTogetherByOptionalCutsAreLaid) {
  const CutInput input = read_cut_input("cuts_bending_two_joints_together.txt");
  ASSERT_EQ(input.cuts.size(), 638u);
  CutInput required = input;
  for (CutSegment& cut : required.cuts) cut.optional = cut.last_resort = false;
  for (const CutInput& in : {input, required}) {
    const BlockSet set = cut_blocks(in);
    EXPECT_EQ(set.cuts_left_out, 0);
    expect_valid_blocks(set, in.tolerance);
    EXPECT_NEAR(total_area(set), 200.0 * 180.0, 1e-9 * 200.0 * 180.0);
    int joint_edges = 0;
    for (const Block& b : set.blocks)
      for (const EdgeOrigin& e : b.outer.edges) joint_edges += e.kind == EdgeKind::joint;
    EXPECT_GT(joint_edges, 0) << "the joints are laid";
  }
}

// The ring's vertex nearest to an edge of the same ring that does not end there, and that
// distance [m]. (A ring may pass through one point twice, two lobes meeting at a corner.)
std::pair<double, Vec2> closest_vertex_to_an_edge(const Ring& ring) {
  std::pair<double, Vec2> closest{INFINITY, {}};
  const size_t n = ring.points.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      if (ring.points[j] == ring.points[i] || ring.points[(j + 1) % n] == ring.points[i]) continue;
      const double distance = segment_distance(ring.points[i], ring.points[j], ring.points[(j + 1) % n]);
      if (distance < closest.first) closest = {distance, ring.points[i]};
    }
  return closest;
}

// The cuts crackseed{ auto } gives the study's Case 3 at 262 m, where the tolerance grows with the
// zones away from the opening. A group's outline segment is bent through a joint crossing beyond
// its one end, and then that end is bent back along it: the segment folds into a spike, which a
// bend through its end cannot unfold, and block 252 kept a corner of 1e-8 rad at (-15.314, 5.475)
// m that zoning could not cut off. No block may have a corner within the model's tolerance of an
// edge of its own.
TEST(Cutter, AnOutlineBentBackOnItselfLeavesNoNeedle) {
  const CutInput input = read_cut_input("cuts_folding_an_outline_into_a_needle.txt");
  ASSERT_EQ(input.cuts.size(), 818u);
  const BlockSet set = cut_blocks(input);
  double area = 0.0;
  for (const Polygon& base : input.bases) area += std::abs(signed_area(base));
  EXPECT_NEAR(total_area(set), area, 1e-9 * area);
  for (size_t b = 0; b < set.blocks.size(); ++b) {
    const auto [distance, at] = closest_vertex_to_an_edge(set.blocks[b].outer);
    EXPECT_GE(distance, input.tolerance) << "block " << b + 1 << ": a corner at (" << at.x << ", " << at.y << ")";
  }
}

// A potential crack crossing a joint at 10 deg makes two thin wedges; with min_angle = 20 its
// stretch there is cut back to the crossings either side (here two cross joints), and one
// crossing the joint at 40 deg is laid whole.
CutInput crack_at_ten_degrees_to_a_joint(double min_angle) {
  CutInput input;
  input.bases.push_back(box(-10, 10, -10, 10));
  input.tolerance = 0.01;
  input.cuts.push_back({{-11, -11}, {11, 11}, {EdgeKind::joint, 0, 0, false}});
  input.cuts.push_back({{-11, -5}, {11, -5}, {EdgeKind::joint, 1, 1, false}});
  input.cuts.push_back({{-11, 5}, {11, 5}, {EdgeKind::joint, 1, 1, false}});
  const auto line = [](Vec2 through, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const Vec2 d{std::cos(a), std::sin(a)};
    return std::pair{through - 30.0 * d, through + 30.0 * d};
  };
  for (const auto& [a, b] : {line({0, 0}, 55), line({-6, -6}, 85)}) {
    CutSegment cut{a, b, {EdgeKind::potential, -1, 0, true}};
    cut.optional = true;
    cut.min_angle = min_angle;
    input.cuts.push_back(cut);
  }
  return input;
}

// The sharpest corner of any block with a potential-crack edge at it [deg], and the length of
// potential crack laid (each edge seen from its two blocks).
std::pair<double, double> sharpest_potential_corner_and_length(const BlockSet& set) {
  double sharpest = 180.0, laid = 0.0;
  for (const Block& b : set.blocks) {
    const auto& p = b.outer.points;
    const size_t n = p.size();
    for (size_t i = 0; i < n; ++i) {
      const size_t prev = (i + n - 1) % n, next = (i + 1) % n;
      if (b.outer.edges[i].kind == EdgeKind::potential) laid += 0.5 * norm(p[next] - p[i]);
      if (b.outer.edges[i].kind != EdgeKind::potential && b.outer.edges[prev].kind != EdgeKind::potential)
        continue;
      const Vec2 u = p[prev] - p[i], v = p[next] - p[i];
      const double corner = std::atan2(u.x * v.y - u.y * v.x, dot(u, v)) * 180.0 / std::numbers::pi;
      // Interior angle of a counter-clockwise ring at p[i]: from v round to u.
      const double interior = corner < 0.0 ? -corner : 360.0 - corner;
      sharpest = std::min(sharpest, interior);
    }
  }
  return {sharpest, laid};
}

TEST(Cutter, OptionalCutsAreCutBackFromCornersSharperThanTheirMinAngle) {
  const BlockSet all = cut_blocks(crack_at_ten_degrees_to_a_joint(0.0));
  const auto [sharpest_all, laid_all] = sharpest_potential_corner_and_length(all);
  EXPECT_EQ(all.cuts_cut_back, 0);
  EXPECT_NEAR(sharpest_all, 10.0, 1e-6);
  const double sin55 = std::sin(55.0 * std::numbers::pi / 180.0), sin85 = std::sin(85.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(laid_all, 20.0 / sin55 + 20.0 / sin85, 1e-6);

  const CutInput input = crack_at_ten_degrees_to_a_joint(20.0);
  const BlockSet set = cut_blocks(input);
  const auto [sharpest, laid] = sharpest_potential_corner_and_length(set);
  EXPECT_EQ(set.cuts_cut_back, 1);
  EXPECT_GE(sharpest, 20.0);
  // The 55 deg crack keeps its parts beyond the cross joints at y = +-5; the 85 deg one is whole.
  EXPECT_NEAR(laid, 10.0 / sin55 + 20.0 / sin85, 1e-6);
  expect_valid_blocks(set, input.tolerance);
  EXPECT_NEAR(total_area(set), 400.0, 1e-9 * 400.0);
}

}  // namespace
}  // namespace edem
