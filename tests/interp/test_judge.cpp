// judge{ most = n }: at most n sections break at a judgment, those furthest past the built-in
// criteria first; the rest wait for the next judgment.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "interp_test.hpp"
#include "model/model.hpp"

namespace edem {
namespace {

using test::expect_runs;

// The seed's tension bar (test::seed_bar) with potential cracks every 0.25 m, in vertical tension
// above its sigma_t = 0.0546 MPa: 0.06 MPa where x < 0 and 0.08 MPa where x > 0, so every section
// fails at the first judgment.
std::string bar() {
  return test::seed_bar("0.25") + R"(
insitu{ syy = 0.06e6, szz = 0.02e6 }
insitu{ syy = 0.08e6, szz = 0.02e6, region = {{0, -1}, {1, -1}, {1, 2}, {0, 2}} }
)";
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

}  // namespace
}  // namespace edem
