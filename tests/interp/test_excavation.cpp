// excavate{}, fill{} and stage(): what they change, what they keep, and the stage bookkeeping.
#include "interp_test.hpp"

namespace edem::test {
namespace {

// Two blocks stacked, jointed, under gravity; the upper one a region that can be excavated.
const char* kStack = R"(
  model{ title = "stack" }
  block{ x = {0, 4}, y = {0, 2} }
  block{ x = {0, 4}, y = {2, 4} }
  region{ name = "cut", polygon = {{1, 0}, {3, 0}, {3, 1}, {1, 1}} }
  zone{ edge = 0.5 }
  material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
  material{ "fill", density = 1800, young = 1e8, poisson = 0.3 }
  assign{ material = "rock" }
  joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
  jassign{ material = "joint" }
  gravity{ 0, -9.81 }
  boundary{ side = "bottom", fix = "xy" }
)";

TEST(Excavation, ZonesTurnNullAndTheStageCounts) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kStack) + R"(
    history{ "stage", every = 10 }
    assert(stage() == 0 and info().stage == 0)
    solve{ ratio = 1e-6 }
    local cut = 0
    for z in zones() do if z.region == "cut" then cut = cut + 1 end end
    excavate("cut")
    assert(stage() == 1 and info().stage == 1)
    local gone = 0
    for z in zones() do
      if z.excavated then
        gone = gone + 1
        assert(z.excavated == 1 and z.region == "cut" and z.sxx == 0 and z.syy == 0, "stress-free")
      end
    end
    assert(gone == cut and cut > 0, ("%d of %d zones excavated"):format(gone, cut))
    solve{ ratio = 1e-6 }
    -- The rock over the cut now spans it: the roof above its middle sags.
    assert(gp_near(2, 1).uy < 0)
    fill{ "cut", material = "fill" }
    for z in zones() do
      if z.region == "cut" then assert(not z.excavated and z.material == "fill" and z.syy == 0) end
    end
    assert(stage() == 1, "fill is no stage")
    solve{ ratio = 1e-6 }
    local load = 0
    for z in zones() do if z.region == "cut" then load = load + z.syy * z.area end end
    assert(load < 0, "the fill carries its weight")
  )");
}

// blocks() says how far each block has moved and whether it is gone: what mucking out needs.
TEST(Excavation, BlocksTellTheirLargestDisplacementAndWhetherTheyAreGone) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kStack) + R"(
    for b in blocks() do assert(b.max_displacement == 0 and b.excavated == nil) end
    solve{ ratio = 1e-6 }
    local largest = {}
    for g in gridpoints() do
      largest[g.block] = math.max(largest[g.block] or 0, math.sqrt(g.ux ^ 2 + g.uy ^ 2))
    end
    local moved = 0
    for b in blocks() do
      assert(b.max_displacement == largest[b.id], ("block %d: %.17g against %.17g"):format(
        b.id, b.max_displacement, largest[b.id] or -1))
      if b.max_displacement > 0 then moved = moved + 1 end
    end
    assert(moved > 0, "the blocks settle under gravity")
    excavate("cut")
    local gone = 0
    for b in blocks() do
      if b.region == "cut" then
        assert(b.excavated == 1, "the cut's block went in stage 1")
        gone = gone + 1
      else
        assert(b.excavated == nil, "block " .. b.id .. " is in place")
      end
    end
    assert(gone > 0)
  )");
}

