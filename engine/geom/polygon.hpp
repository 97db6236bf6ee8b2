// Simple polygons in double precision: area, centroid, containment, validation.
//
// A Polygon is an open list of vertices (the last joins the first). Validation uses
// exact predicates, so a polygon that is accepted is truly simple.
#pragma once

#include <string_view>
#include <vector>

#include "core/vec2.hpp"

namespace edem {

// Positive when counter-clockwise [m^2].
double signed_area(const Polygon& polygon);
double perimeter(const Polygon& polygon);
Vec2 centroid(const Polygon& polygon);

// Point strictly inside (not on the boundary), tested exactly.
bool contains(const Polygon& polygon, Vec2 point);

// Distance from a point to the polygon: 0 inside or on it, else to the nearest edge [m].
double distance(const Polygon& polygon, Vec2 point);

// Distance from p to the segment a-b [m].
double segment_distance(Vec2 p, Vec2 a, Vec2 b);

// True when p lies on the line through a and b, tested exactly.
bool on_line_exactly(Vec2 p, Vec2 a, Vec2 b);

struct Box {
  double x0, x1, y0, y1;  // [m]
  double diagonal() const;
};
Box bounding_box(const Polygon& polygon);

// The largest coordinate a model may have [m]. The exact geometry (CGAL over GMP) and the
// snapping of small features work on numbers of the model's own size; beyond this, far past any
// rock mass, a coordinate is a mistake, and numbers like 1e200 overflow the exact arithmetic.
inline constexpr double kMaxCoordinate = 1e7;

// Throws edem::Error naming `what` for a coordinate that is not finite or is beyond
// kMaxCoordinate.
void check_coordinate(Vec2 p, std::string_view what);

// Throws edem::Error naming `what` when the polygon has fewer than three vertices, a
// non-finite or too large coordinate, repeated consecutive vertices, zero area or crossing edges.
void validate_polygon(const Polygon& polygon, std::string_view what);

// True when the interiors of two valid polygons share area (touching edges is fine). Exact.
bool interiors_overlap(const Polygon& a, const Polygon& b);

// The same polygon, counter-clockwise.
Polygon counter_clockwise(Polygon polygon);

}  // namespace edem
