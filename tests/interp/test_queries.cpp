// Reading the model from a script: info() and the blocks() and zones() iterators.
#include <gtest/gtest.h>

#include "interp_test.hpp"

namespace edem {
namespace {

using test::expect_runs;

// A 10 x 10 square cut by two horizontal joints into three blocks, with a region in the
// middle one, zoned.
constexpr const char* kScene = R"(
  model{ title = "three layers" }
  block{ x = {0, 10}, y = {0, 10} }
  jset{ angle = 0, spacing = 5, origin = {0, 2.5} }
  region{ name = "core", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
  zone{ edge = 1 }
)";

TEST(Queries, Info) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kScene) + R"(
    local i = info()
    assert(i.title == "three layers", i.title)
    assert(i.joint_sets == 1 and i.regions == 1, "counts of inputs")
    assert(i.blocks >= 4, "three layers and the region: " .. i.blocks)
    assert(i.zones > 0 and i.gridpoints > 0)
    assert(math.type(i.blocks) == "integer")
  )");
}

TEST(Queries, Blocks) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kScene) + R"(
    local n, area, in_core, holes = 0, 0, 0, 0
    for b in blocks() do
      n = n + 1
      assert(b.id == n, "ids are 1, 2, ...")
      area = area + b.area
      assert(b.x == b.centroid.x and b.y == b.centroid.y)
      assert(#b.vertices >= 3 and b.vertices[1].x == b.vertices[1][1])
      assert(b.base == 1 and b.zones > 0)
      holes = holes + #b.holes
      if b.region then
        assert(b.region == "core" and b.regions[1] == "core")
        in_core = in_core + b.area
      end
    end
    assert(n == info().blocks)
    assert(math.abs(area - 100) < 1e-9, area)
    assert(math.abs(in_core - 4) < 1e-9, in_core)
    assert(holes == 1, "the core is a hole in the middle layer")
  )");
}

TEST(Queries, Zones) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kScene) + R"(
    local n, area, core = 0, 0, 0
    for z in zones() do
      n = n + 1
      assert(z.id == n)
      area = area + z.area
      assert(#z.vertices == 3 and #z.gridpoints == 3)
      assert(z.block >= 1 and z.block <= info().blocks)
      if z.region == "core" then core = core + z.area end
    end
    assert(n == info().zones)
    assert(math.abs(area - 100) < 1e-9, area)
    assert(math.abs(core - 4) < 1e-9, core)
  )");
}

TEST(Queries, IteratorsSurviveAChangedModel) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kScene) + R"(
    local n = 0
    for b in blocks() do
      n = n + 1
      if n == 1 then model{ title = "empty" } end  -- the loop sees the new, empty model
    end
    assert(n == 1, n)
  )");
}

TEST(Queries, EmptyModel) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    assert(info().blocks == 0 and info().title == "")
    for b in blocks() do error("no blocks expected") end
    for z in zones() do error("no zones expected") end
  )");
}

}  // namespace
}  // namespace edem
