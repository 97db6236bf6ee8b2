// judge{ most = n }: at most n sections break at a judgment, those furthest past the built-in
// criteria first; the rest wait for the next judgment. judge{ radius = r }: a section's stress is
// fitted to its two blocks' zones within r of its point as well. judge{ at = "equilibrium" }:
// sections judged only on the states a solve brings to its ratio, in rounds until none breaks;
// judge{ neighbours }: of touching sections that fail, the worst breaks and the others wait.
// sections(): those whose rock is dug out are gone; each section's overstress.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "interp_test.hpp"
#include "model/model.hpp"

namespace edem {
namespace {

using test::expect_runs;

// The seed's tension bar (test::seed_bar) with potential cracks every 0.25 m, in vertical tension
// above its sigma_t = 0.0546 MPa: 0.06 MPa where x < 0 and 0.08 MPa where x > 0, so every section
// fails at the first judgment.
const char* const kStep = R"(
insitu{ syy = 0.06e6, szz = 0.02e6 }
insitu{ syy = 0.08e6, szz = 0.02e6, region = {{0, -1}, {1, -1}, {1, 2}, {0, 2}} }
)";

std::string bar() {
  return test::seed_bar("0.25") + kStep;
}

struct Broken {
  int count = 0, right = 0;  // cracks, and those whose section lies at x > 0
};

Broken broken(Interpreter& interpreter) {
  const Model& model = interpreter.context().model();
  Broken b;
  for (int id = 0; id < model.crack_count(); ++id) {
    ++b.count;
    b.right += model.crack(id).position.x > 0.0;
  }
  return b;
}

TEST(JudgeMost, AllThatFailBreakAtOnceByDefault) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() + "judge{ every = 10 }\ncycle(10)");
  const int sections = interpreter.context().model().info().sections;
  EXPECT_GT(sections, 4);
  EXPECT_EQ(broken(interpreter).count, sections);
}

// The cracks a judgment makes are contacts at once: info() counts them as contacts() does, not
// as last found (none: the intact sections are bonded); pairs(info()) lists that count too.
TEST(JudgeMost, InfoCountsTheContactsAJudgmentMakes) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() +
                               "judge{ every = 10 }\ncycle(10)\n"
                               "local n = 0\nfor c in contacts() do n = n + 1 end\n"
                               "assert(info().cracks > 4, 'the sections broke')\n"
                               "assert(n > 0 and info().contacts == n, ('info %d, contacts() %d'):format(info().contacts, n))\n"
                               "local listed\nfor key, value in pairs(info()) do if key == 'contacts' then listed = value end end\n"
                               "assert(listed ~= nil and listed > 0 and listed == info().contacts, tostring(listed))");
}

// A cohesive crack (its joint material softens) judged past its strength starts at its law's
// peak: kStep's 0.06 and 0.08 MPa, past sigma_t = 0.0546 MPa, give it 0.0546 MPa at an opening of
// sigma_t / kn, not the section's stress at an opening past the peak (damage it would keep).
TEST(JudgeMost, ACohesiveCrackStartsAtItsPeakNotPastIt) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() +
                               "joint_material{ 'crack', kn = 1880e6, ks = 1880e6, friction = 31.2, "
                               "cohesion = 0.143e6, tension = 0.0546e6, fracture_energy = 20 }\n"
                               "judge{ every = 10 }\ncycle(10)\n"
                               "local n, peak = 0, 0.0546e6\n"
                               "for c in contacts() do\n"
                               "  n = n + 1\n"
                               "  assert(c.state == 'bonded', c.state)\n"
                               "  assert(math.abs(c.sn - peak) <= 1e-9 * peak, ('sn %.9g'):format(c.sn))\n"
                               "  assert(math.abs(c.un - peak / 1880e6) <= 1e-9 * peak / 1880e6, ('un %.9g'):format(c.un))\n"
                               "end\n"
                               "assert(n > 0 and info().cracks > 4, 'the sections broke')");
}

TEST(JudgeMost, AtMostThatManyBreakAtAJudgmentTheFurthestPastFirst) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() + "judge{ every = 10, most = 2 }\ncycle(10)");
  Broken b = broken(interpreter);
  EXPECT_EQ(b.count, 2);
  EXPECT_EQ(b.right, 2);  // the sections in 0.08 MPa go before those in 0.06 MPa
  expect_runs(interpreter, "cycle(10)");
  b = broken(interpreter);
  EXPECT_EQ(b.count, 4);
  EXPECT_GE(b.right, 3);
}

