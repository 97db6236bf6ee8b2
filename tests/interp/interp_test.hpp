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

}  // namespace edem::test
