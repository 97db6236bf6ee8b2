// Bolts in a model: the same bits on any thread count, cut where their rock is excavated,
// re-hosted across a joint without a jump, untouched by reset{ displacement }, replayed with a
// re-zone.
#include <lua.hpp>

#include "interp_test.hpp"

namespace edem::test {
namespace {

// A block cut by a joint dipping 45 deg (x + y = 3); the rock, the joint (friction 25 deg) and the
// rebar, after any more cuts; the left side held, gravity on.
const char* kJointedBlock = R"(
  model{ title = "bolted" }
  block{ x = {0, 4}, y = {0, 2} }
  crack{ from = {0.5, 2.5}, to = {3.5, -0.5} }
)";
const char* kRockAndRebar = R"(
  zone{ edge = 0.25 }
  material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "joint", kn = 5e9, ks = 5e9, friction = 25 }
  jassign{ material = "joint" }
  gravity{ 0, -9.81 }
  boundary{ side = "left", fix = "xy" }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
                 bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
)";

// Two blocks under gravity: the lower-left one held by its left side, the upper-right one resting
// on the joint (so it would slide) and held by a bolt across it.
const std::string kBolted = std::string(kJointedBlock) + R"(
  region{ name = "right", polygon = {{3, 0}, {4, 0}, {4, 2}, {1, 2}} }
)" + kRockAndRebar + R"(
  bolt{ from = {0.5, 0.8}, to = {3.5, 1.4}, segments = 24, material = "rebar" }
)";

// Runs kBolted + `tail` and returns what the script printed through `report`.
std::string run_with(int threads, const std::string& tail) {
  Interpreter interpreter({.quiet = true, .threads = threads, .stdlib_dirs = {}});
  // Zones small enough for two threads' worth of work.
  std::string model = kBolted;
  model.replace(model.find("edge = 0.25"), 11, "edge = 0.05");
  expect_runs(interpreter, model + R"(
    local out = {}
    function report(...) for _, v in ipairs({...}) do out[#out + 1] = ("%.17g"):format(v) end end
  )" + tail + R"(
    result = table.concat(out, " ")
  )");
  lua_getglobal(interpreter.state(), "result");
  std::string result = lua_isstring(interpreter.state(), -1) ? lua_tostring(interpreter.state(), -1) : "";
  lua_pop(interpreter.state(), 1);
  return result;
}

TEST(Bolts, TwoThreadsGiveTheSameBitsAsOne) {
  const std::string tail = R"(
    cycle(400)
    for b in bolts() do
      report(b.head_force)
      for _, s in ipairs(b.segments) do report(s.force, s.slip, s.x, s.y) end
    end
    for g in gridpoints() do report(g.ux, g.uy) end
  )";
  const std::string one = run_with(1, tail), two = run_with(2, tail);
  EXPECT_FALSE(one.empty());
  EXPECT_EQ(one, two);
}

TEST(Bolts, HoldTheBlockAndCarryItsPull) {
  {  // Without the bolt the block slides off the joint: the grout's pull on the rock is what holds it.
    std::string model = kBolted;
    model.erase(model.find("  bolt{ from"));
    Interpreter loose;
    loose.context().quiet = true;
    expect_runs(loose, model + R"(
      local r = solve{ ratio = 1e-7, max_cycles = 20000 }
      assert(not r.converged and gp_near(4, 2).uy < -1, "the block slides without the bolt")
    )");
  }
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"(
    local r = solve{ ratio = 1e-7, max_cycles = 200000 }
    assert(r.converged, "solved")
    assert(gp_near(4, 2).uy > -0.02, "held within 2 cm")
    local b
    for x in bolts() do b = x end
    -- The segment across the joint carries the pull; the grout takes it off towards the ends.
    local largest, ends = 0, math.max(math.abs(b.segments[1].force), math.abs(b.segments[24].force))
    for _, s in ipairs(b.segments) do largest = math.max(largest, s.force) end
    assert(largest > 0 and ends < 0.5 * largest, ("largest %g, at the ends %g"):format(largest, ends))
    assert(b.broken == 0 and b.yielded == 0 and not b.removed)
  )");
}

