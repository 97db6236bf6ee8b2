// The mechanical commands as a script uses them: materials, loads, solving, the queries of the
// solver state, callbacks and histories; and how an error inside a callback is reported.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp_test.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::error_of;
using test::expect_runs;
using test::starts_with;

// A 10 m x 10 m elastic column on a fixed base with smooth sides, under gravity.
constexpr const char* kColumn = R"(
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", density = 2500, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
gravity{ 0, -9.81 }
)";

std::string column(const std::string& rest) {
  return std::string(kColumn) + rest;
}

TEST(Mechanics, GravityColumnSettlesToRhoGDepth) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"(
    local r = solve{ ratio = 1e-6 }
    assert(r.converged == true and r.ratio <= 1e-6, "converged: " .. tostring(r.ratio))
    assert(math.type(r.cycles) == "integer" and r.cycles > 0)
    assert(info().cycle == r.cycles and info().ratio == r.ratio)
    for _, p in ipairs{ {5, 5}, {2.5, 1.5}, {7.5, 8.5} } do
      local z = zone_at(p[1], p[2])
      local expected = -2500 * 9.81 * (10 - z.y)
      assert(math.abs(z.syy / expected - 1) < 0.02, ("syy %g, expected %g"):format(z.syy, expected))
      assert(z.s1 <= z.s3 and z.syy < 0)
      assert(z.state == "elastic" and z.material == "rock")
    end
    assert(zone_at(20, 5) == nil)
    local top = gp_near(5, 10)
    assert(top.uy < 0 and not top.fixed_y, "the top settles")
    local base = gp_near(5, 0)
    assert(base.fixed_x and base.fixed_y and base.uy == 0)
    -- a second solve from equilibrium does (almost) nothing
    assert(solve{ ratio = 1e-5 }.cycles <= 10)
  )"));
}

// info().damping_rate: adaptive damping's c = 2 omega, which the solve sets from the Rayleigh quotient
// (at most 2 / step, where it would reverse a velocity); 0 under local damping.
TEST(Mechanics, InfoGivesTheAdaptiveDampingRate) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"lua(
    assert(info().damping_rate == 0, "none before cycling")
    solve{ ratio = 1e-6 }
    local c = info().damping_rate
    assert(c > 0 and c <= 2 / info().step, ("adaptive: %g (step %g)"):format(c, info().step))
    set{ damping = "local" }
    assert(info().damping_rate == 0, "local: " .. info().damping_rate)
  )lua"));
}

TEST(Mechanics, SolveWithoutATableAndItsLine) {
  Interpreter interpreter;
  testing::internal::CaptureStdout();
  expect_runs(interpreter, column("local r = solve()\nassert(r.converged)"));
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_TRUE(starts_with(out, "solve: ")) << out;
  EXPECT_TRUE(contains(out, " cycles, ratio "));
  testing::internal::CaptureStdout();
  expect_runs(interpreter,
              "local r = solve{ ratio = 1e-9, max_cycles = 3 }\nassert(not r.converged)");
  EXPECT_TRUE(starts_with(testing::internal::GetCapturedStdout(),
                          "solve: stopped after 3 cycles at ratio "));
}

