// What a script did that is likely not what it meant: said once, with its line, never silently.
// Histories that follow their rock through an excavation; warnings for plausible mistakes; the
// script's declared --set keys.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_test.hpp"
#include "interp_test.hpp"

namespace edem {
namespace {

using test::Cli;
using test::contains;
using test::Outcome;
using test::slurp;

// Two blocks stacked under gravity; in the lower one a region "cut" (x 1 to 3, y 0 to 1).
const char* kStack = R"(model{ title = "stack" }
block{ x = {0, 4}, y = {0, 2} }
block{ x = {0, 4}, y = {2, 4} }
region{ name = "cut", polygon = {{1, 0}, {3, 0}, {3, 1}, {1, 1}} }
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
gravity{ 0, -9.81 }
boundary{ side = "bottom", fix = "xy" }
solve{ ratio = 1e-6 }
)";  // 12 lines

// The cells of one column of a history CSV, by the column's heading ("" for an empty cell).
std::vector<std::string> column(const std::string& csv, const std::string& heading) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> head;
  std::istringstream cells(line);
  for (std::string cell; std::getline(cells, cell, ',');) head.push_back(cell);
  size_t at = head.size();
  for (size_t i = 0; i < head.size(); ++i)
    if (head[i] == heading) at = i;
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::istringstream parts(line);
    for (std::string cell; std::getline(parts, cell, ',');) row.push_back(cell);
    values.push_back(at < row.size() ? row[at] : "");
  }
  return values;
}

size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// A history inside the excavated region: a warning at the excavate line, then empty cells, never
// a silent zero; the same after a checkpoint.
TEST_F(Cli, AHistoryWhoseRockIsExcavatedSaysSoAndRecordsNothingMore) {
  write("h.lua", std::string(kStack) + R"(history{ "uy", at = {2, 0.5}, every = 10, name = "inside" }
history{ "syy", at = {2, 0.4}, every = 10, name = "stress" }
history{ "cycle", every = 10 }
cycle(20)
excavate{ "cut" }
solve{ ratio = 1e-6 }
save("h.h5")
restore("h.h5")
cycle(20)
history_write("h.csv")
)");
  const Outcome r = edem("run h.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "h.lua:17: excavate: warning: history 'inside' records nothing more: its gridpoint at ("));
  EXPECT_TRUE(contains(r.err, "h.lua:17: excavate: warning: history 'stress' records nothing more: its zone at (2, 0.4) "
                              "was excavated at stage 1 (measure where rock stays)"));
  EXPECT_EQ(count(r.err, "records nothing more"), 2u);
  const std::string csv = slurp(dir_ / "h.csv");
  for (const char* name : {"inside [m]", "stress [Pa]"}) {
    const auto cells = column(csv, name);
    ASSERT_GT(cells.size(), 4u) << csv;
    EXPECT_NE(cells[0], "") << name << " recorded before the excavation";
    EXPECT_EQ(cells.back(), "") << name << " recorded after it, even after restore:\n" << csv;
  }
}

// A history on the excavation's outline goes on at the rock's gridpoint at the same place: the
// roof over the opening sags, and the history shows it.
TEST_F(Cli, AHistoryOnTheOutlineGoesOnInTheRockAcrossIt) {
  write("h.lua", std::string(kStack) + R"(history{ "uy", at = {2, 1}, every = 10, name = "roof" }
excavate{ "cut" }
solve{ ratio = 1e-6 }
history_write("h.csv")
print(("roof %.6g"):format(gp_near(2, 1.05).uy))
)");
  const Outcome r = edem("run h.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(contains(r.err, "warning"));
  const auto cells = column(slurp(dir_ / "h.csv"), "roof [m]");
  ASSERT_FALSE(cells.empty());
  EXPECT_LT(std::stod(cells.back()), -1e-4) << "the roof sags";
}

// Plausible mistakes run, each with one warning at its line: an angle in radians, a friction
// coefficient, a tensile in-situ stress, a history outside the model, nothing holding it under
// gravity. A warning said in a loop is said once.
TEST_F(Cli, PlausibleMistakesAreWarnedOnceAtTheirLine) {
  write("w.lua", R"(model{ title = "w" }
block{ x = {0, 4}, y = {0, 4} }
for _ = 1, 3 do jset{ angle = math.pi / 6, spacing = 2 } end
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 0.61 }
jassign{ material = "joint" }
gravity{ 0, -9.81 }
insitu{ sxx = 1e6, syy = -2e6 }
history{ "uy", at = {10, 10} }
cycle(10)
)");
  const Outcome r = edem("--quiet run w.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "w.lua:3: jset: warning: angle = 0.523599 is in degrees; it looks like radians (30 deg)"));
  EXPECT_EQ(count(r.err, "jset: warning"), 1u) << r.err;
  EXPECT_TRUE(contains(r.err, "w.lua:7: joint_material: warning: friction = 0.61 is an angle in degrees; as a "
                              "coefficient (tan phi) it would be 31.4 deg"));
  EXPECT_TRUE(contains(r.err, "w.lua:10: insitu: warning: sxx = 1e+06 Pa is tension (compression is negative)"));
  EXPECT_TRUE(contains(r.err, "w.lua:11: history: warning: at = (10, 10) lies outside the model's zones"));
  EXPECT_TRUE(contains(r.err, "w.lua:12: cycle: warning: gravity acts and no gridpoint is held"));
  EXPECT_EQ(count(r.err, "warning"), 5u) << r.err;
}

// Whole and half degrees, a friction of 0 and a compressive in-situ state are not doubted.
TEST_F(Cli, OrdinaryValuesAreNotDoubted) {
  write("ok.lua", std::string(kStack) + R"(jassign{ material = "joint" }
joint_material{ "smooth", kn = 1e10, ks = 1e10, friction = 0 }
joint_material{ "rough", kn = 1e10, ks = 1e10, friction = 1.5 }
insitu{ sxx = -1e6, syy = -2e6 }
)");
  const Outcome r = edem("--quiet run ok.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// settings{} declares the --set keys: a key it does not declare is an error naming the script
// line; values take the defaults' types; out_dir() is --out's folder.
TEST_F(Cli, ScriptsDeclareTheirSettings) {
  write("s.lua", R"(local s = settings{ depth = 158, bolts = "none", strict = false }
print(s.depth, math.type(s.depth), s.bolts, s.strict, out_dir())
)");
  Outcome r = edem("--quiet run s.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "158\tinteger\tnone\tfalse\t.\n");
  r = edem("--quiet --out o --set depth=212.5 --set bolts=1 --set strict=true run s.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "212.5\tfloat\t1\ttrue\to\n");
  r = edem("--quiet --set dept=2 run s.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "s.lua:1: settings: --set dept=2: this script has no setting 'dept' (did you mean "
                              "'depth'?) (its settings: bolts, depth, strict)"));
  r = edem("--quiet --set depth=deep run s.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "s.lua:1: settings: --set depth=deep: depth is a number (its default is), got \"deep\""));
  r = edem("--quiet --set strict=1 run s.lua");
  EXPECT_TRUE(contains(r.err, "s.lua:1: settings: --set strict=1: strict is true or false (its default is), got \"1\""));
}

}  // namespace
}  // namespace edem
