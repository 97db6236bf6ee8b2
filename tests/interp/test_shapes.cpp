// edem.shapes: the polygons the stdlib builds, contains(), the point-in-polygon test that scripts
// use to pick what lies in an excavation stage or a cavern's outline, and distance_to().
#include "interp_test.hpp"

namespace edem::test {
namespace {

TEST(Shapes, ContainsTakesEitherWindingAndConcavePolygons) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, R"(
    local shapes = require "edem.shapes"
    local square = { {0, 0}, {2, 0}, {2, 2}, {0, 2} }
    local clockwise = { {0, 0}, {0, 2}, {2, 2}, {2, 0} }
    local ell = { {0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3} }   -- notch at x, y > 1
    assert(shapes.contains(square, 1, 1) and shapes.contains(clockwise, 1, 1))
    assert(not shapes.contains(square, 3, 1) and not shapes.contains(clockwise, -1, 1))
    assert(not shapes.contains(square, 1, 2.5) and not shapes.contains(square, 1, -0.5))
    assert(shapes.contains(ell, 2.5, 0.5) and shapes.contains(ell, 0.5, 2.5))
    assert(not shapes.contains(ell, 2, 2), "the notch of the L is outside")
    -- A ray through a vertex is counted once: the point level with the L's inner corner.
    assert(shapes.contains(ell, 0.5, 1) and not shapes.contains(ell, 1.5, 3))
    local disc = shapes.circle{ radius = 5, segments = 64 }
    assert(shapes.contains(disc, 4.9, 0) and not shapes.contains(disc, 3.6, 3.6))
  )");
}

// The distance to the nearest edge, from inside or outside, to an edge's middle or past its end.
TEST(Shapes, DistanceToTheOutline) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, R"(
    local shapes = require "edem.shapes"
    local ell = { {0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3} }
    local function near(a, b) return math.abs(a - b) < 1e-12 end
    assert(near(shapes.distance_to(ell, 0.5, 2), 0.5), "inside, nearest the two long edges")
    assert(near(shapes.distance_to(ell, 2, 1.25), 0.25), "in the notch, above the inner edge")
    assert(near(shapes.distance_to(ell, 4, 0.5), 1), "outside, beside the short edge")
    assert(near(shapes.distance_to(ell, 6, 5), 5), "past the corner (3, 1): the corner's distance")
    assert(shapes.distance_to(ell, 3, 0) == 0, "a vertex")
  )");
}

}  // namespace
}  // namespace edem::test