// solve{ stall }: a block on a 30 degree slope with 20 degrees of friction has no equilibrium;
// its solve ends once the ratio has not fallen a tenth in `stall` cycles, long before max_cycles,
// under either damping, and says why. The same block with 40 degrees of friction settles in just
// the cycles it takes without a stall limit.
TEST(Mechanics, AStallLimitEndsTheSolveOfABlockThatKeepsSliding) {
  Interpreter interpreter;
  testing::internal::CaptureStdout();
  expect_runs(interpreter, R"lua(
    local function block_on_slope(friction, damping)
      model{ title = "a block on a slope" }
      block{ x = {-3, 8}, y = {-1, 0} }
      block{ x = {-1, 1}, y = {0, 1} }
      zone{ edge = 0.5 }
      material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
      assign{ material = "rock" }
      joint_material{ "plane", kn = 1e10, ks = 1e10, friction = friction }
      jassign{ material = "plane" }
      boundary{ polygon = {{-3.1, -1.1}, {8.1, -1.1}, {8.1, -0.01}, {-3.1, -0.01}}, fix = "xy" }
      gravity{ 9.81 * math.sin(math.rad(30)), -9.81 * math.cos(math.rad(30)) }
      if damping == "local" then set{ damping = "local", local_damping = 0.8 } end
    end
    for _, damping in ipairs({ "adaptive", "local" }) do
      block_on_slope(20, damping)
      local r = solve{ ratio = 1e-5, max_cycles = 1000000, stall = 2000 }
      assert(r.stalled and not r.converged, damping .. ": not stalled")
      assert(r.cycles < 20000, ("%s: stalled only after %d cycles"):format(damping, r.cycles))
      assert(gp_near(0, 1).ux > 1e-3, damping .. ": the block did not slide")
      block_on_slope(40, damping)
      local free = solve{ ratio = 1e-5, max_cycles = 100000 }
      block_on_slope(40, damping)
      local limited = solve{ ratio = 1e-5, max_cycles = 100000, stall = 2000 }
      assert(free.converged and limited.converged and not limited.stalled, damping .. ": did not settle")
      assert(limited.cycles == free.cycles, ("%s: %d cycles with the limit, %d without"):format(damping,
             limited.cycles, free.cycles))
    end
  )lua");
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_TRUE(contains(out, "the ratio has not fallen a tenth below its lowest in the last 2000 cycles (stall): "
                            "the rock keeps moving without nearing an equilibrium"))
      << out;
}

// solve{ stall } and judging at equilibrium: each judgment that breaks sections starts the count
// again, so the rounds after a hole dug at once (150 cracks in 6 judgments, about 500 cycles
// each) run as without the limit even when it is shorter than a round. Were the count kept
// across a judgment, the ratio at the equilibrium just judged would be the lowest to beat and a
// limit of 2,000 cycles would already cut the rounds short.
// hole_in_a_ring(): a new model, a 40 m x 30 m block under in-situ stress with a 3 m hole to dig
// and, in a ring of 7 m about it, potential cracks that break in several rounds once it is dug.
constexpr const char* kHoleInARing = R"lua(
local shapes = require "edem.shapes"
local function circle(r) return shapes.circle{ centre = { 20, 15 }, radius = r, segments = 32 } end
local function hole_in_a_ring()
  model{ title = "cracks at equilibrium" }
  block{ x = { 0, 40 }, y = { 0, 30 } }
  region{ name = "hole", polygon = circle(3) }
  region{ name = "ring", polygon = circle(7) }
  crackseed{ region = "ring", angles = { 30, 120 }, spacing = 1, material = "strength", after = "crack" }
  zone{ edge = 0.5, far = 2, near = { "ring" } }
  material{ "rock", density = 2500, young = 2e9, poisson = 0.25 }
  material{ "strength", model = "mohr", young = 2e9, poisson = 0.25, cohesion = 1e6, friction = 30,
            tension = 0.3e6 }
  assign{ material = "rock" }
  joint_material{ "crack", kn = 2e10, ks = 1e10, friction = 30 }
  insitu{ sxx = -3e6, syy = -5e6, szz = -4e6 }
  for _, side in ipairs{ "left", "right", "top", "bottom" } do boundary{ side = side, fix = "xy" } end
end
)lua";

TEST(Mechanics, AStallLimitDoesNotCutShortTheRoundsOfJudgingAtEquilibrium) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kHoleInARing) + R"lua(
    local function hole_dug_at_once(stall)
      hole_in_a_ring()
      judge{ at = "equilibrium" }
      excavate{ region = "hole" }
      return solve{ ratio = 1e-5, max_cycles = 20000, stall = stall }
    end
    local free = hole_dug_at_once(0)
    assert(free.converged and free.judgments >= 4 and free.broke > 100,
           ("the rounds: %d judgments, %d broke"):format(free.judgments, free.broke))
    local cracks = info().cracks
    for _, stall in ipairs{ 2000, 300 } do
      local limited = hole_dug_at_once(stall)
      assert(limited.converged and not limited.stalled, ("stall %d: stopped after %d cycles, %d judgments"):format(
             stall, limited.cycles, limited.judgments))
      assert(limited.cycles == free.cycles and limited.judgments == free.judgments and info().cracks == cracks,
             ("stall %d: %d cycles, %d judgments, %d cracks against %d, %d, %d"):format(stall, limited.cycles,
             limited.judgments, info().cracks, free.cycles, free.judgments, cracks))
    end
  )lua");
}