TEST(Bolts, AreLaidWhereTheDrawnRockIsNow) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"lua(
    solve{ ratio = 1e-7, max_cycles = 200000 }
    -- The right block has moved a few mm; a bolt drawn from a gridpoint of it, (x, y) as drawn,
    -- is laid where that rock is now, stress-free.
    local g = gp_near(3.7, 0.4)
    local id = bolt{ from = {g.x, g.y}, to = {g.x, g.y + 1.2}, segments = 6, material = "rebar" }
    local b
    for x in bolts() do if x.id == id then b = x end end
    local a = b.segments[1].a
    assert(math.abs(a.x - (g.x + g.ux)) < 1e-9 and math.abs(a.y - (g.y + g.uy)) < 1e-9,
           ("head at (%.9g, %.9g), the rock there at (%.9g, %.9g)"):format(a.x, a.y, g.x + g.ux, g.y + g.uy))
    assert(math.abs(g.uy) > 1e-3, "the rock had moved")
    cycle(10)
    for x in bolts() do
      if x.id == id then
        for _, s in ipairs(x.segments) do assert(math.abs(s.force) < 1, ("force %g"):format(s.force)) end
      end
    end
  )lua");
}

TEST(Bolts, AreCutWhereTheirRockIsExcavatedAndGoOutOfServiceWhenNoneIsLeft) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"lua(
    bolt{ from = {3.3, 1.0}, to = {3.8, 1.5}, segments = 4, material = "rebar" }  -- all in the right block
    boundary{ side = "right", fix = "xy" }
    solve{ ratio = 1e-6 }
    excavate("right")
    cycle(10)
    local across, inside
    for x in bolts() do if x.id == 1 then across = x else inside = x end end
    -- The bolt across the joint: its part in the right block is gone, its part in the left stays.
    assert(not across.removed, "the bolt's head is still in the left block")
    local cut, kept = 0, 0
    for _, s in ipairs(across.segments) do
      local beyond = s.b.x + s.b.y > 3 + 1e-6  -- its end past the joint x + y = 3, in the dug block
      if beyond then
        assert(s.force == 0 and s.state == "removed", ("segment at (%g, %g): %s, %g N/m"):format(s.x, s.y, s.state, s.force))
        cut = cut + 1
      else
        assert(s.state ~= "removed", ("segment at (%g, %g) is in the left block"):format(s.x, s.y))
        kept = kept + 1
      end
    end
    assert(cut == 13 and kept == 11, ("%d segments cut, %d kept"):format(cut, kept))
    -- The bolt wholly in the right block has nothing left.
    assert(inside.removed, "all of the second bolt's rock was excavated")
    for _, s in ipairs(inside.segments) do assert(s.force == 0 and s.state == "removed") end
    assert(inside.head_force == 0)
    local ok_head, why = pcall(bolt_head, { bolt = inside.id, velocity = 1e-3 })
    assert(not ok_head and why:find("head was cut off with its rock", 1, true), why)
    -- And a bolt cannot be laid there now.
    local ok, err = pcall(bolt, { from = {3.2, 1}, to = {3.8, 1}, segments = 2, material = "rebar" })
    assert(not ok and err:find("not in the rock"), err)
  )lua");
}

