// Scenes shared by unit tests and benchmarks, built through the engine API.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "model/model.hpp"

namespace edem::scenes {

// Warhead outline centred on the origin: flat floor, vertical walls, circular arch of the given
// rise; the same outline as scripts/examples/jointed_cavern.lua builds in Lua.
inline Polygon warhead(double width, double height, double rise, int arc_segments) {
  const double half = width / 2, top = height / 2;
  const double radius = (half * half + rise * rise) / (2 * rise);
  const double centre = top - radius;
  const double start = std::atan2(top - rise - centre, half);
  Polygon outline{{-half, -top}, {half, -top}};
  for (int i = 0; i <= arc_segments; ++i) {
    const double a = start + (std::numbers::pi - 2 * start) * i / arc_segments;
    outline.push_back({radius * std::cos(a), centre + radius * std::sin(a)});
  }
  return outline;
}

// The seed's Case 3 region: the seed's 200 m x 180 m region, Case 3 joints (60 degrees,
// spacing 16/12/8 m, and a cross set), the 24 m x 48 m warhead as a glued region "cavern".
inline Model jointed_cavern() {
  Model model({"jointed cavern", 1e-9});
  model.add_block({{{-100, -90}, {100, -90}, {100, 90}, {-100, 90}}});
  JointSetDef main_set;
  main_set.angle = 60;
  main_set.spacing = {16, 12, 8};
  model.add_joint_set(main_set);
  JointSetDef cross_set;
  cross_set.angle = -30;
  cross_set.spacing = {16};
  model.add_joint_set(cross_set);
  model.add_region({"cavern", warhead(24, 48, 8, 16), true});
  return model;
}

// Boundary segments of zoned blocks on glued ring edges, directed with their block on the left,
// by exact end-point coordinates: (x0, y0, x1, y1) -> block.
inline std::multimap<std::array<double, 4>, int> glued_segments(const Mesh& mesh) {
  std::multimap<std::array<double, 4>, int> segments;
  for (size_t b = 0; b < mesh.block_boundary.size(); ++b)
    for (const BoundaryLoop& loop : mesh.block_boundary[b])
      for (size_t k = 0; k < loop.gridpoints.size(); ++k) {
        if (!loop.edges[k].glued) continue;
        const Vec2 p = mesh.gp_position[static_cast<size_t>(loop.gridpoints[k])];
        const Vec2 q = mesh.gp_position[static_cast<size_t>(loop.gridpoints[(k + 1) % loop.gridpoints.size()])];
        segments.insert({{p.x, p.y, q.x, q.y}, static_cast<int>(b)});
      }
  return segments;
}

}  // namespace edem::scenes