// solve{ settle }: local damping brings the column to 1e-5, adaptive damping takes it on to 1e-9,
// to the state local damping alone reaches at 1e-9 (elastic: there is one); the solve then gives
// local damping back. (What it saves depends on the model: RESULTS, "One step from the in-situ
// state".)
TEST(Mechanics, ASettledSolveEndsAtTheTighterRatioAndGivesItsDampingBack) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"lua(
    set{ damping = "local" }
    local alone = solve{ ratio = 1e-9, max_cycles = 1000000 }
    local top = gp_near(5, 10).uy
    model{}
  )lua") + column(R"lua(
    set{ damping = "local" }
    local settled = solve{ ratio = 1e-5, settle = 1e-9, max_cycles = 1000000 }
    assert(alone.converged and settled.converged and settled.ratio <= 1e-9, "ratio " .. settled.ratio)
    local uy = gp_near(5, 10).uy
    assert(math.abs(uy / top - 1) < 1e-6, ("the top settles %.9g m, under local damping alone %.9g"):format(uy, top))
    assert(info().damping_rate == 0, "local damping is given back: " .. info().damping_rate)
  )lua"));
}

// Judged at equilibrium, each state judged is the settled one, and the rounds after a break go on:
// the hole's ring of potential cracks (as above) breaks in several rounds and ends settled.
TEST(Mechanics, ASettledSolveJudgesTheSettledStatesInRounds) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kHoleInARing) + R"lua(
    hole_in_a_ring()
    set{ damping = "local" }
    judge{ at = "equilibrium", criterion = function(s)
      assert(info().ratio <= 1e-8, ("a state judged at ratio %g"):format(info().ratio))
      if s.overstress > 1 then return s.s3 > s.tension and "tension" or "shear" end
    end }
    excavate{ region = "hole" }
    local r = solve{ ratio = 1e-5, settle = 1e-8, max_cycles = 200000 }
    assert(r.converged and r.ratio <= 1e-8 and r.judgments >= 3 and r.broke > 100,
           ("%d cycles to ratio %g: %d judgments, %d broke"):format(r.cycles, r.ratio, r.judgments, r.broke))
    assert(info().damping_rate == 0, "local damping is given back")
  )lua");
}

TEST(Mechanics, SettleMustBeBelowTheRatio) {
  EXPECT_TRUE(contains(error_of(column("solve{ ratio = 1e-5, settle = 1e-5 }")),
                       "settle must be 0 or below ratio (1e-05), got 1e-05"));
}