// A segment that broke and was then cut away with its rock (a block mucked out) still counts in
// the bolt's broken, and says it broke; a checkpoint keeps that.
TEST(Bolts, CountASegmentThatBrokeAfterItIsCutAwayWithItsRock) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"lua(
    -- The right block pulled off until the bolt across the joint breaks there, then held.
    local function the_bolt() for b in bolts() do return b end end
    boundary{ side = "right", xvel = 2e-6 }
    local broken_at
    for batch = 1, 40 do
      cycle(500)
      for i, s in ipairs(the_bolt().segments) do if s.state == "broken" then broken_at = i end end
      if broken_at then break end
    end
    assert(broken_at, "the bolt did not break")
    boundary{ side = "right", fix = "xy" }
    cycle(10)
    local before = the_bolt()
    assert(before.broken >= 1 and before.segments[broken_at].broke, "a broken segment counts as broken")
    for i, s in ipairs(before.segments) do
      assert(s.broke == (s.state == "broken"), ("segment %d: %s, broke %s"):format(i, s.state, tostring(s.broke)))
    end
    -- The rock beyond the joint dug out: the broken segment reaches it and is cut away with it,
    -- but it broke all the same.
    excavate("right")
    cycle(10)
    local function check(b, when)
      local s = b.segments[broken_at]
      assert(s.state == "removed" and s.broke, ("%s: the broken segment is %s, broke %s"):format(when, s.state,
             tostring(s.broke)))
      assert(b.broken == before.broken, ("%s: broken %d, %d before the cut"):format(when, b.broken, before.broken))
      assert(not b.segments[1].broke, when .. ": the head's segment never broke")
    end
    check(the_bolt(), "after the cut")
    local file = os.tmpname()
    save(file .. ".h5")
    restore(file .. ".h5")
    os.remove(file .. ".h5")
    os.remove(file)
    check(the_bolt(), "restored")
  )lua");
}

// A bolt laid after the model has cycled (as a cavern's step is bolted once it is solved) and
// saved before the next cycle: the checkpoint restores, and cycling goes on from it as from the
// model it was saved from.
TEST(Bolts, LaidAfterCyclingAreSavedAndRestoredBeforeTheNextCycle) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"lua(
    set{ damping = "adaptive" }
    solve{ ratio = 1e-5 }
    bolt{ from = {0.5, 1.6}, to = {3.0, 1.8}, segments = 10, material = "rebar" }
    local file = os.tmpname()
    save(file .. ".h5")
    cycle(50)
    local went_on = {}
    for g in gridpoints() do went_on[g.id] = g.uy end
    restore(file .. ".h5")
    os.remove(file .. ".h5")
    os.remove(file)
    local n = 0
    for _ in bolts() do n = n + 1 end
    assert(n == 2, ("%d bolts restored, 2 saved"):format(n))
    cycle(50)
    for g in gridpoints() do
      assert(g.uy == went_on[g.id],
             ("gridpoint %d: uy %.17g restored, %.17g as saved"):format(g.id, g.uy, went_on[g.id]))
    end
  )lua");
}

// The cut is applied when the model is next prepared, but a head dug out by an excavate{} just
// before is gone already: a drive given to it then is refused too, not dropped at the next cycle.
TEST(Bolts, RefuseADriveOnAHeadDugOutBeforeAnyCycle) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"lua(
    local inside = bolt{ from = {3.3, 1.0}, to = {3.8, 1.5}, segments = 4, material = "rebar" }
    boundary{ side = "right", fix = "xy" }
    solve{ ratio = 1e-6 }
    excavate("right")
    local ok, why = pcall(bolt_head, { bolt = inside, velocity = 1e-3 })
    assert(not ok, "a drive on a head dug out was accepted")
    assert(why:find("head was cut off with its rock", 1, true), why)
    -- The bolt across the joint keeps its head in the left block: it can still be driven.
    bolt_head{ bolt = 1, force = 1e3 }
    cycle(10)
    local across
    for x in bolts() do if x.id == 1 then across = x end end
    assert(across.head_force ~= 0, "the drive on the head left in the rock was dropped")
  )lua");
}

