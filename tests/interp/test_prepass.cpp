// prepass{}: the implicit solve agrees with the explicit one, leaves the model as it was, and
// reports its stages.
#include <unistd.h>

#include <filesystem>

#include "interp_test.hpp"

namespace edem::test {
namespace {

// A square plate under biaxial in-situ stress with a square hole region to excavate; elastic
// unless the script says otherwise.
const char* kPlate = R"(
  model{ title = "plate with a hole" }
  block{ x = {0, 10}, y = {0, 10} }
  region{ name = "hole", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
  region{ name = "slot", polygon = {{4, 6}, {6, 6}, {6, 7}, {4, 7}} }
  zone{ edge = 0.5 }
  material{ "rock", young = 1e9, poisson = 0.25 }
  assign{ material = "rock" }
  insitu{ sxx = -2e6, syy = -1e6 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
)";

// Excavating the hole and then the slot: the prepass's displacements against the explicit
// solver's at equilibrium (the same discrete problem, so they agree to the solver's tolerance).
TEST(Prepass, StagesAgreeWithTheExplicitSolver) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kPlate) + R"(
    local pre = prepass{ stages = { "hole", "slot" }, steps = 2 }
    assert(#pre.stages == 3 and pre.stages[1].name == "present state" and pre.stages[3].name == "slot")
    assert(pre.stages[1].iterations == 0, "the in-situ state is in equilibrium already")
    for g in gridpoints() do assert(g.ux == 0 and g.uy == 0, "the model is left as it was") end
    assert(stage() == 0)
    excavate("hole")
    solve{ ratio = 1e-11, max_cycles = 200000 }
    excavate("slot")
    solve{ ratio = 1e-11, max_cycles = 200000 }
    local gone = {}  -- the excavated blocks: their gridpoints are no longer rock
    for b in blocks() do
      for _, r in ipairs(b.regions) do if r == "hole" or r == "slot" then gone[b.id] = true end end
    end
    local largest, worst = 0, 0
    for g in gridpoints() do
      local p = gone[g.block] and { ux = g.ux, uy = g.uy } or pre.gridpoints[g.id]
      largest = math.max(largest, math.abs(g.ux), math.abs(g.uy))
      worst = math.max(worst, math.abs(p.ux - g.ux), math.abs(p.uy - g.uy))
    end
    assert(largest > 1e-4, "the hole moves the rock")
    assert(worst < 1e-5 * largest, ("implicit against explicit: %g of %g"):format(worst, largest))
    local excavated = 0
    for _, z in ipairs(pre.zones) do
      if z.states[2] == "excavated" then excavated = excavated + 1 end
      assert(z.states[1] ~= "excavated")
    end
    assert(excavated > 0)
  )");
}

// Elastic problems are linear: one Newton iteration per load step, whatever the step.
TEST(Prepass, AnElasticStepTakesOneNewtonIteration) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kPlate) + R"(
    for _, solver in ipairs({ "lu", "ldlt", "klu", "umfpack" }) do
      local pre = prepass{ stages = { "hole" }, steps = 3, solver = solver }
      assert(pre.stages[2].iterations == 3, solver .. ": " .. pre.stages[2].iterations)
      for _, step in ipairs(pre.stages[2].steps) do assert(step.converged) end
    end
  )");
}

// Mohr-Coulomb rock around the hole yields; the zones say so, by stage, with principal stresses.
TEST(Prepass, YieldedZonesAreReported) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kPlate) + R"(
    material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 0.3e6, friction = 30 }
    local pre = prepass{ stages = { "hole" } }
    local yielded = 0
    for _, z in ipairs(pre.zones) do
      assert(z.states[1] == "none", "in situ everything is elastic")
      if z.states[2] == "shear" then yielded = yielded + 1 end
      assert(z.s1 <= z.s3 and z.angle > -90 and z.angle <= 90)
    end
    assert(yielded > 0, "the hole's wall yields")
  )");
}

// plot{ show = {"prepass"} } draws the last prepass's yielded zones, and asks for one first.
TEST(Prepass, YieldedZonesArePlotted) {
  namespace fs = std::filesystem;
  const fs::path file = fs::temp_directory_path() / ("edem_prepass_plot_" + std::to_string(::getpid()) + ".png");
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kPlate) + R"(
    material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 0.3e6, friction = 30 }
  )");
  const std::string plot = "plot{ file = '" + file.string() + "', show = { 'prepass', 'zones' } }";
  EXPECT_TRUE(contains(error_of(interpreter, plot), "no prepass{} result for this mesh (run prepass{} first)"));
  EXPECT_FALSE(fs::exists(file));
  expect_runs(interpreter, "prepass{ stages = { 'hole' } }\n" + plot);
  EXPECT_GT(fs::file_size(file), 1000u);
  fs::remove(file);
  // The run's own plastic zones, after the explicit solver has excavated the hole too.
  expect_runs(interpreter, "excavate('hole')\nsolve{ ratio = 1e-5 }\n"
                           "plot{ file = '" + file.string() + "', show = { 'plastic', 'blocks' } }");
  EXPECT_GT(fs::file_size(file), 1000u);
  fs::remove(file);
}

}  // namespace
}  // namespace edem::test