TEST(Mechanics, QuietSolvePrintsNothing) {
  Interpreter interpreter({.quiet = true, .stdlib_dirs = {}});
  testing::internal::CaptureStdout();
  expect_runs(interpreter, column("solve()"));
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST(Mechanics, EveryRunsOnMultiplesOfN) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    local seen = {}
    local h = every(10, function(cycle) seen[#seen + 1] = cycle end)
    assert(math.type(h) == "integer")
    cycle(95)
    assert(#seen == 9, #seen)
    for i, c in ipairs(seen) do assert(c == 10 * i) end
    cancel(h)
    cycle(20)
    assert(#seen == 9, "cancelled")
    local ok, message = pcall(cancel, h)
    assert(not ok and message:find("cancel: ", 1, true), message)
  )"));
}

TEST(Mechanics, ACallbackMayCancelItself) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    local calls, h = 0
    h = every(5, function() calls = calls + 1; if calls == 2 then cancel(h) end end)
    cycle(50)
    assert(calls == 2, calls)
  )"));
}

TEST(Mechanics, CallbacksSeeTheModelBetweenCycles) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    local cycles = {}
    every(7, function(c) cycles[#cycles + 1] = info().cycle end)
    cycle(21)
    assert(#cycles == 3 and cycles[1] == 7 and cycles[3] == 21)
  )"));
}

TEST(Mechanics, ErrorInsideACallbackNamesItsLineAndTheCyclingCommand) {
  const std::string message = error_of(column(R"(
local function check(c)
  if c >= 30 then
    return c + nothing
  end
end
every(10, function(c)
  check(c)
end)
cycle(100)
)"));
  // The column takes lines 1-9; the script above starts on line 10.
  EXPECT_EQ(message,
            "test.lua:13: every: error in the callback (while cycle() at test.lua:19 was "
            "running): attempt to perform arithmetic on a nil value (global 'nothing')\n"
            "traceback:\n"
            "  test.lua:13: in function 'check'\n"
            "  test.lua:17: in function <test.lua:16>\n"
            "  test.lua:19: in main chunk");
}

TEST(Mechanics, ErrorInsideACallbackStopsAtThatCycle) {
  Interpreter interpreter;
  const std::string message = error_of(interpreter, column(R"(
every(10, function(c) if c == 30 then error("stop") end end)
local function run() solve{ ratio = 1e-12, max_cycles = 1000 } end
run()
)"));
  EXPECT_TRUE(
      starts_with(message,
                  "test.lua:11: every: error in the callback (while solve() at test.lua:12 "
                  "was running): stop\ntraceback:\n  test.lua:11: in function <test.lua:11>\n"
                  "  test.lua:12: in function 'run'\n  test.lua:13: in main chunk"))
      << message;
  EXPECT_EQ(interpreter.context().model().solver_info().cycle, 30);
}

TEST(Mechanics, CommandErrorInsideACallbackKeepsItsName) {
  EXPECT_TRUE(starts_with(error_of(column("every(5, function() info(1) end)\ncycle(5)")),
                          "test.lua:10: every: error in the callback (while cycle() at test.lua:11 "
                          "was running): info: takes no arguments, got 1\n"));
}

TEST(Mechanics, ACaughtCallbackErrorIsAnOrdinaryMessage) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    every(5, function() error("inner") end)
    local ok, message = pcall(cycle, 10)
    assert(not ok)
    assert(message:find("^test.lua:11: every: error in the callback %(while cycle%(%) at "), message)
    assert(info().cycle == 5)
  )"));
}

TEST(Mechanics, NoCyclingOrNewModelInsideACallback) {
  EXPECT_TRUE(contains(error_of(column("every(5, function() cycle(1) end)\ncycle(5)")),
                       "(while cycle() at test.lua:11 was running): cycle: cannot cycle inside a "
                       "callback while cycle() at test.lua:11 is cycling"));
  EXPECT_TRUE(contains(error_of(column("every(5, function() model{} end)\nsolve()")),
                       "model: cannot start a new model inside a callback while solve() at "
                       "test.lua:11 cycles the current one"));
}

TEST(Mechanics, CallbacksRunOnTheCyclingCoroutine) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    local threads = {}
    every(5, function() threads[#threads + 1] = coroutine.running() end)
    local co = coroutine.create(function() cycle(5); coroutine.yield(); cycle(5) end)
    assert(coroutine.resume(co))
    assert(coroutine.resume(co))
    cycle(5)
    local main = coroutine.running()
    assert(threads[1] == co and threads[2] == co and threads[3] == main)
  )"));
}

TEST(Mechanics, CallbackFunctionsAreReleased) {
  Interpreter interpreter;
  expect_runs(interpreter, column(R"(
    local alive = setmetatable({}, { __mode = "k" })
    local function track(f) alive[f] = true; return f end
    local function count() collectgarbage(); collectgarbage(); local n = 0
      for _ in pairs(alive) do n = n + 1 end; return n end
    local h = every(10, track(function() end))
    history{ name = "one", fn = track(function() return 1 end) }
    assert(count() == 2, "the model keeps its functions")
    cancel(h)
    assert(count() == 1, "cancel releases the callback")
    model{}
    assert(count() == 0, "a new model releases the old one's functions")
  )"));
}

TEST(Mechanics, AnInterpreterClosesWithCallbacksHeld) {
  // Under the sanitizers this checks that no reference is released into a closed state.
  Interpreter interpreter;
  expect_runs(interpreter, column("every(10, function() end)\nhistory{ name = 'x', fn = "
                                  "function() return 0 end }\ncycle(10)"));
}

TEST(Mechanics, SetChangesOnlyTheKeysGiven) {
  Interpreter interpreter;
  const auto settings = [&] { return interpreter.context().model().solver_settings(); };
  expect_runs(interpreter, "set{ fraction = 0.5 }");
  EXPECT_EQ(settings().mode, SolverMode::static_);
  EXPECT_EQ(settings().step_fraction, 0.5);
  expect_runs(interpreter, "set{ mode = 'dynamic' }");
  EXPECT_EQ(settings().mode, SolverMode::dynamic);
  EXPECT_EQ(settings().damping, Damping::none);
  EXPECT_EQ(settings().step_fraction, 0.5);
  expect_runs(interpreter, "set{ damping = 'local', local_damping = 0.3 }");
  EXPECT_EQ(settings().damping, Damping::local);
  EXPECT_EQ(settings().local_damping, 0.3);
  expect_runs(interpreter, "set{ step = 1e-4 }");
  EXPECT_EQ(settings().damping, Damping::local);
  EXPECT_EQ(settings().step, 1e-4);
  expect_runs(interpreter, "set{ mode = 'static' }");
  EXPECT_EQ(settings().damping, Damping::adaptive);
  expect_runs(interpreter, "set{ mode = 'dynamic', damping = 'local' }");
  EXPECT_EQ(settings().damping, Damping::local);
  EXPECT_EQ(settings().local_damping, 0.3);
}

TEST(Mechanics, ResetClearsWhatItNames) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"(
    solve()
    local syy = zone_at(5, 5).syy
    assert(gp_near(5, 10).uy < 0)
    reset{ "displacement", "velocity" }
    for gp in gridpoints() do assert(gp.ux == 0 and gp.uy == 0 and gp.vx == 0 and gp.vy == 0) end
    assert(zone_at(5, 5).syy == syy, "stresses are kept")
  )"));
}

// reset{ "joint" } is UDEC's RESET JDISP: the contacts' shear displacement and slip records start
// again from zero (slip measured from an in-situ state), their forces and states are kept.
TEST(Mechanics, ResetJointClearsTheContactsRecordsNotTheirForces) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"(
    jset{ angle = 50, spacing = 4, origin = {0.3, 0.2} }
    joint_material{ "smooth", kn = 1e10, ks = 1e9, friction = 15 }
    jassign{ material = "smooth" }
    solve{ ratio = 1e-5, max_cycles = 3000 }
    local before, slipped = {}, 0
    for c in contacts() do
      before[c.id] = c
      if c.slip > 0 then slipped = slipped + 1 end
    end
    assert(slipped > 0, "the 50 deg joints slip at 15 deg friction")
    reset{ "displacement" }
    local kept = 0
    for c in contacts() do if c.slip == before[c.id].slip then kept = kept + 1 end end
    assert(kept == #before, "displacement alone leaves the contacts' records")
    reset{ "joint" }
    for c in contacts() do
      local b = before[c.id]
      assert(c.us == 0 and c.slip == 0, ("contact %d: us %g, slip %g"):format(c.id, c.us, c.slip))
      assert(c.fn == b.fn and c.fs == b.fs and c.state == b.state and c.un == b.un,
             ("contact %d: forces or state changed"):format(c.id))
    end
  )"));
}

