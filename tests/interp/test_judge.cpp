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

// A 0.2 m x 1 m column, zones of 0.05 m, with potential cracks across it every 0.25 m, in
// vertical tension above the seed's sigma_t = 0.0546 MPa:
// 0.06 MPa where x < 0 and 0.08 MPa where x > 0, so every section fails at the first judgment.
constexpr const char* kBar = R"(
block{ x = {-0.1, 0.1}, y = {0, 1} }
crackseed{ angle = 0, spacing = 0.25, origin = {0, 0.5}, material = "strength", after = "crack" }
zone{ edge = 0.05 }
material{ "rock", young = 415.52e6, poisson = 0.136, density = 1505 }
material{ "strength", model = "mohr", young = 415.52e6, poisson = 0.136, cohesion = 0.143e6,
          friction = 34, tension = 0.0546e6 }
assign{ material = "rock" }
joint_material{ "crack", kn = 1880e6, ks = 1880e6, friction = 31.2 }
insitu{ syy = 0.06e6, szz = 0.02e6 }
insitu{ syy = 0.08e6, szz = 0.02e6, region = {{0, -1}, {1, -1}, {1, 2}, {0, 2}} }
)";

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
  expect_runs(interpreter, std::string(kBar) + "judge{ every = 10 }\ncycle(10)");
  const int sections = interpreter.context().model().info().sections;
  EXPECT_GT(sections, 4);
  EXPECT_EQ(broken(interpreter).count, sections);
}

TEST(JudgeMost, AtMostThatManyBreakAtAJudgmentTheFurthestPastFirst) {
  Interpreter interpreter;
  interpreter.context().quiet = true;
  expect_runs(interpreter, std::string(kBar) + "judge{ every = 10, most = 2 }\ncycle(10)");
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
  expect_runs(interpreter, std::string(kBar) +
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
  expect_runs(first, std::string(kBar) + "judge{ every = 10, most = 1 }\nsave('" + file.string() + "')");
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