TEST(JudgeMost, AppliesToAUsersCriterionToo) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() +
                               "judge{ every = 10, most = 1, criterion = function(s) return \"shear\" end }\n"
                               "cycle(10)");
  const Broken b = broken(interpreter);
  EXPECT_EQ(b.count, 1);
  EXPECT_EQ(b.right, 1);
}

TEST(JudgeMost, ACheckpointKeepsIt) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("edem_judge_most_" + std::to_string(::getpid()) + ".h5");
  Interpreter first;
  first.context().quiet = true;
  expect_runs(first, bar() + "judge{ every = 10, most = 1 }\nsave('" + file.string() + "')");
  Interpreter second;
  second.context().quiet = true;
  expect_runs(second, "restore('" + file.string() + "')\ncycle(10)");
  std::filesystem::remove(file);
  EXPECT_EQ(broken(second).count, 1);
}

TEST(JudgeMost, ANegativeCountIsAnErrorNamingIt) {
  EXPECT_TRUE(test::contains(test::error_of("judge{ most = -1 }"), "most"));
}

// judge{ radius }: sections of the bar (zones of 0.05 m, cracks at y = 0.25, 0.5 and 0.75) in the
// stress insitu{} sets, before any cycle; `field` gives it.
std::vector<SectionView> views(const std::string& field, const std::string& judge) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, test::seed_bar("0.25") + field + judge);
  const Model& model = interpreter.context().model();
  std::vector<SectionView> v;
  for (int id = 0; id < model.section_count(); ++id) v.push_back(model.section(id));
  return v;
}

TEST(JudgeRadius, ARadiusShorterThanTheZonesIsTheSeedsFourZonesToTheBit) {
  const std::vector<SectionView> seeds = views(kStep, "judge{}");
  const std::vector<SectionView> short_radius = views(kStep, "judge{ radius = 0.01 }");
  ASSERT_EQ(seeds.size(), short_radius.size());
  for (size_t i = 0; i < seeds.size(); ++i) {
    EXPECT_EQ(seeds[i].sxx, short_radius[i].sxx);
    EXPECT_EQ(seeds[i].syy, short_radius[i].syy);
    EXPECT_EQ(seeds[i].sxy, short_radius[i].sxy);
  }
}

// kStep: syy = 0.06 MPa where x < 0, 0.08 MPa where x > 0. The sections at x = -0.0875 m see only
// the left's through their four nearest zones a side, and the right's too when the radius reaches
// past x = 0: the fitted field then slopes, and at the point, near the fitted zones' left end, it
// is more than 1 % off 0.06 MPa (below it: the least-squares line through a step).
TEST(JudgeRadius, AStepInTheStressIsSeenOutToTheRadius) {
  for (const auto& [judge, seen] :
       {std::pair{"judge{}", false}, std::pair{"judge{ radius = 0.1 }", true}}) {
    int left = 0;
    for (const SectionView& v : views(kStep, judge)) {
      if (v.position.x > -0.08) continue;
      ++left;
      if (seen)
        EXPECT_GT(std::abs(v.syy - 0.06e6), 0.01 * 0.06e6) << judge << " at y = " << v.position.y;
      else
        EXPECT_NEAR(v.syy, 0.06e6, 1e-9 * 0.06e6) << judge << " at y = " << v.position.y;
    }
    EXPECT_EQ(left, 3);  // one on each crack
  }
}

// syy = 0.06 MPa but 0.08 MPa above the crack at y = 0.75. Zones just above it lie within 0.3 m of
// the sections at y = 0.5, but in another block: those sections see 0.06 MPa alone; the
// sections at y = 0.75, whose upper block it is, see both.
TEST(JudgeRadius, OnlyTheSectionsOwnTwoBlocksAreAveraged) {
  const std::string field = R"(
insitu{ syy = 0.06e6, szz = 0.02e6 }
insitu{ syy = 0.08e6, szz = 0.02e6, region = {{-1, 0.75}, {1, 0.75}, {1, 2}, {-1, 2}} }
)";
  int middle = 0, upper = 0;
  for (const SectionView& v : views(field, "judge{ radius = 0.3 }")) {
    if (std::abs(v.position.y - 0.5) < 1e-9) {
      ++middle;
      EXPECT_NEAR(v.syy, 0.06e6, 1e-9 * 0.06e6) << "at x = " << v.position.x;
    }
    if (std::abs(v.position.y - 0.75) < 1e-9) {
      ++upper;
      EXPECT_GT(v.syy, 0.065e6) << "at x = " << v.position.x;
      EXPECT_LT(v.syy, 0.075e6) << "at x = " << v.position.x;
    }
  }
  EXPECT_EQ(middle, 8);  // the zones along a crack are 0.025 m
  EXPECT_EQ(upper, 8);
}