// moved_blocks(d) gives what the loop over blocks() would pick for mucking out, no more, and
// refuses a distance that is not one.
TEST(Excavation, MovedBlocksAreTheBlocksInPlaceThatMovedFurther) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kStack) + R"(
    for b in moved_blocks(0) do error("nothing has moved yet: block " .. b.id) end
    solve{ ratio = 1e-6 }
    excavate("cut")
    solve{ ratio = 1e-6 }
    local function picked(d)
      local ids = {}
      for b in blocks() do
        if not b.excavated and b.max_displacement > d then ids[#ids + 1] = b.id end
      end
      return table.concat(ids, " ")
    end
    local largest = 0
    for b in blocks() do if not b.excavated then largest = math.max(largest, b.max_displacement) end end
    assert(largest > 0, "the rock settles")
    for _, d in ipairs({0, 0.5 * largest, largest}) do
      local ids = {}
      for b in moved_blocks(d) do
        assert(b.max_displacement > d and not b.excavated and b.vertices, "a block table as blocks() gives")
        ids[#ids + 1] = b.id
      end
      assert(table.concat(ids, " ") == picked(d), ("moved_blocks(%g): %s, blocks(): %s"):format(
        d, table.concat(ids, " "), picked(d)))
    end
    assert(picked(0) ~= "" and picked(largest) == "", "the two ends of the range")
    -- Mucking out while iterating: each block once, none excavated twice.
    local out = 0
    for b in moved_blocks(0) do excavate{ block = b.id }; out = out + 1 end
    assert(out > 0)
    for b in moved_blocks(0) do error("block " .. b.id .. " is out already") end
  )");
  const std::string error = error_of(interpreter, "for b in moved_blocks(-1) do end");
  EXPECT_TRUE(contains(error, "distance")) << error;
  EXPECT_TRUE(contains(error, "-1")) << error;
}

TEST(Excavation, ContactsWithAnExcavatedBlockGo) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kStack) + R"(
    region{ name = "upper", polygon = {{0, 2}, {4, 2}, {4, 4}, {0, 4}} }
    zone{ edge = 0.5 }
    assign{ material = "rock" }
    jassign{ material = "joint" }
    solve{ ratio = 1e-6 }
    local before = 0
    for c in contacts() do before = before + 1 end
    assert(before > 0)
    excavate("upper")
    cycle(1)
    for c in contacts() do error("a contact with the excavated block is left: at " .. c.x .. ", " .. c.y) end
  )");
}

TEST(Excavation, CracksCarryTheStage) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {-0.5, 0.5}, y = {0, 2} }
    region{ name = "notch", polygon = {{0.3, 1.4}, {0.5, 1.4}, {0.5, 1.6}, {0.3, 1.6}} }
    crackseed{ angle = 0, spacing = 10, origin = {0, 0.5}, material = "strength", after = "crack" }
    zone{ edge = 0.1 }
    material{ "rock", young = 1e9, poisson = 0.2 }
    material{ "strength", model = "mohr", young = 1e9, poisson = 0.2, cohesion = 1e6, friction = 30,
              tension = 1e4 }
    assign{ material = "rock" }
    joint_material{ "crack", kn = 1e10, ks = 1e10, friction = 30 }
    boundary{ side = "bottom", fix = "y" }
    excavate("notch")
    boundary{ side = "top", yvel = 1e-7 }
    cycle(3000)
    assert(info().cracks > 0, "the bar cracked")
    for c in cracks() do assert(c.stage == 1, "crack stage " .. c.stage) end
  )");
}

TEST(Excavation, TheNewSurfaceCanBeTouched) {
  // A glued region across a block, excavated: the rock above it must land on the rock below
  // (the region's outline was glued; excavate{} frees it on both sides), not fall through.
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {0, 10}, y = {0, 10} }
    region{ name = "gap", polygon = {{0, 3}, {10, 3}, {10, 5}, {0, 5}} }
    zone{ edge = 1 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.2 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 1e9, ks = 1e9, friction = 30 }
    jassign{ material = "j" }
    gravity{ 0, -9.81 }
    boundary{ side = "bottom", fix = "xy" }
    boundary{ side = "left", fix = "x" }
    boundary{ side = "right", fix = "x" }
    solve{ ratio = 1e-5 }
    excavate{ region = "gap" }
    cycle(8000)
    local top = gp_near(5, 10).uy
    assert(info().contacts > 0, "the upper rock touches the lower")
    assert(top < -1.99 and top > -2.01, ("the top moved %g m: it should drop the gap's 2 m"):format(top))
    -- The freed surface's gridpoints are the rock's own: gp_near picks the rock's side.
    assert(math.abs(gp_near(5, 5).uy - top) < 0.01, "the upper rock's underside moved with it")
    assert(math.abs(gp_near(5, 3).uy) < 0.01, "the lower rock's top stayed")
  )");
}