TEST(Mechanics, GridpointsAndZonesCarryTheState) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"(
    cycle(20)
    local n, fixed = 0, 0
    for gp in gridpoints() do
      n = n + 1
      assert(gp.id == n and gp.x == gp.position.x and gp.y == gp.position[2])
      for _, k in ipairs{ "ux", "uy", "vx", "vy", "fx", "fy" } do assert(type(gp[k]) == "number") end
      if gp.fixed_y then fixed = fixed + 1; assert(gp.y == 0) end
      assert(gp.block == 1)
    end
    assert(n == info().gridpoints and fixed > 0)
    local near = gp_near(5.1, 9.9)
    local function d2(gp) return (gp.x - 5.1)^2 + (gp.y - 9.9)^2 end
    for gp in gridpoints() do assert(d2(gp) >= d2(near)) end
    local count = 0
    for z in zones() do
      count = count + 1
      assert(z.material == "rock" and z.state == "elastic" and type(z.syy) == "number")
    end
    assert(count == info().zones)
    local z = zone_at(5, 5)
    assert(#z.vertices == 3 and z.block == 1)
    local i = info()
    assert(i.cycle == 20 and i.time > 0 and i.step > 0 and i.ratio > 0)
  )"));
}

TEST(Mechanics, ZonesWithoutMaterialHaveNone) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    block{ x = {0, 1}, y = {0, 1} }
    zone{ edge = 0.5 }
    local z = zone_at(0.5, 0.5)
    assert(z.material == nil and z.sxx == 0 and z.state == "elastic")
    assert(gp_near(0, 0).ux == 0)
    assert(info().cycle == 0)
  )");
}