// sxx = 0.01 MPa + 0.2 MPa/m * y, syy = 0.06 MPa: a linear field in equilibrium without a body
// force. The fit is a linear equilibrium field, so at any radius it gives the field at each
// section's point; only the zones it is fitted to change.
TEST(JudgeRadius, ALinearEquilibriumFieldIsFittedExactlyAtAnyRadius) {
  const std::string field =
      "insitu{ sxx = 0.01e6, syy = 0.06e6, szz = 0.02e6, ygrad = {0.2e6, 0, 0} }\n";
  for (const char* judge : {"judge{}", "judge{ radius = 0.1 }", "judge{ radius = 0.3 }"}) {
    const std::vector<SectionView> v = views(field, judge);
    ASSERT_EQ(v.size(), 23u) << judge;  // 8, 8 and 7 on the three cracks (one 0.05 m long)
    for (const SectionView& s : v) {
      EXPECT_NEAR(s.sxx, 0.01e6 + 0.2e6 * s.position.y, 1e-9 * 0.2e6)
          << judge << " at y = " << s.position.y;
      EXPECT_NEAR(s.syy, 0.06e6, 1e-9 * 0.06e6) << judge;
      EXPECT_NEAR(s.sxy, 0.0, 1e-9 * 0.06e6) << judge;
    }
  }
}

TEST(JudgeRadius, AnotherRadiusFitsTheSectionsAgain) {
  const std::vector<SectionView> seeds = views(kStep, "judge{}");
  const std::vector<SectionView> back =
      views(kStep, "judge{ radius = 0.1 }\nfor s in sections() do end\njudge{}");
  ASSERT_EQ(seeds.size(), back.size());
  for (size_t i = 0; i < seeds.size(); ++i) EXPECT_EQ(seeds[i].syy, back[i].syy);
}

TEST(JudgeRadius, ACheckpointKeepsIt) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("edem_judge_radius_" + std::to_string(::getpid()) + ".h5");
  const std::vector<SectionView> wide = views(kStep, "judge{ radius = 0.1 }");
  Interpreter first;
  first.context().quiet = true;
  expect_runs(first, bar() + "judge{ radius = 0.1 }\nsave('" + file.string() + "')");
  Interpreter second;
  second.context().quiet = true;
  // assign{} makes the restored model fit its sections again, with the radius it read back.
  expect_runs(second, "restore('" + file.string() + "')\nassign{ material = \"rock\" }");
  std::filesystem::remove(file);
  const Model& model = second.context().model();
  ASSERT_EQ(model.section_count(), static_cast<int>(wide.size()));
  for (int id = 0; id < model.section_count(); ++id)
    EXPECT_EQ(model.section(id).syy, wide[static_cast<size_t>(id)].syy);
}

TEST(JudgeRadius, ANegativeRadiusIsAnErrorNamingIt) {
  EXPECT_TRUE(test::contains(test::error_of("judge{ radius = -1 }"), "radius"));
}

// judge{ at = "equilibrium" }: the bar of kStep held at both ends (its stress in equilibrium from
// the start), every section past its strength.
std::string held_bar(const std::string& judge) {
  return bar() + "boundary{ side = \"bottom\", fix = \"xy\" }\nboundary{ side = \"top\", fix = \"xy\" }\n" + judge;
}

SolveResult last_solve(Interpreter& interpreter) { return interpreter.context().model().solve({}); }

TEST(JudgeAtEquilibrium, CyclingJudgesNothing) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, held_bar("judge{ at = \"equilibrium\" }\ncycle(100)"));
  EXPECT_EQ(broken(interpreter).count, 0);
}

