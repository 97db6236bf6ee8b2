#include "solver/loads.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace edem {

std::vector<int> select_boundary_nodes(const Mechanics& m, const BoundaryDef& def) {
  std::vector<int> candidates;
  for (const BoundarySegment& s : m.boundary) {
    candidates.push_back(s.a);
    candidates.push_back(s.b);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  if (candidates.empty()) fail("the model has no outer boundary gridpoints (zone it first)");
  auto position = [&](int n) {
    return Vec2{m.position[2 * static_cast<size_t>(n)], m.position[2 * static_cast<size_t>(n) + 1]};
  };
  std::vector<int> selected;
  if (!def.side.empty()) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int n : candidates) {
      const Vec2 p = position(n);
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const double tol = 1e-9 * std::max(x1 - x0, y1 - y0);
    for (int n : candidates) {
      const Vec2 p = position(n);
      const bool on = def.side == "left"     ? p.x <= x0 + tol
                      : def.side == "right"  ? p.x >= x1 - tol
                      : def.side == "bottom" ? p.y <= y0 + tol
                      : def.side == "top"    ? p.y >= y1 - tol
                                             : false;
      if (on) selected.push_back(n);
    }
    if (def.side != "left" && def.side != "right" && def.side != "bottom" && def.side != "top")
      fail("side must be \"left\", \"right\", \"top\" or \"bottom\", got \"{}\"", def.side);
  } else {
    validate_polygon(def.polygon, "boundary polygon");
    for (int n : candidates)
      if (contains(def.polygon, position(n))) selected.push_back(n);
    if (selected.empty()) fail("no outer boundary gridpoint lies inside the polygon");
  }
  return selected;
}

void lump_boundary_loads(Mechanics& m) {
  std::fill(m.load.begin(), m.load.end(), 0.0);
  for (const BoundarySegment& s : m.boundary) {
    if (!s.loaded) continue;
    const size_t a = static_cast<size_t>(s.a), b = static_cast<size_t>(s.b);
    const double dx = m.position[2 * b] - m.position[2 * a];
    const double dy = m.position[2 * b + 1] - m.position[2 * a + 1];
    // Outward normal times length: the domain lies left of a -> b.
    const double nx = dy, ny = -dx;
    const double tax = s.at_a.xx * nx + s.at_a.xy * ny, tay = s.at_a.xy * nx + s.at_a.yy * ny;
    const double tbx = s.at_b.xx * nx + s.at_b.xy * ny, tby = s.at_b.xy * nx + s.at_b.yy * ny;
    m.load[2 * a] += (2.0 * tax + tbx) / 6.0;
    m.load[2 * a + 1] += (2.0 * tay + tby) / 6.0;
    m.load[2 * b] += (tax + 2.0 * tbx) / 6.0;
    m.load[2 * b + 1] += (tay + 2.0 * tby) / 6.0;
  }
  // What an excavation still holds on the rock (excavate{ release = n }).
  for (size_t i = 0; i < m.release.dof.size(); ++i)
    m.load[static_cast<size_t>(m.release.dof[i])] += m.release.factor * m.release.force[i];
}

}  // namespace edem