// A block resting on a joint that dips 45 deg (friction 25 deg) is held by a bolt whose head was in
// the block beyond it, which is mucked out: the rest of the bolt, grouted in the block and in the
// rock behind the joint, still holds it. With the block rigid and the joint slipping all along,
// the bolt across the joint carries T = W (sin 45 - cos 45 tan 25) / (-u.s + (-u.n) tan 25), u the
// bolt's axis towards its end, s the block's way down the joint, n the joint's normal into it.
TEST(Bolts, StillHoldTheBlocksBehindWhenTheBlockAtTheirHeadIsMuckedOut) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kJointedBlock) + R"lua(
    crack{ from = {3.2, -0.5}, to = {3.2, 2.5} }  -- the bolt's head block, right of x = 3.2
  )lua" + kRockAndRebar + R"lua(
    local id = bolt{ from = {3.8, 1.4}, to = {0.8, 0.8}, segments = 24, material = "rebar" }
    for b in blocks() do if b.x > 3.2 then excavate{ block = b.id } end end  -- mucked out
    local r = solve{ ratio = 1e-6, max_cycles = 200000 }
    assert(r.converged, ("not in equilibrium after %d cycles (ratio %g): nothing holds the block"):format(r.cycles, r.ratio))
    local b
    for x in bolts() do if x.id == id then b = x end end
    assert(not b.removed, "the bolt was taken out of service whole")
    -- The segment across the joint (its ends either side of x + y = 3).
    local force
    for _, s in ipairs(b.segments) do
      if (s.a.x + s.a.y - 3) * (s.b.x + s.b.y - 3) < 0 then force = s.force end
    end
    local w = 2500 * 9.81 * 2.4  -- the block between the joint and x = 3.2: 2.4 m2
    local u = { -3 / math.sqrt(9.36), -0.6 / math.sqrt(9.36) }
    local r2 = math.sqrt(0.5)
    local us, un, mu = u[1] * r2 - u[2] * r2, (u[1] + u[2]) * r2, math.tan(math.rad(25))
    local expected = w * (r2 - r2 * mu) / (-us - un * mu)
    print(("bolt across the joint: %.1f N/m, expected %.1f N/m (%.2f %%)"):format(force, expected,
          100 * (force - expected) / expected))
    assert(math.abs(force - expected) <= 0.02 * expected, "the bolt does not carry what the block needs")
    local moved = 0
    for g in gridpoints() do
      if g.x + g.y > 3 + 1e-6 and g.x < 3.2 - 1e-6 then moved = math.max(moved, math.sqrt(g.ux ^ 2 + g.uy ^ 2)) end
    end
    assert(moved < 0.01, ("the block moved %.3g m"):format(moved))
  )lua");
}

TEST(Bolts, ResetDisplacementLeavesTheirForces) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"(
    solve{ ratio = 1e-7, max_cycles = 200000 }
    local function forces()
      local f = {}
      for b in bolts() do for _, s in ipairs(b.segments) do f[#f + 1] = s.force end end
      return f
    end
    local before = forces()
    reset{ "displacement" }
    cycle(50)
    local after, largest = forces(), 0
    for i = 1, #before do largest = math.max(largest, math.abs(before[i])) end
    for i = 1, #before do
      assert(math.abs(after[i] - before[i]) <= 1e-5 * largest,
             ("segment %d: %g before, %g after"):format(i, before[i], after[i]))
    end
  )");
}