TEST(Mechanics, InsituForms) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    block{ x = {0, 10}, y = {0, 10} }
    zone{ edge = 1 }
    material{ "rock", density = 2000, young = 1e9, poisson = 0.3 }
    assign{ material = "rock" }
    insitu{ surface = 20, density = 2000, k0 = 0.5, surcharge = 1e5 }
    local z = zone_at(5, 5)
    local sv = -(1e5 + 2000 * 9.81 * (20 - z.y))
    assert(math.abs(z.syy - sv) < 1e-6 * math.abs(sv), z.syy)
    assert(math.abs(z.sxx - 0.5 * sv) < 1e-6 * math.abs(sv) and z.szz == z.sxx)
    insitu{ sxx = -1e6, syy = -2e6, sxy = 1e5, ygrad = {1e4, 2e4, 0} }
    z = zone_at(5, 5)
    assert(math.abs(z.sxx - (-1e6 + 1e4 * z.y)) < 1e-3 and z.szz == z.sxx)
    assert(math.abs(z.syy - (-2e6 + 2e4 * z.y)) < 1e-3 and z.sxy == 1e5)
    insitu{ sxx = -1e6, ygrad = {0, 0, 0, 3e4} }
    z = zone_at(5, 5)
    assert(z.sxx == -1e6 and math.abs(z.szz - (-1e6 + 3e4 * z.y)) < 1e-3, z.szz)
    insitu{ syy = -5, region = {{0, 0}, {5, 0}, {5, 5}, {0, 5}} }
    assert(zone_at(2, 2).syy == -5 and zone_at(8, 8).syy ~= -5)
  )");
  EXPECT_EQ(error_of(interpreter, "insitu{ surface = 10, density = 1, syy = 1, sxy = 2 }"),
            "test.lua:1: insitu: syy, sxy belong to the stress form; with surface = give density, "
            "k0 and surcharge");
}

TEST(Mechanics, BoundaryForms) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"(
    boundary{ side = "top", stress = {0, -1e6, 0} }
    solve()
    local z = zone_at(5, 9.5)
    assert(math.abs(z.syy - (-1e6 - 2500 * 9.81 * (10 - z.y))) < 0.02e6, z.syy)
    boundary{ polygon = {{-1, 9}, {11, 9}, {11, 11}, {-1, 11}}, yvel = -1e-6 }
    assert(gp_near(5, 10).fixed_y)
    boundary{ side = "top", free = "y" }
    assert(not gp_near(5, 10).fixed_y)
  )"));
}

TEST(Mechanics, MaterialForms) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    material{ "a", young = 1e9, poisson = 0.2 }
    material{ "b", bulk = 1e9, shear = 5e8, density = 1800 }
    material{ "c", model = "mohr", young = 1e9, poisson = 0.2, cohesion = 1e6, friction = 30,
              dilation = 10, tension = 1e5 }
    material{ "void", model = "null" }
    material{ "a", young = 2e9, poisson = 0.3 }  -- redefined before use
  )");
  EXPECT_EQ(interpreter.context().model().material_names(),
            (std::vector<std::string>{"a", "b", "c", "void"}));
  EXPECT_EQ(error_of("material{ 'r', young = 1, poisson = 0.1, shear = 1 }"),
            "test.lua:1: material: give young and poisson, or bulk and shear, not both pairs");
  EXPECT_EQ(error_of("material{ 'r', bulk = 1 }"),
            "test.lua:1: material: bulk needs shear too (or give young and poisson)");
  EXPECT_EQ(error_of("material{ 'r', young = 1, poisson = -1 }"),
            "test.lua:1: material: poisson must be in (-1, 0.5), got -1");
  EXPECT_EQ(error_of("material{ 'r', young = 1, poisson = 0.2, tension = 1 }"),
            "test.lua:1: material: tension needs model = \"mohr\" or \"ss\" (this material's model is "
            "\"elastic\")");
  EXPECT_EQ(error_of("material{ '', model = 'null' }"),
            "test.lua:1: material: name must not be empty");
}

