#include "geom/block_snap.hpp"

#include <algorithm>
#include <cmath>

#include "geom/polygon.hpp"

namespace edem {

namespace {

bool near_box(Vec2 p, const Box& b, double margin) {
  return p.x >= b.x0 - margin && p.x <= b.x1 + margin && p.y >= b.y0 - margin && p.y <= b.y1 + margin;
}

// The foot of p on segment a-b, exact along an axis-parallel edge.
Vec2 foot(Vec2 p, Vec2 a, Vec2 b) {
  if (a.x == b.x) return {a.x, p.y};
  if (a.y == b.y) return {p.x, a.y};
  const Vec2 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return a + t * d;
}

// Moves p onto a corner of `other` within the tolerance, else onto an edge; true if moved.
bool snap_corner(Vec2& p, const Polygon& other, double tolerance) {
  for (const Vec2& q : other) {
    if (q.x == p.x && q.y == p.y) return false;
    if (norm(q - p) <= tolerance) {
      p = q;
      return true;
    }
  }
  for (size_t i = 0; i < other.size(); ++i) {
    const Vec2 a = other[i], b = other[(i + 1) % other.size()];
    const double d = segment_distance(p, a, b);
    if (d > 0.0 && d <= tolerance) {
      p = foot(p, a, b);
      return true;
    }
  }
  return false;
}

// Puts the corners of `other` that lie within the tolerance of an edge of `block` (but not on
// it) into that edge. A corner that lies on the edge's line only to round-off (no distance in
// doubles, off the line exactly) goes in too: the mesh would refine towards it without end.
int take_corners_into_edges(Polygon& block, const Polygon& other, double tolerance) {
  int taken = 0;
  for (const Vec2& q : other) {
    for (size_t i = 0; i < block.size(); ++i) {
      const Vec2 a = block[i], b = block[(i + 1) % block.size()];
      if ((q.x == a.x && q.y == a.y) || (q.x == b.x && q.y == b.y)) break;
      if (norm(q - a) <= tolerance || norm(q - b) <= tolerance) continue;  // a corner's own business
      const double d = segment_distance(q, a, b);
      if (d <= tolerance && (d > 0.0 || !on_line_exactly(q, a, b))) {
        block.insert(block.begin() + static_cast<std::ptrdiff_t>(i) + 1, q);
        ++taken;
        break;
      }
    }
  }
  return taken;
}

}  // namespace

std::vector<Polygon> snap_blocks_together(const std::vector<Polygon>& blocks, double tolerance, int* snapped) {
  std::vector<Polygon> out;
  std::vector<Box> boxes;
  for (Polygon block : blocks) {
    const Box box = bounding_box(block);
    for (size_t k = 0; k < out.size(); ++k) {
      const Box& other = boxes[k];
      if (box.x1 < other.x0 - tolerance || box.x0 > other.x1 + tolerance || box.y1 < other.y0 - tolerance ||
          box.y0 > other.y1 + tolerance)
        continue;
      for (Vec2& p : block)
        if (near_box(p, other, tolerance) && snap_corner(p, out[k], tolerance)) ++*snapped;
      *snapped += take_corners_into_edges(block, out[k], tolerance);
      // The block's corners on an earlier block's edge go into that edge as well.
      if (const int taken = take_corners_into_edges(out[k], block, tolerance); taken > 0) {
        *snapped += taken;
        boxes[k] = bounding_box(out[k]);
      }
    }
    // Corners snapped onto the same point are one.
    Polygon kept;
    for (const Vec2& p : block)
      if (kept.empty() || p.x != kept.back().x || p.y != kept.back().y) kept.push_back(p);
    while (kept.size() > 1 && kept.front().x == kept.back().x && kept.front().y == kept.back().y) kept.pop_back();
    boxes.push_back(bounding_box(kept));
    out.push_back(std::move(kept));
  }
  return out;
}

}  // namespace edem