TEST(Bolts, NodesSlidingIntoTheNextBlockKeepTheirGrout) {
  // Rigid ground in two blocks; a bolt in the right one with its head at the joint, pulled out
  // through the left one: the nodes cross the joint into the left block and the pull-out load
  // goes on smoothly (a node re-hosted with its grout's force and slip).
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    model{ title = "two blocks" }
    block{ x = {-1, 1}, y = {-0.05, 0.05} }
    crack{ from = {0, -1}, to = {0, 1} }
    zone{ edge = 0.1 }
    material{ "rock", young = 30e9, poisson = 0.25, density = 2600 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
    jassign{ material = "joint" }
    boundary{ polygon = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, fix = "xy" }
    bolt_material{ "b", young = 190e9, area = 446e-6, yield_tension = 1e6, failure_strain = 0.5,
                   bond_stiffness = 50e6, bond_strength = 0.2e6 }
    local id = bolt{ from = {-0.05, 0}, to = {0.5, 0}, free_length = 0.05, segments = 20, material = "b" }
    local loads = {}
    for step = 1, 30 do
      bolt_head{ bolt = id, velocity = 1e-7 }
      cycle(10000)  -- 1 mm a step: the nodes (0.025 m apart) cross the joint one after another
      bolt_head{ bolt = id, velocity = 0 }
      solve{ ratio = 1e-9, max_cycles = 100000 }
      for b in bolts() do loads[step] = b.head_force end
    end
    -- Past the peak the whole bond slips: the load stays at s_b L = 0.1 MN while nodes change
    -- blocks (a node that lost its grout would drop it by s_b dx = 5 kN).
    for step = 10, 30 do
      assert(math.abs(loads[step] - 0.1e6) < 0.002e6, ("step %d: %g"):format(step, loads[step]))
    end
    -- And the bolt stays straight: the nodes slide along it, not off it (a slide along an axis
    -- that follows its own turning would feed back on itself).
    for b in bolts() do
      for _, s in ipairs(b.segments) do assert(math.abs(s.y) < 1e-9, ("a node off the axis: y = %g"):format(s.y)) end
    end
  )");
}

TEST(Bolts, TheirStiffnessSetsTheDynamicTimeStep) {
  // A stiff bolt (short segments of steel) in soft rock: the automatic step is the bolt's, and
  // a step forced above it is refused before it runs (its segments would ring between their
  // yield forces, bounded, so the watchdog would not see it).
  const std::string model = std::string(kBolted) + R"(
    material{ "rock", density = 2500, young = 1e8, poisson = 0.25 }
    boundary{ side = "right", fix = "xy" }
    set{ mode = "dynamic" }
    cycle(1)
    local bolt_only = info().step
    -- Segments 0.1285 m, 5 kg/m over 1.5 m: a node's own bound 2 sqrt(m / k), k = 4 EA / L / 1.5
    -- (two segments, both ends moving) + the grout.
    local ea = 200e9 * 4.9e-4 / 1.5
    local l = math.sqrt(3 ^ 2 + 0.6 ^ 2) / 24
    local m = 7850 * 4.9e-4 / 1.5 * l
    local k = 4 * ea / l + 2 * 50e6 / 1.5 * l
    local bound = 2 * math.sqrt(m / k)
    assert(bolt_only <= 0.9 * bound * (1 + 1e-9) and bolt_only > 0.5 * bound,
           ("step %g, a bolt node's bound %g"):format(bolt_only, bound))
    step_used = bolt_only
  )";
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, model + R"(
    cycle(2000)
    for b in bolts() do assert(b.max_force == b.max_force, "finite") end
  )");
  Interpreter forced;
  forced.context().quiet = true;
  const std::string error = error_of(forced, model + R"(
    set{ step = 3 * step_used }
    cycle(5000)
  )");
  EXPECT_TRUE(contains(error, "test.lua:")) << error;
  EXPECT_TRUE(contains(error, "above the critical step")) << error;
  EXPECT_TRUE(contains(error, "bolts' stiffest node")) << error;
}

TEST(Bolts, LaidBeforeARezoneAreLaidAgain) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBolted) + R"(
    jset{ angle = 0, spacing = 10, origin = {0, 1.0} }  -- re-cuts and re-zones
    local n = 0
    for b in bolts() do n = n + 1; assert(#b.segments == 24) end
    assert(n == 1, ("%d bolts after the re-zone"):format(n))
    solve{ ratio = 1e-6, max_cycles = 100000 }
  )");
}

}  // namespace
}  // namespace edem::test
