// Helpers for the interpreter tests: run Lua in a fresh Interpreter, expect success or an error.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "interpreter.hpp"

namespace edem::test {

// Runs `code` as "test.lua" and fails the test with the error if there is one.
inline void expect_runs(Interpreter& interpreter, const std::string& code) {
  const auto error = interpreter.run_string(code, "test.lua");
  EXPECT_FALSE(error) << "script failed:\n" << code << "\n" << error.value_or("");
}

// Runs `code` as "test.lua" and returns its error message ("" if it did not fail).
inline std::string error_of(Interpreter& interpreter, const std::string& code) {
  const auto error = interpreter.run_string(code, "test.lua");
  EXPECT_TRUE(error) << "script should have failed:\n" << code;
  return error.value_or("");
}

// EXPECT_TRUE(contains(text, part)) prints both when it fails (no gmock needed).
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << part << "' not found in:\n" << text;
}

inline ::testing::AssertionResult starts_with(const std::string& text, const std::string& head) {
  if (text.rfind(head, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "does not start with '" << head << "':\n" << text;
}

inline std::string error_of(const std::string& code) {
  Interpreter interpreter;
  return error_of(interpreter, code);
}

// The seed paper's tension bar, unloaded: a 0.2 m x 1 m column of its rock (elastic zones of
// 0.05 m, judged by its Mohr-Coulomb strength) with potential cracks across it every `spacing` m
// from y = 0.5, which become joints of material "crack".
inline std::string seed_bar(const std::string& spacing) {
  return R"(
block{ x = {-0.1, 0.1}, y = {0, 1} }
crackseed{ angle = 0, spacing = )" + spacing + R"(, origin = {0, 0.5}, material = "strength", after = "crack" }
zone{ edge = 0.05 }
material{ "rock", young = 415.52e6, poisson = 0.136, density = 1505 }
material{ "strength", model = "mohr", young = 415.52e6, poisson = 0.136, cohesion = 0.143e6,
          friction = 34, tension = 0.0546e6 }
assign{ material = "rock" }
joint_material{ "crack", kn = 1880e6, ks = 1880e6, friction = 31.2 }
)";
}

// drive(points, vx, vy): each of the gridpoints in points (as gridpoints() gives them) held at that
// velocity [m a cycle in static mode], so that a block is moved as a rigid body by them.
constexpr const char* kDrive = R"lua(
local function drive(points, vx, vy)
  for _, g in ipairs(points) do
    local h = 0.01  -- boundary{} selects by the gridpoints' positions as built
    boundary{ polygon = {{g.x - h, g.y - h}, {g.x + h, g.y - h}, {g.x + h, g.y + h}, {g.x - h, g.y + h}},
              xvel = vx, yvel = vy }
  end
end
)lua";

}  // namespace edem::test