TEST(JudgeAtEquilibrium, ASolveJudgesTheStateAtItsRatioUntilNoneBreaks) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, held_bar("judge{ at = \"equilibrium\", neighbours = \"break\" }"));
  const SolveResult r = last_solve(interpreter);
  const int sections = interpreter.context().model().info().sections;
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.broke, sections);  // all past their strength on the first state judged
  EXPECT_EQ(broken(interpreter).count, sections);
  EXPECT_EQ(r.judgments, 1);  // none left intact to judge again
}

// The cracks the first round broke: how many, how many of the bar's cuts have one on the
// 0.08 MPa side, and how many pairs of them touch (on one cut, end to end).
struct FirstRound {
  int count = 0, cuts_right = 0, touching = 0;
};

FirstRound first_round(const Model& model) {
  FirstRound f;
  std::vector<CrackView> round;
  for (int id = 0; id < model.crack_count() && model.crack(id).cycle == model.crack(0).cycle; ++id)
    round.push_back(model.crack(id));
  f.count = static_cast<int>(round.size());
  for (const double y : {0.25, 0.5, 0.75})
    f.cuts_right += std::any_of(round.begin(), round.end(), [&](const CrackView& c) {
      return std::fabs(c.position.y - y) < 1e-9 && c.position.x > 0.0;
    });
  for (size_t i = 0; i < round.size(); ++i)
    for (size_t j = i + 1; j < round.size(); ++j)
      f.touching += std::fabs(round[i].position.y - round[j].position.y) < 1e-9 &&
                    std::fabs(round[i].position.x - round[j].position.x) <
                        0.5 * (round[i].length + round[j].length) + 1e-9;
  return f;
}

// By default at equilibrium, of the failing sections that touch only the one furthest past its
// strength breaks; the others are judged again on the state that leaves. Along each of the bar's
// three cuts the sections touch end to end: the first round breaks no two neighbours, and on
// every cut the worst, on the 0.08 MPa side; the cuts that open relieve some of the rest.
TEST(JudgeAtEquilibrium, OfTouchingSectionsTheWorstBreaksAndTheOthersWait) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, held_bar("judge{ at = \"equilibrium\" }"));
  const SolveResult r = last_solve(interpreter);
  const Model& model = interpreter.context().model();
  EXPECT_TRUE(r.converged);
  const FirstRound f = first_round(model);
  EXPECT_EQ(f.touching, 0);
  EXPECT_EQ(f.cuts_right, 3);
  EXPECT_LT(f.count, model.info().sections / 2);
  EXPECT_GT(r.judgments, 2);
  EXPECT_LT(r.broke, model.info().sections);
}

// Judged every n cycles, all that fail break together unless told otherwise (the seed's way).
TEST(JudgeAtEquilibrium, NeighboursWaitIsTheEquilibriumModesDefaultOnly) {
  Interpreter cycles;
  cycles.context().quiet = true;
  expect_runs(cycles, bar() + "judge{ every = 10 }\ncycle(10)");
  EXPECT_EQ(broken(cycles).count, cycles.context().model().info().sections);
  Interpreter waiting;
  waiting.context().quiet = true;
  expect_runs(waiting, bar() + "judge{ every = 10, neighbours = \"wait\" }\ncycle(10)");
  const FirstRound f = first_round(waiting.context().model());
  EXPECT_EQ(f.touching, 0);
  EXPECT_EQ(f.cuts_right, 3);
  EXPECT_LT(f.count, waiting.context().model().info().sections / 2);
}

TEST(JudgeAtEquilibrium, AnUnknownNeighbourRuleIsAnErrorNamingIt) {
  const std::string error = test::error_of("judge{ at = \"equilibrium\", neighbours = \"later\" }");
  EXPECT_TRUE(test::contains(error, "neighbours")) << error;
  EXPECT_TRUE(test::contains(error, "later")) << error;
}

// Two a round (most = 2), the furthest past first: the crack that opens across the bar first
// relieves the rest, which a judgment of all at once breaks too.
TEST(JudgeAtEquilibrium, MostBreaksTheFurthestPastFirstRoundByRound) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, held_bar("judge{ at = \"equilibrium\", most = 2 }"));
  const SolveResult r = last_solve(interpreter);
  const int sections = interpreter.context().model().info().sections;
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.judgments, r.broke / 2 + 1);  // two a round, then a round that broke none
  EXPECT_LT(r.broke, sections);
  const Model& model = interpreter.context().model();
  ASSERT_GE(model.crack_count(), 2);
  EXPECT_GT(model.crack(0).position.x, 0.0);  // the 0.08 MPa side first
  EXPECT_GT(model.crack(1).position.x, 0.0);
}