TEST(Excavation, AFallenBlockIsMuckedOut) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kStack) + R"(
    solve{ ratio = 1e-6 }
    local upper
    for z in zones() do if z.y > 2 then upper = z.block end end
    excavate{ block = upper }
    assert(stage() == 0, "mucking out is no stage")
    for z in zones() do
      if z.block == upper then assert(z.excavated == 1 and z.sxx == 0) else assert(not z.excavated) end
    end
    local ok, err = pcall(excavate, { block = upper })
    assert(not ok and err:find("block " .. upper .. " was excavated already"), err)
    ok, err = pcall(excavate, { block = 99 })
    assert(not ok and err:find("there is no block 99"), err)
    solve{ ratio = 1e-6 }
  )");
}

// loose_blocks{}: a block falling free is loose, one resting on its neighbour is not, one that
// slides off it is with a speed given; blocks glued to a held block are held with it.
TEST(Excavation, LooseBlocksAreThoseHeldByNothingOrMovingFast) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {0, 4}, y = {0, 2} }                  -- the base, held
    block{ x = {1, 3}, y = {2.5, 3.5} }              -- a block above it, not touching
    region{ name = "glued", polygon = {{0, 0}, {2, 0}, {2, 2}, {0, 2}} }  -- glued into the base
    zone{ edge = 0.5 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
    jassign{ material = "joint" }
    gravity{ 0, -9.81 }
    boundary{ side = "bottom", fix = "xy" }
    set{ mode = "dynamic", damping = "none" }
    local function loose(speed)
      local ids = {}
      for b in loose_blocks{ speed = speed } do ids[#ids + 1] = b.y > 2.2 and "above" or "base" end
      return table.concat(ids, " ")
    end
    cycle(10)
    assert(loose() == "above", "falling: " .. loose())
    set{ mode = "static", damping = "local" }
    solve{ ratio = 1e-6 }  -- it lands and settles on the base
    assert(loose() == "", "resting: " .. loose())
    -- on a slope steeper than its friction it slides off, pressed all the while
    gravity{ 9.81 * math.sin(math.rad(45)), -9.81 * math.cos(math.rad(45)) }
    set{ mode = "dynamic", damping = "none" }
    cycle(2000)
    assert(loose() == "", "sliding, no speed given: " .. loose())
    assert(loose(0.05) == "above", "sliding faster than 0.05 m/s: " .. loose(0.05))
  )");
  const std::string error = error_of(interpreter, "for b in loose_blocks{ speed = -1 } do end");
  EXPECT_TRUE(contains(error, "speed")) << error;
}

// While an excavation's load comes off, the rock it pushes on is held by it: not loose until the
// release ends (muck out would take a wall the dug rock still bears on).
TEST(Excavation, RockTheReleaseStillPushesOnIsNotLoose) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {0, 4}, y = {0, 2} }
    region{ name = "dig", polygon = {{-1, -1}, {5, -1}, {5, 1}, {-1, 1}} }
    zone{ edge = 0.5 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    insitu{ sxx = -1e6, syy = -1e6, szz = -1e6 }
    local function loose()
      local n = 0
      for _ in loose_blocks{} do n = n + 1 end
      return n
    end
    assert(loose() == 2, "held by nothing: " .. loose())  -- the two glued blocks, each listed
    excavate{ region = "dig", release = 1000 }
    cycle(10)
    assert(loose() == 0, "while the release runs: " .. loose())
    cycle(1000)
    assert(loose() == 1, "after it: " .. loose())
  )");
}

