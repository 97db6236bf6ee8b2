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

// The plate in rock too weak for the hole (c = 0.3 MPa, 10 deg, under 2 and 1 MPa): the continuum
// has no static state once the hole is about half unloaded.
std::string weak_plate() {
  return std::string(kPlate) + R"(
    zone{ edge = 1 }
    material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 0.3e6, friction = 10 }
  )";
}

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

// Rock too weak for the hole (c = 0.3 MPa, 10 deg, under 2 and 1 MPa): the continuum has no static
// state once the hole is half unloaded. By default that stops the script naming the stage; with
// on_failure = "keep" the prepass ends there and returns what it found up to the last converged
// step: the stage's reached load factor, its yielded zones, no later stage, and the model as it was.
TEST(Prepass, AStageWithNoStaticStateEndsThePrepassWhenKept) {
  const std::string weak = weak_plate();
  {
    Interpreter interpreter;
    interpreter.context().quiet = true;
    EXPECT_TRUE(contains(error_of(interpreter, weak + "prepass{ stages = { \"hole\", \"slot\" }, iterations = 8 }"),
                         "stage 1 (hole): no equilibrium found beyond load factor"));
  }
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, weak + R"(
    local pre = prepass{ stages = { "hole", "slot" }, iterations = 8, on_failure = "keep" }
    assert(pre.failure and pre.failure:find("stage 1 (hole): no equilibrium found beyond load factor", 1, true), tostring(pre.failure))
    assert(#pre.stages == 2, "present state and the hole, no slot: " .. #pre.stages)
    assert(pre.stages[1].reached == 1 and pre.stages[1].failure == nil)
    local reached = pre.stages[2].reached
    assert(reached > 0.1 and reached < 1, "reached " .. reached)
    assert(pre.stages[2].failure == pre.failure)
    local yielded, excavated, in_hole = 0, 0, 0
    for _, z in ipairs(pre.zones) do
      assert(#z.states == 2)
      local inside = z.x > 4 and z.x < 6 and z.y > 4 and z.y < 6
      if inside then in_hole = in_hole + 1 end
      if z.states[2] == "excavated" then
        assert(inside, "excavated outside the hole")
        excavated = excavated + 1
      elseif z.states[2] ~= "none" then
        yielded = yielded + 1
      end
    end
    assert(excavated == in_hole, ("the hole's zones: %d excavated of %d"):format(excavated, in_hole))
    assert(yielded > 0, "the wall yields before the collapse")
    for z in zones() do assert(not z.excavated and z.state == "elastic") end
    assert(info().cycle == 0)
    -- crackseed{ auto } takes the kept result as any other; an origin given anchors every group's cuts.
    local groups = crackseed{ auto = pre, spacing = 1, material = "rock", origin = {0.25, 0.5} }
    assert(#groups > 0)
    for _, g in ipairs(groups) do
      assert(g.origin.x == 0.25 and g.origin.y == 0.5, "group origin " .. g.origin.x .. ", " .. g.origin.y)
    end
  )");
}

// The same weak rock with 30 iterations a load step: a failed step's line search stops once it has
// given the same out-of-balance force, to the last bit, four iterations in a row (it no longer
// moves the iterate), instead of repeating it up to its 30th iteration. The stage has no static
// state past load factor 0.70: after 0.7015625 the steps creep on by less than a tenth of a step
// over 10 cut-backs counted across the small successes between them, which ends the attempt
// (one attempt at the stage: restarts = 0): 11 failed steps, 554 iterations (without the creeping
// budget the attempt went on to 17 cut-backs, 814 iterations, to the same factor; without the
// stop of the line search, 897).
TEST(Prepass, AStuckLineSearchGivesUpAndTheStepIsCutBack) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, weak_plate() + R"(
    local pre = prepass{ stages = { "hole" }, iterations = 30, restarts = 0, on_failure = "keep" }
    local hole = pre.stages[2]
    assert(hole.reached == 0.7015625, "reached " .. hole.reached)
    local failed, stalled = 0, 0
    for _, step in ipairs(hole.steps) do
      local r, n = step.residuals, #step.residuals
      if not step.converged then
        failed = failed + 1
        if n < 30 and r[n] == r[n - 1] and r[n - 1] == r[n - 2] and r[n - 2] == r[n - 3] then stalled = stalled + 1 end
      end
    end
    assert(failed == 11 and hole.cutbacks == 11, ("failed steps %d, cut-backs %d"):format(failed, hole.cutbacks))
    assert(stalled >= 4, "failed steps that ended on four equal forces: " .. stalled)
    assert(hole.iterations <= 554, "iterations " .. hole.iterations)
  )");
}

// A stage that fails is solved again from its start in twice the load steps, `restarts` times:
// the weak rock's hole, which has no static state past about half its unloading, fails in 10, 20
// and 40 steps; the message names the last attempt's, and the stage's log keeps every attempt's
// steps. restarts = 0 makes one attempt; a negative count is refused before anything is solved.
TEST(Prepass, AFailedStageIsSolvedAgainInTwiceTheSteps) {
  const std::string weak = weak_plate();
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, weak + R"lua(
    local once = prepass{ stages = { "hole" }, iterations = 8, restarts = 0, on_failure = "keep" }
    local hole = once.stages[2]
    assert(hole.restarts == 0, "restarts " .. hole.restarts)
    assert(once.failure:find("(10 load steps from the stage's start)", 1, true), once.failure)
    local again = prepass{ stages = { "hole" }, iterations = 8, on_failure = "keep" }
    local retried = again.stages[2]
    assert(retried.restarts == 2, "restarts " .. retried.restarts)
    assert(again.failure:find("(40 load steps from the stage's start)", 1, true), again.failure)
    assert(#retried.steps > #hole.steps and retried.cutbacks > hole.cutbacks,
           "every attempt's steps are kept")
    assert(retried.iterations > hole.iterations)
    assert(retried.reached > 0.1 and retried.reached < 1, "reached " .. retried.reached)
  )lua");
  EXPECT_TRUE(contains(
      error_of(interpreter, weak + "prepass{ stages = { \"hole\" }, restarts = -1 }"), "restarts"));
}

