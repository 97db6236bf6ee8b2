// Geometry cut to a rectangle of the canvas before Cairo sees it: Cairo keeps path coordinates in
// 24.8 fixed point (about +-8 million device units), and a window a few micrometres wide puts a
// model's far parts billions of units away, where they would wrap round into the picture.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "core/vec2.hpp"
#include "io/canvas.hpp"

namespace edem {

// The part of segment a-b inside `r` (Liang-Barsky), or nothing.
std::optional<std::pair<Vec2, Vec2>> clip_segment(Vec2 a, Vec2 b, const Rect& r);

// The polygon cut to `r` (Sutherland-Hodgman): the same filled area inside `r`; a concave polygon
// may gain edges along r's sides, which a caller draws outside what it shows. Empty: none inside.
std::vector<Vec2> clip_polygon(const std::vector<Vec2>& polygon, const Rect& r);

}  // namespace edem
