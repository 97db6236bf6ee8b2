// How a script that stops is reported: "FILE:LINE: word: message" for every kind of error,
// a short traceback when the error is inside a function, none at the top level.
#include <gtest/gtest.h>

#include "interp_test.hpp"

namespace edem {
namespace {

using test::contains;
using test::error_of;
using test::starts_with;

TEST(Errors, CommandErrorNamesTheCommandAndTheLine) {
  EXPECT_EQ(error_of("\n\nzone{ edge = 1 }"),
            "test.lua:3: zone: no blocks to zone: define blocks with block{...} first");
}

TEST(Errors, TracebackWhenTheErrorIsInsideAFunction) {
  const std::string message = error_of(R"(local function cut(s)
  jset{ angle = 0, spacing = s }
end
local function cut_twice(s)
  cut(s)
end
cut_twice(-1))");
  EXPECT_TRUE(starts_with(message, "test.lua:2: jset: spacing must be > 0, got -1\ntraceback:\n"));
  EXPECT_TRUE(contains(message, "  test.lua:2: in function 'cut'\n"));
  EXPECT_TRUE(contains(message, "  test.lua:5: in function 'cut_twice'\n"));
  EXPECT_TRUE(contains(message, "  test.lua:7: in main chunk"));
}

TEST(Errors, NoTracebackAtTheTopLevel) {
  EXPECT_EQ(error_of("jset{ angle = 0, spacing = 0 }"),
            "test.lua:1: jset: spacing must be > 0, got 0");
}

TEST(Errors, SyntaxErrors) {
  EXPECT_EQ(error_of("x = 1\nx = = 2"), "test.lua:2: syntax: unexpected symbol near '='");
}

TEST(Errors, LuaRuntimeErrors) {
  EXPECT_EQ(error_of("local t\nprint(t.x)"),
            "test.lua:2: lua: attempt to index a nil value (local 't')");
  EXPECT_EQ(error_of("string.rep()"),
            "test.lua:1: lua: bad argument #1 to 'rep' (string expected, got no value)");
}

TEST(Errors, TheScriptsOwnErrors) {
  EXPECT_EQ(error_of("error('too deep')"), "test.lua:1: error: too deep");
  EXPECT_EQ(error_of("\nerror('no position', 0)"), "test.lua:2: error: no position");
  EXPECT_EQ(error_of("assert(false)"), "test.lua:1: error: assertion failed!");
  EXPECT_EQ(error_of("assert(1 > 2, 'one is not more than two')"),
            "test.lua:1: error: one is not more than two");
  EXPECT_EQ(error_of("error({})"), "test.lua:1: error: (error object is a table value)");
  EXPECT_EQ(error_of("error(setmetatable({}, {__tostring = function() return 'custom' end}))"),
            "test.lua:1: error: custom");
}

TEST(Errors, UnknownCommandsGetAHint) {
  EXPECT_EQ(error_of("blok{ x = {0, 1}, y = {0, 1} }"),
            "test.lua:1: blok: unknown command (did you mean 'block'?)");
  EXPECT_EQ(error_of("zonee{}"), "test.lua:1: zonee: unknown command (did you mean 'zone'?)");
  EXPECT_EQ(error_of("prnt('x')"), "test.lua:1: prnt: unknown command (did you mean 'print'?)");
  EXPECT_EQ(error_of("frobnicate()"), "test.lua:1: frobnicate: unknown command");
}

TEST(Errors, ACaughtCommandErrorRaisedAgainIsUnchanged) {
  EXPECT_EQ(error_of("local ok, e = pcall(jset, { angle = 0, spacing = -1 })\nerror(e, 0)"),
            "test.lua:1: jset: spacing must be > 0, got -1");
}

TEST(Errors, CommandErrorsInsideCoroutines) {
  // coroutine.wrap puts its own position in front of the message; the command's stays.
  EXPECT_EQ(error_of("local f = coroutine.wrap(function()\n"
                     "  jset{ angle = 0, spacing = -1 }\n"
                     "end)\n"
                     "f()"),
            "test.lua:2: jset: spacing must be > 0, got -1");
}

TEST(Errors, LongFileNamesAreNotShortened) {
  // Lua shortens sources past 60 characters to "...tail"; users must see their path.
  const std::string name = std::string(80, 'd') + "/script.lua";
  Interpreter interpreter;
  const auto syntax = interpreter.run_string("x = = 1", name);
  ASSERT_TRUE(syntax);
  EXPECT_TRUE(starts_with(*syntax, name + ":1: syntax: "));
  const auto command = interpreter.run_string("\njset{ angle = 0, spacing = 0 }", name);
  ASSERT_TRUE(command);
  EXPECT_TRUE(starts_with(*command, name + ":2: jset: "));
  const auto runtime = interpreter.run_string("local t\nt.x = 1", name);
  ASSERT_TRUE(runtime);
  EXPECT_TRUE(starts_with(*runtime, name + ":2: lua: "));
}

TEST(Errors, AnInterpreterKeepsWorkingAfterAnError) {
  Interpreter interpreter;
  error_of(interpreter, "jset{}");
  test::expect_runs(interpreter, "block{ x = {0, 1}, y = {0, 1} }\nassert(info().blocks == 1)");
}

}  // namespace
}  // namespace edem