// crackseed{ auto }'s regions: by principal direction, whatever the mode (a lone zone marked as
// yielded in tension joins the shear region around it), or with by_mode = true by mode too (it
// leaves that region).
TEST(Prepass, AutoRegionsTakeTheModeOfMostOfTheirArea) {
  const std::string scene = weak_plate() + R"(
    local pre = prepass{ stages = { "hole", "slot" }, iterations = 8, on_failure = "keep" }
    -- The yielded zone with the most yielded zones within 1.5 m, marked as a tension zone.
    local marked, most = nil, -1
    for _, z in ipairs(pre.zones) do
      if z.state ~= "none" and z.states[#z.states] ~= "excavated" then
        local near = 0
        for _, o in ipairs(pre.zones) do
          local close = (o.x - z.x) ^ 2 + (o.y - z.y) ^ 2 < 1.5 ^ 2
          if o.state ~= "none" and close then near = near + 1 end
        end
        if near > most then marked, most = z, near end
      end
    end
    marked.state = "tension"
    local function region_of(groups)
      for _, g in ipairs(groups) do
        for _, id in ipairs(g.zones) do if id == marked.id then return g end end
      end
    end
  )";
  Interpreter together;
  together.context().quiet = true;
  expect_runs(together, scene + R"(
    local g = region_of(crackseed{ auto = pre, spacing = 1, material = "rock" })
    assert(g and g.mode == "shear" and #g.zones > 1, "the marked zone is in a shear region")
  )");
  Interpreter apart;
  apart.context().quiet = true;
  expect_runs(apart, scene + R"(
    local g = region_of(crackseed{ auto = pre, spacing = 1, material = "rock", by_mode = true })
    assert(g == nil or (g.mode == "tension" and #g.zones == 1),
           "the marked zone is a region of its own")
  )");
}

// Joints as interface elements: two blocks on a horizontal joint, pressed from the top with the
// sides on rollers (uniaxial strain): the top moves p H / M + p / kn (M = E (1 - nu) / ((1 + nu)
// (1 - 2 nu))), as the explicit solver finds too.
TEST(Prepass, AJointClosesByItsStiffness) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {0, 1}, y = {0, 2} }
    jset{ angle = 0, spacing = 10, origin = {0, 1} }
    zone{ edge = 0.25 }
    material{ "rock", young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 2e9, ks = 1e9, friction = 30 }
    jassign{ material = "joint" }
    boundary{ side = "bottom", fix = "y" }
    boundary{ side = "left", fix = "x" }
    boundary{ side = "right", fix = "x" }
    boundary{ side = "top", stress = { 0, -1e6, 0 } }
    assert(info().blocks == 2)
    local M = 1e9 * 0.75 / (1.25 * 0.5)
    local expected = -(1e6 * 2 / M + 1e6 / 2e9)
    local top = gp_near(0.5, 2).id
    local pre = prepass{ steps = 1 }
    local implicit = pre.gridpoints[top].uy
    assert(math.abs(implicit - expected) < 1e-9 * math.abs(expected), ("%.12g against %.12g"):format(implicit, expected))
    assert(math.abs(prepass{ joints = false, steps = 1 }.gridpoints[top].uy - (-1e6 * 2 / M)) < 1e-9 * math.abs(expected),
           "tied, the joint adds nothing")
    solve{ ratio = 1e-10, max_cycles = 100000 }
    for g in gridpoints() do
      if g.id == top then assert(math.abs(g.uy - expected) < 1e-6 * math.abs(expected), "explicit: " .. g.uy) end
    end
  )");
}

// A block on a 40 degree joint under gravity holds with 50 degrees of friction (its shear traction
// below the limit); with 30 it slides, and there is no static state to find
// (tests/bad/prepass_loose_block.lua).
TEST(Prepass, ABlockOnAJointHoldsByFriction) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {0, 10}, y = {0, 10} }
    jset{ angle = 40, spacing = 20, origin = {5, 5} }
    zone{ edge = 1 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 50 }
    jassign{ material = "joint" }
    boundary{ side = "bottom", fix = "xy" }
    gravity{ 0, -10 }
    local pre = prepass{ steps = 2 }
    local tied = prepass{ steps = 2, joints = false }
    -- Held, the blocks settle as one under their weight (about 1 mm); the joint adds only its
    -- elastic give (sigma / kn ~ 3e-5 m), where sliding would add metres.
    local largest, apart = 0, 0
    for i, g in ipairs(pre.gridpoints) do
      largest = math.max(largest, math.abs(g.ux), math.abs(g.uy))
      apart = math.max(apart, math.abs(g.ux - tied.gridpoints[i].ux), math.abs(g.uy - tied.gridpoints[i].uy))
    end
    assert(largest > 5e-4 and apart < 1e-4, ("settles %g, joint's give %g"):format(largest, apart))
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
