#include "state/sections.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace edem {

int loop_edge_count(const Mesh& mesh) {
  int count = 0;
  for (const auto& loops : mesh.block_boundary)
    for (const BoundaryLoop& loop : loops) count += static_cast<int>(loop.gridpoints.size());
  return count;
}

SectionLayout find_sections(const Mesh& mesh) {
  SectionLayout layout;
  const size_t edges = static_cast<size_t>(loop_edge_count(mesh));
  layout.edge_section.assign(edges, -1);
  layout.edge_glued.assign(edges, 0);
  // A potential segment seen from the first side: its section, keyed by its end points (the
  // two faces' gridpoints are at exactly the same coordinates, zoning.hpp).
  using Point = std::pair<double, double>;
  std::map<std::pair<Point, Point>, int> first_side;
  int flat = 0;
  for (size_t block = 0; block < mesh.block_boundary.size(); ++block) {
    for (const BoundaryLoop& loop : mesh.block_boundary[block]) {
      const size_t count = loop.gridpoints.size();
      for (size_t i = 0; i < count; ++i, ++flat) {
        const EdgeOrigin& origin = loop.edges[i];
        layout.edge_glued[static_cast<size_t>(flat)] = origin.glued;
        if (origin.kind != EdgeKind::potential) continue;
        const int a = loop.gridpoints[i], b = loop.gridpoints[(i + 1) % count];
        const Vec2 pa = mesh.gp_position[static_cast<size_t>(a)];
        const Vec2 pb = mesh.gp_position[static_cast<size_t>(b)];
        const Point qa{pa.x, pa.y}, qb{pb.x, pb.y};
        const auto key = qa < qb ? std::make_pair(qa, qb) : std::make_pair(qb, qa);
        const auto [it, inserted] = first_side.emplace(key, static_cast<int>(layout.sections.size()));
        if (inserted) {
          Section s;
          s.a[0] = a, s.b[0] = b;
          s.edge[0] = flat;
          s.block[0] = static_cast<int>(block);
          s.seed = origin.source;
          s.point = 0.5 * (pa + pb);
          s.length = norm(pb - pa);
          double angle = std::atan2(pb.y - pa.y, pb.x - pa.x) * 180.0 / std::numbers::pi;
          if (angle < 0.0) angle += 180.0;
          if (angle >= 180.0) angle -= 180.0;
          s.angle = angle;
          layout.sections.push_back(s);
          continue;
        }
        // The other face runs the other way: its b is at the first face's a.
        Section& s = layout.sections[static_cast<size_t>(it->second)];
        s.a[1] = b, s.b[1] = a;
        s.edge[1] = flat;
        s.block[1] = static_cast<int>(block);
      }
    }
  }
  // A potential edge with no twin faces an unzoned block: a free face, not a section.
  std::vector<Section> paired;
  for (const Section& s : layout.sections) {
    if (s.edge[1] < 0) {
      layout.edge_glued[static_cast<size_t>(s.edge[0])] = 0;
      continue;
    }
    const int id = static_cast<int>(paired.size());
    layout.edge_section[static_cast<size_t>(s.edge[0])] = id;
    layout.edge_section[static_cast<size_t>(s.edge[1])] = id;
    paired.push_back(s);
  }
  layout.sections = std::move(paired);
  return layout;
}

}  // namespace edem
