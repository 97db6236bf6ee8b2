// A small 2D point/vector type for geometry in double precision.
#pragma once

#include <cmath>
#include <vector>

namespace edem {

struct Vec2 {
  double x = 0.0;  // [m]
  double y = 0.0;  // [m]
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
// Plain sqrt, not std::hypot: hypot guards against an overflow no model coordinate comes near
// and is several times slower (it was the largest single cost of contact detection).
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// A simple polygon: an open list of vertices (the last joins the first); geom/polygon.hpp
// measures and checks it.
using Polygon = std::vector<Vec2>;

}  // namespace edem