TEST(Mechanics, Histories) {
  const fs::path csv =
      fs::temp_directory_path() / ("edem_histories_" + std::to_string(::getpid()) + ".csv");
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"lua(
    assert(history{ "ratio" } == "ratio")
    assert(history{ "uy", at = {5, 10}, every = 20 } == "uy@(5 10)")
    assert(history{ "syy", at = {5, 5}, name = "mid" } == "mid")
    local samples = 0
    history{ name = "sag", unit = "m", every = 20,
             fn = function() samples = samples + 1; return -gp_near(5, 10).uy end }
    cycle(40)
    assert(samples == 2, samples)
    history_write(")lua" + csv.string() +
                                  R"lua(")
  )lua"));
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(csv);
  std::string header;
  std::getline(text, header);
  EXPECT_EQ(header, "cycle,ratio [-],uy@(5 10) [m],mid [Pa],sag [m]");
  std::string line;
  int rows = 0;
  while (std::getline(text, line)) ++rows;
  EXPECT_EQ(rows, 4);  // cycles 10, 20, 30, 40
  EXPECT_TRUE(interpreter.context().histories_written);
}

// chart{ history = } draws recorded histories against the cycle; a name it does not know, or a
// history with no samples yet, is an error naming the histories there are.
TEST(Mechanics, ChartOfHistories) {
  const fs::path png =
      fs::temp_directory_path() / ("edem_history_chart_" + std::to_string(::getpid()) + ".png");
  Interpreter interpreter;
  interpreter.context().quiet = true;
  const std::string setup = column(R"lua(
    local uy = history{ "uy", at = {5, 10}, every = 20 }
    history{ name = "sag", unit = "m", every = 20, fn = function() return -gp_near(5, 10).uy end }
  )lua");
  EXPECT_TRUE(contains(error_of(interpreter, setup + "chart{ file = 'x.png', history = 'sag' }"),
                       "chart: history 'sag' has no samples yet: cycle the model first"));
  Interpreter second;
  second.context().quiet = true;
  expect_runs(second, setup + "cycle(40)\nchart{ file = '" + png.string() + "', history = {uy, 'sag'}, title = 'top' }\n");
  EXPECT_GT(fs::file_size(png), 1000u);
  fs::remove(png);
  EXPECT_TRUE(contains(error_of(second, "chart{ file = 'x.png', history = 'nothing' }"),
                       "chart: no history named 'nothing' (histories: uy@(5 10), sag)"));
  EXPECT_TRUE(contains(error_of(second, "chart{ file = 'x.png' }"),
                       "chart: give series = {...}, history = \"name\", or both"));
}

// profile{} samples along a line exactly what history{} and the queries see at each point: the
// nearest gridpoint's displacement, the containing zone's stress; with file = it draws them.
TEST(Mechanics, ProfileSamplesAlongALine) {
  const fs::path png = fs::temp_directory_path() / ("edem_profile_" + std::to_string(::getpid()) + ".png");
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, column(R"lua(
    solve{ ratio = 1e-6 }
    local p = profile{ from = {5, 0}, to = {5, 10}, quantity = "uy", points = 11, file = ")lua" +
                                  png.string() + R"lua(" }
    assert(#p.value == 11 and #p.distance == 11 and #p.x == 11 and #p.y == 11)
    for i = 1, 11 do
      assert(math.abs(p.distance[i] - (i - 1)) < 1e-12 and p.x[i] == 5 and math.abs(p.y[i] - (i - 1)) < 1e-12)
      assert(p.value[i] == gp_near(p.x[i], p.y[i]).uy, "uy at point " .. i)
    end
    assert(p.value[1] == 0 and p.value[11] < 0, "fixed base, settled top")
    local s = profile{ from = {2, 0.5}, to = {8, 9.5}, quantity = "syy", points = 7 }
    for i = 1, 7 do assert(s.value[i] == zone_at(s.x[i], s.y[i]).syy, "syy at point " .. i) end
  )lua"));
  EXPECT_GT(fs::file_size(png), 1000u);
  fs::remove(png);
  EXPECT_TRUE(contains(error_of(interpreter, "profile{ from = {1, 1}, to = {1, 1}, quantity = 'uy' }"),
                       "profile: from and to are the same point (1, 1): a profile needs a line"));
  EXPECT_TRUE(contains(error_of(interpreter, "profile{ from = {1, 1}, to = {2, 1}, quantity = 'joint_sn' }"),
                       "profile: quantity must be one of"));
  EXPECT_TRUE(contains(error_of(interpreter, "profile{ from = {1, 1}, to = {20, 1}, quantity = 'syy' }"),
                       "profile: no zone contains the point (10.306"));
}

// Joint quantities: the counts of the model's contacts, and one contact followed by its
// gridpoint, equal to what contact_near() says about it.
TEST(Mechanics, JointHistories) {
  const fs::path csv =
      fs::temp_directory_path() / ("edem_joint_histories_" + std::to_string(::getpid()) + ".csv");
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"lua(
    block{ x = {0, 1}, y = {0, 2} }
    jset{ angle = 0, spacing = 10, origin = {0, 1} }
    zone{ edge = 0.25 }
    material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 10e9, ks = 1e9, friction = 30 }
    jassign{ material = "j" }
    boundary{ side = "bottom", fix = "xy" }
    boundary{ side = "top", stress = {0, -1e6, 0} }
    assert(history{ "joint_sn", at = {0.5, 1} } == "joint_sn@(0.5 1)")
    history{ "joint_un", at = {0.5, 1} }
    history{ "contacts", every = 5 }
    history{ "max_slip" }
    cycle(200)
    local c = contact_near(0.5, 1)
    history_write(")lua" + csv.string() + R"lua(")
    local last
    for line in io.lines(")lua" + csv.string() + R"lua(") do last = line end
    local v = {}
    for field in last:gmatch("[^,]+") do v[#v + 1] = tonumber(field) end
    assert(v[1] == 200, last)
    assert(v[2] == c.sn and v[3] == c.un, ("%s: sn %g un %g"):format(last, c.sn, c.un))
    assert(v[2] < 0 and v[4] == info().contacts and v[4] > 0 and v[5] == 0, last)
  )lua");
  fs::remove(csv);
}