// Under load control a bar that breaks through finds no equilibrium: the solve stops at its
// max_cycles with the breaks kept, never hangs.
TEST(JudgeAtEquilibrium, ACollapseEndsAtMaxCyclesWithTheStateKept) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, test::seed_bar("0.25") +
                               "boundary{ side = \"bottom\", fix = \"xy\" }\n"
                               "boundary{ side = \"top\", stress = {0, 0.06e6, 0} }\n"
                               "judge{ at = \"equilibrium\" }");
  const SolveResult r = interpreter.context().model().solve({.ratio = 1e-5, .max_cycles = 5000});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cycles, 5000);
  EXPECT_GT(r.broke, 0);
  EXPECT_EQ(broken(interpreter).count, r.broke);
}

TEST(JudgeAtEquilibrium, ACheckpointKeepsIt) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("edem_judge_at_" + std::to_string(::getpid()) + ".h5");
  Interpreter first;
  first.context().quiet = true;
  expect_runs(first, held_bar("judge{ at = \"equilibrium\" }\nsave('" + file.string() + "')"));
  Interpreter second;
  second.context().quiet = true;
  expect_runs(second, "restore('" + file.string() + "')\ncycle(100)");
  std::filesystem::remove(file);
  EXPECT_EQ(broken(second).count, 0);
  EXPECT_GT(last_solve(second).broke, 0);
  EXPECT_EQ(first_round(second.context().model()).touching, 0);  // and that neighbours wait
}

// Sections whose rock is dug out are gone: sections() says so (their stress and strength are
// zero, nothing to fit them from) and info() does not count them as intact; those in the rock
// left are not.
TEST(Sections, ThoseInRockDugOutAreGone) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, R"(
    block{ x = {-1, 1}, y = {0, 1} }
    region{ name = "dug", polygon = {{-1, 0}, {0, 0}, {0, 1}, {-1, 1}} }
    crackseed{ angle = 90, spacing = 0.5, origin = {-0.75, 0.5}, material = "strength", after = "crack" }
    zone{ edge = 0.125 }
    material{ "rock", young = 1e9, poisson = 0.25, density = 2600 }
    material{ "strength", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30, tension = 1e5 }
    assign{ material = "rock" }
    joint_material{ "crack", kn = 1e10, ks = 1e10, friction = 30 }
    boundary{ side = "bottom", fix = "xy" }
    local before = info()
    assert(before.intact_sections == before.sections, "sections gone before anything was dug")
    excavate{ region = "dug" }
    local gone, left = 0, 0
    for s in sections() do
      assert(s.gone == (s.x < 0), ("section %d at x = %g: gone is %s"):format(s.id, s.x, tostring(s.gone)))
      if s.gone then
        gone = gone + 1
        assert(s.sxx == 0 and s.cohesion == 0 and s.overstress == 0, "a gone section has a stress or a strength")
      else
        left = left + 1
      end
    end
    assert(gone > 0 and left > 0, ("%d gone, %d left"):format(gone, left))
    assert(info().intact_sections == left, ("info() counts %d intact, %d are left"):format(info().intact_sections, left))
    assert(info().sections == gone + left, "info().sections changed")
  )");
}

// Each section tells how far its stress is towards the built-in criteria, as judge{ most } ranks
// them: in the bar's uniform vertical tension of 0.06 MPa a horizontal section stands at
// 0.06 / 0.0546 of its tensile strength (its shear is further off: a Mohr circle of radius 0.03
// MPa against 0.102 MPa of shear strength at its centre).
TEST(Sections, OverstressIsTheBuiltInCriteriasMeasure) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, bar() + R"(
    judge{ at = "equilibrium" }
    local seen = 0
    for s in sections() do
      if s.x < -0.05 then
        seen = seen + 1
        local expected = 0.06e6 / 0.0546e6
        assert(math.abs(s.overstress - expected) < 1e-3 * expected,
               ("section %d: overstress %.6f, expected %.6f"):format(s.id, s.overstress, expected))
      end
    end
    assert(seen > 0, "no section at x < -0.05")
  )");
}

}  // namespace
}  // namespace edem
