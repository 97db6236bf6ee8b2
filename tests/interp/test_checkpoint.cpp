// save() and restore(): a run saved mid-stage and restored goes on bit for bit as the run that
// was never stopped (cracks breaking, bolts loaded, contacts slipping, an excavation's release
// half done), on any thread count; what a restored model needs from the script is asked for. And
// field output taken during a run, which reads the same state, leaves the run as it was.
#include <lua.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "interp_test.hpp"

namespace edem::test {
namespace {

namespace fs = std::filesystem;

// A jointed block with potential cracks in weak rock, under gravity and in-situ stress, a
// rectangular opening excavated with its load released over 300 cycles, a bolt across its roof,
// a fn history, a built-in history and a callback.
const char* kScene = R"(
  model{ title = "checkpoint scene" }
  block{ x = {-6, 6}, y = {-6, 6} }
  jset{ angle = 35, spacing = 2.5, origin = {0.3, 0.2} }
  region{ name = "hole", polygon = {{-1.5, -1}, {1.5, -1}, {1.5, 1}, {-1.5, 1}} }
  crackseed{ angles = {110, 20}, spacing = 1.2, region = {{-4, -4}, {4, -4}, {4, 4}, {-4, 4}},
             material = "intact" }
  zone{ edge = 0.4, far = 1.2, near = { "hole" } }
  material{ "rock", density = 2500, young = 2e9, poisson = 0.25 }
  material{ "intact", model = "mohr", density = 2500, young = 2e9, poisson = 0.25, cohesion = 0.15e6,
            friction = 30, tension = 0.05e6 }
  assign{ material = "rock" }
  joint_material{ "joint", kn = 2e10, ks = 2e9, friction = 25 }
  jassign{ material = "joint" }
  gravity{ 0, -9.81 }
  insitu{ surface = 40, density = 2500, k0 = 0.5 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "right", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "top", stress = "insitu" }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
                 bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
  solve{ ratio = 1e-5, max_cycles = 3000 }
  excavate{ region = "hole", release = 300 }
  bolt{ from = {0.2, 1}, to = {0.6, 4}, segments = 12, material = "rebar" }
)";

// What the script registers in Lua, again after a restore.
const char* kFunctions = R"(
  calls = 0
  every(50, function() calls = calls + 1 end)
  history{ name = "roof", every = 10, fn = function() return gp_near(0, 1).uy end }
)";

// Every number a later cycle or a reader could see, in hexadecimal floating point.
const char* kDump = R"(
  local out = {}
  local function put(...) for _, v in ipairs({...}) do out[#out + 1] = type(v) == "number" and ("%a"):format(v) or tostring(v) end end
  local i = info()
  put(i.cycle, i.time, i.step, i.ratio, i.contacts, i.cracks, i.stage, calls)
  for g in gridpoints() do put(g.ux, g.uy, g.vx, g.vy, g.fx, g.fy) end
  for z in zones() do put(z.sxx, z.syy, z.sxy, z.szz, z.state) end
  for c in contacts() do put(c.fn, c.fs, c.un, c.us, c.slip, c.state, c.material) end
  for b in bolts() do
    put(b.head_force)
    for _, s in ipairs(b.segments) do put(s.force, s.strain, s.slip, s.plastic_slip, s.state) end
  end
  for c in cracks() do put(c.section, c.mode, c.cycle, c.stage, c.sxx) end
  dump = table.concat(out, " ")
  slipping, broken = 0, 0
  for c in contacts() do if c.slip > 0 then slipping = slipping + 1 end end
  for _ in cracks() do broken = broken + 1 end
)";

// The energy balance's terms, in hexadecimal floating point. (Summed over the batches a run is
// cut into, they may differ by round-off where a callback cuts it differently.)
const char* kEnergyDump = R"(
  local terms = {}
  local e = energy()
  for _, k in ipairs({"kinetic", "strain", "contact", "bolt", "gravity", "boundary", "release", "prestress", "commands",
                      "excavated", "plastic", "slip", "bond", "damping", "bolt_plastic", "error"}) do
    terms[#terms + 1] = ("%a"):format(e[k])
  end
  energy_dump = table.concat(terms, " ")
)";

class Checkpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("edem_checkpoint_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  static std::string global(Interpreter& interpreter, const char* name) {
    lua_getglobal(interpreter.state(), name);
    std::string value = lua_isstring(interpreter.state(), -1) ? lua_tostring(interpreter.state(), -1) : "";
    lua_pop(interpreter.state(), 1);
    return value;
  }

  static std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

TEST_F(Checkpoint, RestoredRunGoesOnBitForBitMidStage) {
  // Uninterrupted: 200 cycles into the release, then 400 more.
  Interpreter whole({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(whole, std::string(kScene) + kFunctions + "cycle(200)\ncycle(400)\n" + kDump + kEnergyDump +
                         "history_write('" + file("whole.csv") + "')");
  const std::string expected = global(whole, "dump");
  EXPECT_FALSE(global(whole, "energy_dump").empty());
  ASSERT_FALSE(expected.empty());
  // The scene must exercise what a checkpoint has to carry.
  EXPECT_GT(std::stoi(global(whole, "slipping")), 0) << "no contact has slipped";
  EXPECT_GT(std::stoi(global(whole, "broken")), 0) << "no crack broke";

  // Saved after 200 cycles (mid-release: cracks, bolt, contacts live), restored in a fresh
  // interpreter, on 1 and on 2 threads.
  {
    Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    expect_runs(first, std::string(kScene) + kFunctions + "cycle(200)\nsave('" + file("mid.h5") + "')\n" +
                           "assert(info().cracks > 0 and stage() == 1)");
  }
  for (int threads : {1, 2}) {
    Interpreter second({.quiet = true, .threads = threads, .stdlib_dirs = {}});
    const std::string csv = file("restored" + std::to_string(threads) + ".csv");
    expect_runs(second, "restore('" + file("mid.h5") + "')\n" + kFunctions +
                            "calls = 4  -- the callback ran at cycles 50, 100, 150, 200 before the save\n" +
                            "cycle(400)\n" + kDump + kEnergyDump + "history_write('" + csv + "')");
    EXPECT_TRUE(global(second, "dump") == expected) << "restored on " << threads << " thread(s) differs";
    EXPECT_EQ(global(second, "energy_dump"), global(whole, "energy_dump")) << "energy balance, " << threads;
    EXPECT_EQ(slurp(csv), slurp(file("whole.csv"))) << "histories differ";
  }
}

// A bar pulled apart through a cohesive crack (joint_material{ fracture_energy }) half way down its
// softening, then pushed back a little and saved: a bond's largest opening, which sets what it
// carries on the way back, is carried, so the restored run goes on bit for bit.
TEST_F(Checkpoint, RestoredRunWithACohesiveCrackSofteningGoesOnBitForBit) {
  const std::string bar = R"(
    block{ x = { -0.1, 0.1 }, y = { 0, 1 } }
    crackseed{ angle = 0, spacing = 10, origin = { 0, 0.5 }, material = "strength", after = "cohesive" }
    zone{ edge = 0.1 }
    material{ "rock", young = 415.52e6, poisson = 0.136, density = 1505 }
    material{ "strength", model = "mohr", young = 415.52e6, poisson = 0.136, cohesion = 0.143e6,
              friction = 34, tension = 0.0546e6 }
    assign{ material = "rock" }
    joint_material{ "cohesive", kn = 1880e6, ks = 1880e6, friction = 34, cohesion = 0.143e6,
                    tension = 0.0546e6, fracture_energy = 20 }
    judge{ every = 10 }
    boundary{ side = "bottom", fix = "y" }
    boundary{ polygon = { { -0.005, -0.005 }, { 0.005, -0.005 }, { 0.005, 0.005 }, { -0.005, 0.005 } }, fix = "x" }
    boundary{ side = "top", yvel = 1e-7 }
    calls = 0
  )";
  const char* softening = R"(
    softening = 0
    for c in contacts() do if c.state == "bonded" and c.fn > 1 and c.fn < 0.9 * 0.0546e6 * c.length then  -- tension
      softening = softening + 1 end end
  )";
  Interpreter whole({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  const std::string back = "cycle(4000)\nboundary{ side = 'top', yvel = -1e-7 }\ncycle(500)\n";
  expect_runs(whole, bar + back + "cycle(1000)\n" + kDump);
  const std::string expected = global(whole, "dump");
  ASSERT_FALSE(expected.empty());
  {
    // Counted after the save: a contacts() between cycle()s finds the contacts then, which can
    // change the run.
    Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    expect_runs(first, bar + back + "save('" + file("mid.h5") + "')\n" + softening);
    EXPECT_GT(std::stoi(global(first, "softening")), 0) << "no bond is softening at the save";
  }
  Interpreter second({.quiet = true, .threads = 2, .stdlib_dirs = {}});
  expect_runs(second, "restore('" + file("mid.h5") + "')\ncalls = 0\ncycle(1000)\n" + kDump);
  EXPECT_TRUE(global(second, "dump") == expected) << "restored differs";
}

// Joints on the seed's lab curve scaled to the prototype (closures of decimetres): how deep a
// contact is followed and its edge held (JointParams::curve_closure) is carried, so a detection
// after the restore (an excavation's, here) finds the contacts the uninterrupted run finds.
TEST_F(Checkpoint, RestoredSoftJointsGoOnBitForBitThroughAnExcavation) {
  std::string scene = kScene;
  const std::string linear = "joint_material{ \"joint\", kn = 2e10, ks = 2e9, friction = 25 }";
  const auto at = scene.find(linear);
  ASSERT_NE(at, std::string::npos);
  scene.replace(at, linear.size(),
                "joint_material{ \"joint\", kn_law = \"seed-cubic\", stress_scale = 17.86, closure_scale = 400, "
                "ks = 3.6e6, friction = 25 }");
  const auto zoning = scene.find("zone{ edge = 0.4");
  ASSERT_NE(zoning, std::string::npos);
  scene.insert(zoning, "region{ name = \"beside\", polygon = {{1.5, -1}, {3, -1}, {3, 1}, {1.5, 1}} }\n  ");
  scene += "calls = 0\n";
  const char* later = R"(
    excavate{ region = "beside", release = 0 }
    cycle(300)
  )";
  Interpreter whole({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(whole, scene + "cycle(600)\n" + later + kDump);
  const std::string expected = global(whole, "dump");
  ASSERT_FALSE(expected.empty());
  {
    Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    expect_runs(first, scene + "cycle(600)\nsave('" + file("soft.h5") + "')\n");
  }
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(second, "restore('" + file("soft.h5") + "')\ncalls = 0\n" + later + kDump);
  EXPECT_TRUE(global(second, "dump") == expected) << "restored differs";
}

// A strain-softening (ss) element driven past its peak and saved mid-softening: each zone's
// plastic shear strain e_ps, which sets its strength, is carried, so the restored run goes on bit
// for bit.
TEST_F(Checkpoint, RestoredStrainSofteningZonesGoOnBitForBit) {
  const std::string element = R"(
    block{ x = { 0, 1 }, y = { 0, 1 } }
    zone{ edge = 1 }
    material{ "rock", model = "ss", density = 2000, young = 1e9, poisson = 0.25, cohesion = 1e6,
              friction = 30, cohesion_table = { { 0, 1e6 }, { 0.01, 0.2e6 } } }
    assign{ material = "rock" }
    insitu{ sxx = -1e6, syy = -1e6, szz = -1e6 }
    for g in gridpoints() do
      local x, y = g.x, g.y
      boundary{ polygon = { { x - 0.01, y - 0.01 }, { x + 0.01, y - 0.01 }, { x + 0.01, y + 0.01 },
                            { x - 0.01, y + 0.01 } }, xvel = 0.5e-6 * x, yvel = -1e-6 * y }
    end
    cycle(7000)
  )";
  const char* eps = R"(
    local out = {}
    for z in zones() do out[#out + 1] = ("%a"):format(z.e_ps) end
    eps = table.concat(out, " ")
    softening = zone_at(0.3, 0.3).e_ps
  )";
  Interpreter whole({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(whole, element + "cycle(1000)\n" + kDump + eps);
  const std::string expected = global(whole, "dump");
  ASSERT_FALSE(expected.empty());
  {
    Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    expect_runs(first, element + "save('" + file("ss.h5") + "')\n" + eps);
    EXPECT_GT(std::stod(global(first, "softening")), 0.0) << "no zone is softening at the save";
  }
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(second, "restore('" + file("ss.h5") + "')\ncycle(1000)\n" + kDump + eps);
  EXPECT_TRUE(global(second, "dump") == expected) << "restored differs";
  EXPECT_EQ(global(second, "eps"), global(whole, "eps"));
}

// Output frames taken while the model cycles (every 7 cycles, so some right after sections broke,
// when the contacts are not current) leave the run as it would be without them: through the
// release's 300 cycles and 300 more, where the damping adapts and contacts are found again.
TEST_F(Checkpoint, OutputFramesDoNotChangeTheRun) {
  Interpreter plain({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(plain, std::string(kScene) + kFunctions + "cycle(600)\n" + kDump);
  Interpreter watched({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(watched, std::string(kScene) + kFunctions + "output{ file = '" + file("run.xdmf") +
                           "', every = 7 }\ncycle(600)\n" + kDump);
  EXPECT_FALSE(global(plain, "dump").empty());
  EXPECT_TRUE(global(watched, "dump") == global(plain, "dump")) << "output changed the run";
  EXPECT_TRUE(fs::exists(file("run.h5")));
}

// The same for a callback that reads the contacts (contacts(), contact_near) while cycling.
TEST_F(Checkpoint, ContactQueriesFromCallbacksDoNotChangeTheRun) {
  Interpreter plain({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(plain, std::string(kScene) + kFunctions + "cycle(600)\n" + kDump);
  Interpreter watched({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(watched, std::string(kScene) + kFunctions + R"(
    seen = 0
    every(7, function()
      for c in contacts() do seen = seen + 1 end
      local near = contact_near(0, 1)
    end)
    cycle(600)
  )" + kDump);
  EXPECT_GT(std::stoi(global(watched, "seen")), 0);
  EXPECT_TRUE(global(watched, "dump") == global(plain, "dump")) << "looking at the contacts changed the run";
}

// The same between cycle()s: sections broke in the last cycles of the first, so the model is to
// be prepared again; a view that prepares it to find the contacts must leave the next cycle
// restarting the damping as it would have (it did not: the run went on differently).
TEST_F(Checkpoint, ContactAndSectionQueriesBetweenCyclesDoNotChangeTheRun) {
  Interpreter plain({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(plain, std::string(kScene) + kFunctions + "cycle(150)\ncycle(450)\n" + kDump);
  for (const char* look : {"for c in contacts() do seen = seen + 1 end",
                           "for s in sections() do seen = seen + 1 end"}) {
    Interpreter watched({.quiet = true, .threads = 1, .stdlib_dirs = {}});
    expect_runs(watched, std::string(kScene) + kFunctions + "cycle(150)\nseen = 0\n" + look +
                             "\ncycle(450)\n" + kDump);
    EXPECT_GT(std::stoi(global(watched, "seen")), 0) << look;
    EXPECT_TRUE(global(watched, "dump") == global(plain, "dump"))
        << look << ": looking changed the run";
  }
}

TEST_F(Checkpoint, SavedFileNamesItsScriptAndVersion) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  const std::string script = file("make.lua");
  std::ofstream(script) << "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\nsave('" << file("a.h5") << "')\n";
  EXPECT_FALSE(interpreter.run_file(script, {}));
  const std::string head = slurp(file("a.h5")).substr(0, 40);
  EXPECT_TRUE(std::regex_search(
      head, std::regex("^EDEM checkpoint\nschema [1-9][0-9]*\nversion " EDEM_VERSION "\n")))
      << head;
  Interpreter reader({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(reader, "restore('" + file("a.h5") + "')\nassert(info().zones > 0)");
}

TEST_F(Checkpoint, FnHistoryMustBeGivenAgain) {
  Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(first, std::string(kScene) + kFunctions + "cycle(20)\nsave('" + file("h.h5") + "')");
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  const std::string error = error_of(second, "restore('" + file("h.h5") + "')\ncycle(10)");
  EXPECT_TRUE(contains(error, "test.lua:2: cycle: history 'roof' was restored without its function"));
  Interpreter third({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  EXPECT_TRUE(contains(error_of(third, "restore('" + file("h.h5") + "')\n"
                                       "history{ name = 'roof', every = 5, fn = function() return 0 end }"),
                       "was recorded every 10 cycles before it was saved; give every = 10"));
}

TEST_F(Checkpoint, JudgeCriterionMustBeGivenAgain) {
  Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(first, std::string(kScene) + "judge{ every = 10, criterion = function(s) return nil end }\n"
                                           "cycle(20)\nsave('" + file("j.h5") + "')");
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  EXPECT_TRUE(contains(error_of(second, "restore('" + file("j.h5") + "')\ncycle(10)"),
                       "the restored judge{} had a criterion function"));
  Interpreter third({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(third, "restore('" + file("j.h5") + "')\njudge{ every = 10 }\ncycle(10)");
}

TEST_F(Checkpoint, RestoredGeometryIsFixed) {
  Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(first, "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\nsave('" + file("g.h5") + "')");
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  EXPECT_TRUE(contains(error_of(second, "restore('" + file("g.h5") + "')\njset{ angle = 10, spacing = 0.3 }"),
                       "test.lua:2: jset: the geometry of a model restored from a checkpoint cannot change"));
}

// save() from an every() callback, as periodic checkpoints of one long cycle(): the file holds the
// state at that cycle, and a restore goes on from there bit for bit as the uninterrupted run. (The
// runs compared have the same callbacks: where a callback ran at a cycle whose model then changed,
// the energy balance books the change of kinetic energy as the commands', not the damping's.)
TEST_F(Checkpoint, SavedFromACallbackGoesOnBitForBit) {
  const auto watcher = [](const std::string& action) {
    return "start = info().cycle\nevery(10, function(c)\n  if not saved_at and c >= start + 200 then " + action +
           " saved_at, calls_then = c, calls end\nend)\n";
  };
  Interpreter whole({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(whole, std::string(kScene) + kFunctions + watcher("") + "cycle(600)\n" + kDump + kEnergyDump +
                         "history_write('" + file("whole.csv") + "')");
  Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(first, std::string(kScene) + kFunctions + watcher("save('" + file("callback.h5") + "')") + "cycle(600)");
  ASSERT_FALSE(global(first, "saved_at").empty());
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(second, "restore('" + file("callback.h5") + "')\n" + kFunctions + "every(10, function() end)\ncalls = " +
                          global(first, "calls_then") + "\nassert(info().cycle == " + global(first, "saved_at") +
                          ")\ncycle(" + global(whole, "start") + " + 600 - info().cycle)\n" + kDump + kEnergyDump +
                          "history_write('" + file("callback.csv") + "')");
  EXPECT_TRUE(global(second, "dump") == global(whole, "dump")) << "the run saved from a callback differs";
  EXPECT_EQ(global(second, "energy_dump"), global(whole, "energy_dump"));
  EXPECT_EQ(slurp(file("callback.csv")), slurp(file("whole.csv"))) << "histories differ";
}

TEST_F(Checkpoint, BadFileKeepsTheCurrentModel) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  std::ofstream(file("junk.h5")) << "not a checkpoint";
  expect_runs(interpreter, "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\n"
                           "local ok, e = pcall(restore, '" + file("junk.h5") + "')\n"
                           "assert(not ok and e:find('is not an EDEM checkpoint'), e)\n"
                           "assert(info().zones > 0)");
}

TEST_F(Checkpoint, PrepassResultIsKept) {
  Interpreter first({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  const char* model = R"(
    block{ x = {-10, 10}, y = {-10, 10} }
    region{ name = "hole", polygon = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}} }
    zone{ edge = 1 }
    material{ "rock", model = "mohr", density = 2500, young = 1e9, poisson = 0.25, cohesion = 0.2e6, friction = 30 }
    assign{ material = "rock" }
    gravity{ 0, -9.81 }
    insitu{ surface = 60, density = 2500, k0 = 0.8 }
    boundary{ side = "left", fix = "x" } boundary{ side = "right", fix = "x" }
    boundary{ side = "bottom", fix = "y" } boundary{ side = "top", stress = "insitu" }
  )";
  const char* summary = R"(
    local p = prepass_result()
    local yielded = 0
    for _, z in ipairs(p.zones) do if z.state ~= "none" then yielded = yielded + 1 end end
    summary = ("%d %d %a %a"):format(#p.zones, yielded, p.zones[7].s1, p.gridpoints[5].ux)
  )";
  expect_runs(first, std::string(model) + "assert(prepass_result() == nil)\nprepass{ stages = {'hole'}, steps = 2 }\n" +
                         summary + "save('" + file("p.h5") + "')");
  Interpreter second({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  expect_runs(second, "restore('" + file("p.h5") + "')\n" + summary);
  EXPECT_FALSE(global(first, "summary").empty());
  EXPECT_EQ(global(second, "summary"), global(first, "summary"));
}

}  // namespace
}  // namespace edem::test
