#include "geom/polygon.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace edem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

std::vector<Point> to_points(const Polygon& polygon) {
  std::vector<Point> points;
  points.reserve(polygon.size());
  for (const Vec2& p : polygon) points.emplace_back(p.x, p.y);
  return points;
}

}  // namespace

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

bool on_line_exactly(Vec2 p, Vec2 a, Vec2 b) {
  return CGAL::collinear(Point(a.x, a.y), Point(b.x, b.y), Point(p.x, p.y));
}

double signed_area(const Polygon& polygon) {
  // Relative to the first vertex, so that a small polygon far from the origin keeps its digits.
  double twice = 0.0;
  const size_t n = polygon.size();
  if (n == 0) return 0.0;
  const Vec2 o = polygon[0];
  for (size_t i = 1; i + 1 < n; ++i) twice += cross(polygon[i] - o, polygon[i + 1] - o);
  return 0.5 * twice;
}

Vec2 centroid(const Polygon& polygon) {
  // Relative to the first vertex, so that far-away coordinates lose no digits.
  const size_t n = polygon.size();
  if (n == 0) return {};
  const Vec2 o = polygon[0];
  double twice_area = 0.0, cx = 0.0, cy = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = polygon[i] - o, b = polygon[(i + 1) % n] - o;
    const double c = cross(a, b);
    twice_area += c;
    cx += (a.x + b.x) * c;
    cy += (a.y + b.y) * c;
  }
  if (twice_area == 0.0) return o;
  return {o.x + cx / (3.0 * twice_area), o.y + cy / (3.0 * twice_area)};
}

bool contains(const Polygon& polygon, Vec2 point) {
  const auto points = to_points(polygon);
  return CGAL::bounded_side_2(points.begin(), points.end(), Point(point.x, point.y), Kernel()) ==
         CGAL::ON_BOUNDED_SIDE;
}

double distance(const Polygon& polygon, Vec2 point) {
  double best = std::numeric_limits<double>::infinity();
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i)
    best = std::min(best, segment_distance(point, polygon[i], polygon[(i + 1) % n]));
  if (n >= 3 && contains(polygon, point)) return 0.0;
  return best;
}

double Box::diagonal() const { return std::hypot(x1 - x0, y1 - y0); }

Box bounding_box(const Polygon& polygon) {
  Box box{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec2& p : polygon) {
    box.x0 = std::min(box.x0, p.x);
    box.x1 = std::max(box.x1, p.x);
    box.y0 = std::min(box.y0, p.y);
    box.y1 = std::max(box.y1, p.y);
  }
  return box;
}

double perimeter(const Polygon& polygon) {
  double length = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) length += norm(polygon[(i + 1) % polygon.size()] - polygon[i]);
  return length;
}

void check_coordinate(Vec2 p, std::string_view what) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    fail("{} is not a finite number ({}, {})", what, p.x, p.y);
  if (std::fabs(p.x) > kMaxCoordinate || std::fabs(p.y) > kMaxCoordinate)
    fail("{} ({:g}, {:g}) is beyond {:g} m: coordinates are metres about the rock mass (put the "
         "origin near it)",
         what, p.x, p.y, kMaxCoordinate);
}

void validate_polygon(const Polygon& polygon, std::string_view what) {
  if (polygon.size() < 3)
    fail("{} needs at least 3 vertices, got {}", what, polygon.size());
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 p = polygon[i];
    check_coordinate(p, fmt::format("{} vertex {}", what, i + 1));
    if (p == polygon[(i + 1) % polygon.size()])
      fail("{} repeats vertex {} ({}, {})", what, i + 1, p.x, p.y);
  }
  const auto points = to_points(polygon);
  if (!CGAL::is_simple_2(points.begin(), points.end(), Kernel()))
    fail("{} is self-intersecting: its edges cross or touch", what);
  if (signed_area(polygon) == 0.0) fail("{} has zero area", what);
}

bool interiors_overlap(const Polygon& a, const Polygon& b) {
  using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
  auto exact = [](const Polygon& polygon) {
    CGAL::Polygon_2<Exact> out;
    for (Vec2 p : counter_clockwise(polygon)) out.push_back(Exact::Point_2(p.x, p.y));
    return out;
  };
  std::vector<CGAL::Polygon_with_holes_2<Exact>> common;
  CGAL::intersection(exact(a), exact(b), std::back_inserter(common));
  return !common.empty();  // regularised: touching polygons have no common part
}

Polygon counter_clockwise(Polygon polygon) {
  if (signed_area(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

}  // namespace edem
