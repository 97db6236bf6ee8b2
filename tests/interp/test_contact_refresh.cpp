// Contacts are found again only where blocks move: a block falling far from the others has its
// own gridpoints searched, not the whole model's, and still lands on what it falls onto.
#include "interp_test.hpp"

namespace edem::test {
namespace {

// A fixed base, a resting stack of two blocks at its left, and a 1 m block held 3 m above its
// right, which falls once cycling starts (dynamic mode, gravity).
const char* kFall = R"(
  model{ title = "a block falls beside a stack" }
  block{ x = {-10, 10}, y = {-1, 0} }
  block{ x = {-9, -5}, y = {0, 1} }
  block{ x = {-9, -5}, y = {1, 2} }
  block{ x = {4, 5}, y = {3, 4} }
  zone{ edge = 0.25 }
  material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
  jassign{ material = "joint" }
  boundary{ polygon = {{-10.1, -1.1}, {10.1, -1.1}, {10.1, -0.01}, {-10.1, -0.01}}, fix = "xy" }
  gravity{ 0, -9.81 }
  set{ mode = "dynamic" }
  local falling = gp_near(4.5, 4).block
  -- Its boundary gridpoints: the only ones searched while it falls clear of everything.
  local boundary = 0
  for g in gridpoints() do
    local on_edge = g.x == 4 or g.x == 5 or g.y == 3 or g.y == 4
    if g.block == falling and on_edge then boundary = boundary + 1 end
  end
)";

TEST(ContactRefresh, AFallingBlockAloneIsSearchedAgainWhileItIsClearOfTheOthers) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kFall) + R"(
    cycle(1)
    local everything = info().contact_searches  -- the first detection: every boundary gridpoint
    assert(everything > 10 * boundary, "the model has " .. everything .. " boundary gridpoints")
    -- Fall 2 m: its base is then 1 m above the base block's top.
    while gp_near(4.5, 3).uy > -2 do cycle(10) end
    local searched = info().contact_searches - everything
    assert(searched % boundary == 0,
           ("%d gridpoints searched: not a whole number of times the falling block's %d"):format(searched, boundary))
    -- Found again each time it fell an eighth of the smallest reach (0.125 m / 8), or sooner:
    -- over 2 m, at least 128 times; a search of everything each time would be 128 x the model.
    assert(searched // boundary >= 128, ("searched again only %d times"):format(searched // boundary))
  )");
}

TEST(ContactRefresh, TheFallingBlockLandsOnTheBaseWithNoContactFoundLate) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kFall) + R"(
    while gp_near(4.5, 3).uy > -2.9 do cycle(10) end
    set{ mode = "static" }
    reset{ "velocity" }
    solve{ ratio = 1e-6, max_cycles = 50000 }
    -- At rest on the base: fallen its 3 m, less than a micrometre (its weight over kn) aside.
    local fell = -gp_near(4.5, 3).uy
    assert(math.abs(fell - 3) < 1e-4, ("it fell %.7f m"):format(fell))
    assert(info().late_contacts == 0, info().late_contacts .. " contacts found late")
    -- The stack never moved enough to be searched again on its own.
    assert(math.abs(gp_near(-7, 2).uy) < 1e-4, "the stack moved " .. gp_near(-7, 2).uy)
  )");
}