// The time step allows for the contacts: a stiffer joint material, or contacts that form when
// blocks come together, shorten it at once.
TEST(Mechanics, ContactStiffnessSetsTheStep) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"lua(
    block{ x = {0, 1}, y = {0, 1} }
    block{ x = {0, 1}, y = {1.2, 2.2} }
    zone{ edge = 0.25 }
    material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 1e14, ks = 1e14, friction = 30 }
    jassign{ material = "j" }
    boundary{ side = "bottom", fix = "xy" }
    gravity{ 0, -1000 }
    set{ mode = "dynamic" }
    cycle(1)
    local apart = info().step
    assert(info().contacts == 0, "found " .. info().contacts .. " contacts 0.2 m apart")
    -- falling from rest at 1000 m/s2, the block closes the 0.2 m gap in 20 ms; on so stiff a
    -- joint it bounces off within a few cycles, so every cycle is looked at once it is near
    while info().contacts == 0 and info().time < 0.05 do cycle(100) end
    while (info().contacts == 0 or contact_near(0.5, 1).state == "open") and info().time < 0.05 do
      cycle(1)
    end
    assert(info().contacts > 0 and contact_near(0.5, 1).state ~= "open", "the block never landed")
    local touching = info().step
    assert(touching < 0.5 * apart, ("step %g apart, %g touching"):format(apart, touching))
    joint_material{ "j", kn = 1e16, ks = 1e16, friction = 30 }
    cycle(1)
    assert(info().step < 0.2 * touching, ("step %g, then %g with a 100 x stiffer joint"):format(touching, info().step))
  )lua");
}

TEST(Mechanics, HistoryErrors) {
  EXPECT_EQ(error_of("history{ 'ratio', fn = function() return 1 end }"),
            "test.lua:1: history: give a quantity or fn, not both");
  EXPECT_EQ(error_of("history{ every = 5 }"),
            "test.lua:1: history: what to record? give a quantity, history{ \"ratio\" }, or fn = "
            "function() ... end");
  EXPECT_EQ(error_of("history{ name = 'a,b', fn = function() return 1 end }"),
            "test.lua:1: history: name must not contain commas, quotes or line breaks (it heads "
            "a CSV column), got \"a,b\"");
  EXPECT_EQ(error_of("history{ 'uy', at = {1, 1}, unit = 'mm' }"),
            "test.lua:1: history: unit is for fn histories; uy is in m");
  EXPECT_EQ(error_of("history{ name = 'x', fn = function() return 1 end, at = {0, 0} }"),
            "test.lua:1: history: at is for the built-in quantities; fn computes its own value");
  const std::string message = error_of(column(R"(history{ name = "bad", fn = function()
  return "x"
end }
cycle(10))"));
  EXPECT_EQ(message,
            "test.lua:10: history: fn of history 'bad' must return a number, got \"x\" (while "
            "cycle() at test.lua:13 was running)");
}

}  // namespace
}  // namespace edem
