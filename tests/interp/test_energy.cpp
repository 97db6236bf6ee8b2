// energy(): the energy balance from a script; its terms as histories; what commands between
// cycles change (reset{}, excavate{}) booked as theirs; the same bits on any thread count; each
// contact's own balance adding up to the contacts' part; contacts that start anew on another face
// named.
#include <lua.hpp>

#include "interp_test.hpp"

namespace edem::test {
namespace {

// Two blocks on a fixed base, the upper one falling onto it under gravity, in dynamic mode.
const char* kDrop = R"(
  block{ x = {0, 1}, y = {0, 1} }
  block{ x = {0, 1}, y = {1.05, 2.05} }
  zone{ edge = 0.25 }
  material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "j", kn = 1e10, ks = 1e10, friction = 30 }
  jassign{ material = "j" }
  boundary{ side = "bottom", fix = "xy" }
  gravity{ 0, -9.81 }
  set{ mode = "dynamic", damping = "none" }
)";

TEST(Energy, BeforeAnyCycleEveryTermIsZero) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, std::string(kDrop) + R"(
    local e = energy()
    for k, v in pairs(e) do assert(v == 0, k .. " = " .. v) end
  )");
}

TEST(Energy, AFallingBlockBalancesAndItsTermsAreHistories) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, std::string(kDrop) + R"(
    history{ "energy.kinetic", every = 10 }
    history{ "energy.gravity", every = 10 }
    history{ "energy.error", every = 10 }
    while info().time < 0.15 do cycle(100) end  -- landed at 0.1 s, bouncing back up
    local e = energy()
    assert(e.largest > 300, "largest term " .. e.largest .. " J/m")
    assert(math.abs(e.relative_error) < 1e-2, "error " .. e.relative_error)
    assert(e.largest >= e.gravity and math.abs(e.contact_error + e.zone_error + e.bolt_error - e.error) < 1e-9 * e.largest)
    local csv = os.tmpname()
    history_write(csv)
    local header, last
    for line in io.lines(csv) do header = header or line; last = line end
    os.remove(csv)
    assert(header == "cycle,energy.kinetic [J/m],energy.gravity [J/m],energy.error [J/m]", header)
    local v = {}
    for field in last:gmatch("[^,]+") do v[#v + 1] = tonumber(field) end
    assert(v[1] == info().cycle and v[2] == e.kinetic and v[3] == e.gravity and v[4] == e.error, last)
  )");
}

TEST(Energy, ResetVelocityIsACommandsChangeAndExcavationTakesTheRockAway) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, std::string(kDrop) + R"(
    cycle(400)
    local moving = energy()
    assert(moving.kinetic > 0)
    reset{ "velocity" }
    local e = energy()
    -- the kinetic energy the reset took is the commands', not an error
    assert(math.abs(e.commands + moving.kinetic) < 1e-9 * moving.kinetic, e.commands .. " " .. moving.kinetic)
    assert(math.abs(e.error - moving.error) < 1e-9 * moving.largest, e.error .. " " .. moving.error)
    cycle(100)
    local before = energy()
    excavate{ block = 2 }  -- mucked out
    local dug = energy()
    assert(dug.excavated > 0, "excavated " .. dug.excavated)
    assert(math.abs(dug.error - before.error) < 1e-9 * before.largest, dug.error .. " " .. before.error)
    cycle(100)
    assert(math.abs(energy().relative_error) < 1e-2)
  )");
}

TEST(Energy, ResetAndContactBooksFromACallbackAreRefused) {
  const std::pair<const char*, const char*> calls[] = {
      {"energy{ reset = true }", "energy{ reset = true } cannot be given while cycling"},
      {"energy{ by_contact = true }", "energy{ by_contact = ... } cannot be given while cycling"}};
  for (const auto& [call, message] : calls) {
    Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    const std::string error =
        error_of(interpreter, std::string(kDrop) + "every(10, function() " + call + " end)\ncycle(20)\n");
    EXPECT_TRUE(contains(error, message)) << error;
  }
}