// A block on another, their joint given 1 MPa (closed 0.1 m), is slid 6 cm right, its corner past
// the lower block's, then 20 cm down: its corner lies beside the lower block's side, 6 cm out. Its
// contact, found again on that side, must not keep the closure it had on the top face: 4 cm of
// it would be left, and the side would push a corner that is nowhere near it.
TEST(ContactRefresh, ACornerSlidOffALoadedFaceIsNotPushedByTheSideItDropsBeside) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kDrive) + R"lua(
    model{ title = "a loaded corner slid off a face" }
    block{ x = {-1, 0}, y = {-1, 0} }
    block{ x = {-1, 0}, y = {0, 1} }
    zone{ edge = 1 }
    material{ "rock", density = 2600, young = 1e12, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 1e7, ks = 1e7, friction = 0 }
    jassign{ material = "j" }
    local lower, upper = gp_near(-0.5, -0.9).block, gp_near(-0.5, 0.9).block
    boundary{ polygon = {{-1.1, -1.1}, {0.1, -1.1}, {0.1, -0.9}, {-1.1, -0.9}}, fix = "xy" }
    insitu{ sxx = 0, syy = -1e6, szz = 0 }
    cycle(1)
    local function corner_contacts()
      local found = {}
      for c in contacts() do
        if c.block == upper and c.other == lower and c.x > -0.01 then found[#found + 1] = c end
      end
      return found
    end
    local given = corner_contacts()
    assert(#given == 1 and given[1].fn < 0 and math.abs(given[1].un + 0.1) < 1e-3,
           "the corner is not pressed in by the given stress")
    -- The upper block moved as a rigid body by its gridpoints above its base (those on its base
    -- lie on the lower block's and would be selected with them).
    local driven = {}
    for g in gridpoints() do if g.block == upper and g.y > 0.25 then driven[#driven + 1] = g end end
    while gp_near(0, 1).ux < 0.06 do drive(driven, 1e-2, 0); cycle(1) end
    while gp_near(0, 1).uy > -0.2 do drive(driven, 0, -1e-2); cycle(1) end
    drive(driven, 0, 0)
    cycle(20)
    for _, c in ipairs(corner_contacts()) do
      assert(c.x > 0.03 and c.y < -0.1, ("the corner is at (%g, %g), not beside the side"):format(c.x, c.y))
      assert(c.fn == 0, ("the side pushes the corner %g m out of it with %g N/m (closure %g m)"):format(
                         c.x, c.fn, -c.un))
    end
  )lua");
}

// A square pressed 8 cm into the top face of a fixed 28 deg wedge is slid left off its tip. Past
// the wedge's lower face its corner is beside the wedge, not in it: the top face, whose line runs
// on past the apex, must not push it, and no contact of it may be found already pressed in.
TEST(ContactRefresh, ACornerSlidPastAThinTipIsFreeOnceOutsideIt) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kDrive) + R"lua(
    model{ title = "a corner slid past a thin tip" }
    local slope = math.tan(math.rad(28))
    block{ {0, 0}, {3, -3 * slope}, {3, 0} }
    block{ x = {1.5, 2.5}, y = {0, 1} }
    zone{ edge = 0.5 }
    material{ "rock", density = 2600, young = 1e12, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 1e7, ks = 1e7, friction = 0 }
    jassign{ material = "j" }
    local upper = gp_near(2, 0.9).block
    boundary{ polygon = {{2.9, -0.01}, {3.1, -0.01}, {3.1, -3 * slope - 0.1}, {2.9, -3 * slope - 0.1}},
              fix = "xy" }
    cycle(1)
    -- The square moved as a rigid body by its outer gridpoints above its base.
    local driven = {}
    for g in gridpoints() do
      if g.block == upper and g.y > 0.25 and (g.x < 1.51 or g.x > 2.49 or g.y > 0.99) then
        driven[#driven + 1] = g
      end
    end
    local function corner()
      local g = gp_near(1.5, 1)
      return 1.5 + g.ux, g.uy
    end
    drive(driven, 0, -1e-4)
    while select(2, corner()) > -0.08 do cycle(1) end
    drive(driven, -1e-4, 0)
    local checked = 0
    while corner() > -0.15 do
      cycle(10)
      local x, y = corner()
      if x < 0 or y < -slope * x - 1e-3 then
        for c in contacts() do
          if c.block == upper and math.abs(c.x - x) < 0.02 and math.abs(c.y - y) < 0.02 then
            assert(c.fn == 0, ("the corner at (%.4f, %.4f), outside the wedge, is pushed with %g N/m"):format(
                              x, y, c.fn))
          end
        end
        checked = checked + 1
      end
    end
    assert(checked > 200, "the corner was outside the wedge at only " .. checked .. " checks")
    assert(info().late_contacts == 0, info().late_contacts .. " contacts found late")
  )lua");
}

}  // namespace
}  // namespace edem::test