// A block mucked out while its step's load comes off takes its share of the load with it: its
// nodes are no longer cycled, and their last velocity would otherwise go on counting the share's
// work (the balance's error would be 98 % of its largest term here).
TEST(Excavation, MuckingOutDuringAReleaseTakesTheBlocksShare) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {-5, 5}, y = {-5, 5} }
    crack{ from = {-5, 1}, to = {5, 1} }            -- the top slab, the hole's top in it
    region{ name = "hole", polygon = {{-1, -1}, {1, -1}, {1, 2}, {-1, 2}} }
    zone{ edge = 0.5 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
    jassign{ material = "joint" }
    insitu{ sxx = -1e6, syy = -1e6 }
    boundary{ side = "bottom", fix = "xy" }
    boundary{ side = "left", fix = "x" } boundary{ side = "right", fix = "x" }
    set{ mode = "dynamic", damping = "none" }
    energy{ reset = true }
    excavate{ region = "hole", release = 2000 }
    cycle(200)
    local slab
    for b in blocks() do if b.centroid.y > 1 and not b.excavated then slab = b.id end end
    excavate{ block = slab }
    cycle(1500)
    local e = energy()
    assert(math.abs(e.relative_error) < 0.01, ("error %g of the largest term %g"):format(e.error, e.largest))
  )");
}

// A square cut by a vertical joint at x = 0, held on all four sides, in the in-situ stress (its
// vertical part `syy`) and solved; the region "dig" is the rock right of the joint between
// y = `from` and y = `to`.
const char* kJointedSquare = R"(
  local function jointed_square(from, to, syy)
    model{}
    block{ x = {-2, 2}, y = {-2, 2} }
    crack{ from = {0, -2}, to = {0, 2} }
    region{ name = "dig", polygon = {{0, from}, {3, from}, {3, to}, {0, to}} }
    zone{ edge = 0.5 }
    material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
    jassign{ material = "joint" }
    boundary{ side = "left", fix = "x" } boundary{ side = "right", fix = "x" }
    boundary{ side = "bottom", fix = "y" } boundary{ side = "top", fix = "y" }
    insitu{ sxx = -1e6, syy = syy, szz = -1e6 }
    solve{ ratio = 1e-6 }
  end
)";

// A dug block that pressed on the rock across a joint pushed it as its zones did: released over n
// cycles, that push comes off over them too, not at once. (The wall's speed ten cycles in is the
// share of the sudden release's that the load taken off by then gives: 0.7 %.)
TEST(Excavation, AReleaseTakesTheDugBlocksContactsOffGradually) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kJointedSquare) + R"(
    local function wall_speed(release)
      jointed_square(-3, 3, -1e6)
      set{ mode = "dynamic", damping = "none" }
      excavate{ region = "dig", release = release }
      cycle(10)
      local fastest = 0
      for g in gridpoints() do
        if g.x < 0.5 then fastest = math.max(fastest, math.abs(g.vx)) end
      end
      return fastest
    end
    local sudden, gradual = wall_speed(1), wall_speed(1000)
    assert(sudden > 0, "the wall moves once the block that held it is gone")
    assert(gradual < 0.02 * sudden, ("over 1000 cycles: %g m/s, at once: %g m/s"):format(gradual, sudden))
  )");
}

// With a release the contacts are found again at the excavation: what the dug blocks' contacts
// stored goes with them as dug out, and what a detection books itself is not booked again, so
// the balance is closed before any cycle (a quadrant of a jointed, glued square dug out: one
// above the joint's crossing, one below it).
TEST(Excavation, AReleaseBooksWhatTheContactsStoredOnce) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kJointedSquare) + R"(
    for _, dig in ipairs{ { 0, 3 }, { -3, 0 } } do
      jointed_square(dig[1], dig[2], -2e6)
      excavate{ region = "dig", release = 1000 }
      local e = energy()
      local what = ("digging y %g to %g: commands %g, error %g, dug out %g"):format(dig[1], dig[2], e.commands,
                                                                                  e.error, e.excavated)
      assert(math.abs(e.commands) < 1e-9 * e.largest and math.abs(e.error) < 1e-9 * e.largest, what)
      assert(e.excavated > 0, what)
    end
  )");
}

}  // namespace
}  // namespace edem::test
