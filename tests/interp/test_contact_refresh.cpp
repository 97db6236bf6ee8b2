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

}  // namespace
}  // namespace edem::test
