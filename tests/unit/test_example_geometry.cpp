// The seed's Case 3 region (tests/scenes.hpp) is cut and zoned soundly: block areas sum to the region area, and every
// zone has positive area, meets the angle rule, respects the size field, and the zones of a block
// sum to its area.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "scenes.hpp"

namespace edem {
namespace {

double angle_deg(Vec2 at, Vec2 a, Vec2 b) {
  const Vec2 u = a - at, v = b - at;
  return std::atan2(std::abs(cross(u, v)), dot(u, v)) * 180.0 / std::numbers::pi;
}

// Interior angle of each ring corner, for the exemption "unless the block's own corner is
// sharper".
double sharpest_corner_at(const Block& block, Vec2 p) {
  double sharpest = 180.0;
  auto scan = [&](const Ring& ring) {
    const size_t n = ring.points.size();
    for (size_t i = 0; i < n; ++i) {
      if (!(ring.points[i] == p)) continue;
      const Vec2 prev = ring.points[(i + n - 1) % n], next = ring.points[(i + 1) % n];
      double a = angle_deg(p, next, prev);
      if (cross(next - p, prev - p) < 0) a = 360.0 - a;  // reflex corner (ccw ring)
      sharpest = std::min(sharpest, a);
    }
  };
  scan(block.outer);
  for (const Ring& hole : block.holes) scan(hole);
  return sharpest;
}

ZoneDef example_zoning() {
  ZoneDef zone;
  zone.edge = 1.0;
  zone.far = 8.0;
  zone.near = {{"cavern", {}}};
  return zone;
}

TEST(ExampleGeometry, BlockAreasSumToTheRegion) {
  Model model = scenes::jointed_cavern();
  double sum = 0.0;
  for (const Block& b : model.blocks().blocks) sum += b.area;
  EXPECT_NEAR(sum, 200.0 * 180.0, 1e-9 * 200.0 * 180.0);
  EXPECT_GT(model.blocks().blocks.size(), 200u);
  EXPECT_EQ(model.blocks().dropped_cuts, 0);
}

TEST(ExampleGeometry, ZonesMeetTheQualityAndSizeRules) {
  Model model = scenes::jointed_cavern();
  const ZoneDef def = example_zoning();
  model.zone(def);
  const Mesh& mesh = model.mesh();
  const BlockSet& blocks = model.blocks();
  SizeField size;
  size.edge = def.edge;
  size.far = def.far;
  size.growth = def.growth;
  size.near = {model.resolve(def.near[0])};

  ASSERT_GT(mesh.zone_count(), 5000);
  for (size_t b = 0; b < blocks.blocks.size(); ++b) {
    const Block& block = blocks.blocks[b];
    double zone_area = 0.0;
    for (int z = mesh.block_first_zone[b]; z < mesh.block_first_zone[b + 1]; ++z) {
      const auto& g = mesh.zone_gp[z];
      const Vec2 p0 = mesh.gp_position[g[0]], p1 = mesh.gp_position[g[1]],
                 p2 = mesh.gp_position[g[2]];
      const double area = mesh.zone_area(z);
      ASSERT_GT(area, 0.0) << "zone " << z;
      zone_area += area;
      // Angle rule: >= 20 degrees unless a corner of the block at one of its vertices is
      // sharper than 20 degrees.
      const double smallest = std::min({angle_deg(p0, p1, p2), angle_deg(p1, p2, p0),
                                        angle_deg(p2, p0, p1)});
      if (smallest < kMinZoneAngle) {
        const double corner = std::min({sharpest_corner_at(block, p0),
                                        sharpest_corner_at(block, p1),
                                        sharpest_corner_at(block, p2)});
        EXPECT_LT(corner, kMinZoneAngle) << "zone " << z << " angle " << smallest;
      }
      // Size rule: no edge longer than the size field asks for at the zone's centroid.
      const double longest = std::max({norm(p1 - p0), norm(p2 - p1), norm(p0 - p2)});
      EXPECT_LE(longest, size.at(mesh.zone_centroid(z)) * (1 + 1e-9)) << "zone " << z;
    }
    EXPECT_NEAR(zone_area, block.area, 1e-9 * block.area) << "block " << b;
  }
}

TEST(ExampleGeometry, GradedZonesAreFineNearTheCavernAndCoarseFarAway) {
  Model model = scenes::jointed_cavern();
  model.zone(example_zoning());
  const Mesh& mesh = model.mesh();
  double near_sum = 0, far_sum = 0;
  int near_count = 0, far_count = 0;
  for (int z = 0; z < mesh.zone_count(); ++z) {
    const Vec2 c = mesh.zone_centroid(z);
    const double h = std::sqrt(4.0 * mesh.zone_area(z) / std::sqrt(3.0));  // equilateral edge
    if (std::abs(c.x) < 10 && std::abs(c.y) < 20) {
      near_sum += h;
      ++near_count;
    } else if (std::abs(c.x) > 70 || std::abs(c.y) > 70) {
      far_sum += h;
      ++far_count;
    }
  }
  ASSERT_GT(near_count, 0);
  ASSERT_GT(far_count, 0);
  EXPECT_GT(near_sum / near_count, 0.4);  // about edge = 1 m near the cavern
  EXPECT_LT(near_sum / near_count, 1.0);
  EXPECT_GT(far_sum / far_count, 3.0);    // several metres far away (far = 8 m)
  EXPECT_LT(far_sum / far_count, 8.0);
}

TEST(ExampleGeometry, GeometryAfterZoningIsRezoned) {
  Model model = scenes::jointed_cavern();
  model.zone(example_zoning());
  const int zones_before = model.mesh().zone_count();
  model.add_crack({{-100, 0}, {100, 0}});
  EXPECT_GT(model.blocks().blocks.size(), 236u);
  EXPECT_GT(model.mesh().zone_count(), zones_before / 2);
  double sum = 0;
  for (int z = 0; z < model.mesh().zone_count(); ++z) sum += model.mesh().zone_area(z);
  EXPECT_NEAR(sum, 36000.0, 1e-9 * 36000.0);
}


// Both faces along an arrangement edge have it with the same end points, so zoning finds the
// blocks joined by a glued region outline by exact coordinates.
TEST(ExampleGeometry, GluedEdgesHaveTwinsWithTheSameEndPoints) {
  Model model = scenes::jointed_cavern();
  std::multimap<std::array<double, 4>, std::pair<int, bool>> edges;  // -> block, glued
  const auto& blocks = model.blocks().blocks;
  for (size_t b = 0; b < blocks.size(); ++b) {
    auto add = [&](const Ring& ring) {
      for (size_t i = 0; i < ring.points.size(); ++i) {
        const Vec2 p = ring.points[i], q = ring.points[(i + 1) % ring.points.size()];
        edges.insert({{p.x, p.y, q.x, q.y}, {static_cast<int>(b), ring.edges[i].glued}});
      }
    };
    add(blocks[b].outer);
    for (const Ring& hole : blocks[b].holes) add(hole);
  }
  int glued = 0;
  for (const auto& [key, value] : edges) {
    if (!value.second) continue;
    ++glued;
    const auto twin = edges.find({key[2], key[3], key[0], key[1]});
    ASSERT_NE(twin, edges.end()) << "glued edge of block " << value.first << " has no twin";
    EXPECT_NE(twin->second.first, value.first);
    EXPECT_TRUE(twin->second.second) << "glued on one side only";
  }
  EXPECT_GT(glued, 16);  // the warhead outline, cut by the joints
}

// The blocks on the two sides of the cavern outline have the same gridpoints along it.
TEST(ExampleGeometry, ZonesConformAlongTheGluedOutline) {
  Model model = scenes::jointed_cavern();
  model.zone(example_zoning());
  const Mesh& mesh = model.mesh();
  const auto segments = scenes::glued_segments(mesh);  // glued boundary segments -> block
  EXPECT_GT(segments.size(), 2u * 100);  // ~130 m of outline at ~1 m zones, both sides
  for (const auto& [key, block] : segments) {
    const auto twin = segments.find({key[2], key[3], key[0], key[1]});
    ASSERT_NE(twin, segments.end()) << "block " << block << " has a gridpoint its neighbour lacks";
    EXPECT_NE(twin->second, block);
  }
}

}  // namespace
}  // namespace edem