// With energy{ by_contact = true } each contact keeps its own balance: through a landing and a
// bounce, with contacts made, pressed and parted, theirs add up to the contacts' part of the error.
TEST(Energy, TheContactsOwnBalancesAddUpToTheirPartOfTheError) {
  Interpreter interpreter({.quiet = true, .threads = 2, .stdlib_dirs = {}});
  expect_runs(interpreter, std::string(kDrop) + R"(
    for c in contacts() do assert(c.energy_made == nil) end
    energy{ reset = true, by_contact = true }
    local function check()
      local sum, n = 0, 0
      for c in contacts() do sum, n = sum + c.energy_made, n + 1 end
      local e = energy()
      assert(n > 0)
      assert(math.abs(sum - e.contact_error) < 1e-9 * e.largest,
             ("contacts' own %.9g, the balance's %.9g J/m"):format(sum, e.contact_error))
    end
    while info().time < 0.15 do cycle(100); check() end  -- landed at 0.1 s, bouncing back up
    energy{ by_contact = false }
    for c in contacts() do assert(c.energy_made == nil) end
  )");
}

// A block pressed through a soft joint into a slab 0.1 m thick: once its gridpoints are deeper in
// the slab than half its thickness, a detection finds them nearer the slab's underside and their
// contacts start anew there, what their springs held on the top face gone. The balance names what
// those restarts made (negative: lost) as `restarted`, nearly all of the contacts' error then.
TEST(Energy, ContactsFoundOnAnotherFaceAreNamedInTheBalance) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(interpreter, R"(
    block{ x = {0, 1}, y = {-1, 0} }
    block{ x = {0, 1}, y = {0, 0.1} }
    block{ x = {0.2, 0.8}, y = {0.1, 0.7} }
    zone{ edge = 0.1 }
    material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "j", kn = 1e7, ks = 1e7, friction = 30 }
    jassign{ material = "j" }
    local slab, block = gp_near(0.5, 0.05).block, gp_near(0.5, 0.7).block
    boundary{ side = "bottom", fix = "xy" }
    set{ overlap = 0.3 }
    boundary{ polygon = {{0.1, 0.65}, {0.9, 0.65}, {0.9, 0.75}, {0.1, 0.75}}, xvel = 0, yvel = -2e-5 }
    local function underside()  -- the block's gridpoints in contact with the slab's underside
      local n = 0
      for c in contacts() do if c.block == block and c.other == slab and c.normal.y < -0.5 then n = n + 1 end end
      return n
    end
    cycle(2500)
    local before = energy()
    assert(underside() == 0, ("%d gridpoints on the underside already"):format(underside()))
    cycle(1500)
    local after = energy()
    assert(underside() > 0, "no gridpoint was handed to the slab's underside")
    local restarted, made = after.restarted - before.restarted, after.contact_error - before.contact_error
    assert(restarted < -1e3, ("restarted %g J/m"):format(restarted))
    assert(math.abs(made - restarted) < 0.01 * math.abs(restarted),
           ("the contacts made %g J/m, %g of it restarting"):format(made, restarted))
  )");
}

TEST(Energy, TheSameBitsOnAnyThreadCount) {
  std::string dumps[2];
  for (int threads : {1, 2}) {
    Interpreter interpreter({.quiet = true, .threads = threads, .stdlib_dirs = {}});
    expect_runs(interpreter, std::string(kDrop) + R"(
      cycle(3000)
      local e, out = energy(), {}
      for _, k in ipairs({"kinetic", "strain", "contact", "gravity", "slip", "error"}) do out[#out + 1] = ("%a"):format(e[k]) end
      dump = table.concat(out, " ")
    )");
    lua_getglobal(interpreter.state(), "dump");
    dumps[threads - 1] = lua_tostring(interpreter.state(), -1);
  }
  EXPECT_EQ(dumps[0], dumps[1]);
}

}  // namespace
}  // namespace edem::test
