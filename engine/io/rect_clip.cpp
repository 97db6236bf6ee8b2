#include "io/rect_clip.hpp"

#include <algorithm>

namespace edem {

std::optional<std::pair<Vec2, Vec2>> clip_segment(Vec2 a, Vec2 b, const Rect& r) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t0 = 0.0, t1 = 1.0;
  // Each side: p t <= q keeps the point a + t (b - a) on its inner side.
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - r.x, r.x + r.w - a.x, a.y - r.y, r.y + r.h - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return std::nullopt;  // parallel to this side, outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{Vec2{a.x + t0 * dx, a.y + t0 * dy}, Vec2{a.x + t1 * dx, a.y + t1 * dy}};
}

namespace {

// Keeps the part of `in` on the inner side of one edge of the rectangle: inside(p) says whether
// p is, cross(p, q) where p-q crosses the edge.
template <class Inside, class Cross>
std::vector<Vec2> clip_side(const std::vector<Vec2>& in, Inside inside, Cross cross) {
  std::vector<Vec2> out;
  if (in.empty()) return out;
  out.reserve(in.size() + 4);
  Vec2 previous = in.back();
  bool previous_in = inside(previous);
  for (const Vec2& p : in) {
    const bool now_in = inside(p);
    if (now_in != previous_in) out.push_back(cross(previous, p));
    if (now_in) out.push_back(p);
    previous = p;
    previous_in = now_in;
  }
  return out;
}

}  // namespace

std::vector<Vec2> clip_polygon(const std::vector<Vec2>& polygon, const Rect& r) {
  const double x0 = r.x, x1 = r.x + r.w, y0 = r.y, y1 = r.y + r.h;
  const auto at_x = [](double x) {
    return [x](Vec2 p, Vec2 q) { return Vec2{x, p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x)}; };
  };
  const auto at_y = [](double y) {
    return [y](Vec2 p, Vec2 q) { return Vec2{p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y), y}; };
  };
  std::vector<Vec2> out = clip_side(polygon, [x0](Vec2 p) { return p.x >= x0; }, at_x(x0));
  out = clip_side(out, [x1](Vec2 p) { return p.x <= x1; }, at_x(x1));
  out = clip_side(out, [y0](Vec2 p) { return p.y >= y0; }, at_y(y0));
  out = clip_side(out, [y1](Vec2 p) { return p.y <= y1; }, at_y(y1));
  if (out.size() < 3) out.clear();
  return out;
}

}  // namespace edem
