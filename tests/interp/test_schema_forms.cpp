// Schema forms no command of this issue uses yet, checked on stand-in commands: plain
// positional arguments with a function, every(100, f), and a positional name in a table,
// material{ "rock", density = 2650 }.
#include <gtest/gtest.h>

#include <lua.hpp>

#include "adaptor.hpp"
#include "interp_test.hpp"
#include "schema.hpp"

namespace edem {
namespace {

using test::error_of;
using test::expect_runs;

int no_run(lua_State*, Context&, const Args&) {
  return 0;
}

const Command& every_command() {
  static const Command command{
      .name = "every",
      .help = "calls a function every n cycles",
      .form = Form::call,
      .positional =
          {
              {"n", Type::integer, "", gt(0), kRequired, "cycles between calls"},
              {"callback", Type::function, "", any_value, kRequired, "what to call"},
          },
      .run = no_run,
  };
  return command;
}

const Command& material_command() {
  static const Command command{
      .name = "material",
      .help = "defines a material",
      .positional = {{"name", Type::string, "", any_value, kRequired, "its name"}},
      .keys = {{"density", Type::number, "kg/m3", gt(0), "2650", "density"}},
      .run = no_run,
  };
  return command;
}

// every(n, f): calls f(n) at once and returns what it returns.
int every(lua_State* L) {
  return guarded(L, "every", [&] {
    const Args args = read_args(L, every_command(), lua_upvalueindex(1));
    lua_pushvalue(L, args.get<FunctionArg>("callback").index);
    lua_pushinteger(L, static_cast<lua_Integer>(args.integer("n")));
    lua_call(L, 1, 1);
    return 1;
  });
}

// material{...}: returns its name and density.
int material(lua_State* L) {
  return guarded(L, "material", [&] {
    const Args args = read_args(L, material_command(), lua_upvalueindex(1));
    lua_pushstring(L, args.string("name").c_str());
    lua_pushnumber(L, args.number("density"));
    return 2;
  });
}

void add(Interpreter& interpreter, const Command& command, lua_CFunction function) {
  lua_State* L = interpreter.state();
  push_defaults(L, command);
  lua_pushcclosure(L, function, 1);
  lua_setglobal(L, std::string(command.name).c_str());
}

class SchemaForms : public ::testing::Test {
 protected:
  void SetUp() override {
    add(interpreter_, every_command(), every);
    add(interpreter_, material_command(), material);
  }
  std::string error(const std::string& code) { return error_of(interpreter_, code); }
  Interpreter interpreter_;
};

TEST_F(SchemaForms, PositionalArguments) {
  expect_runs(interpreter_, "assert(every(3, function(n) return n * 2 end) == 6)");
  EXPECT_EQ(error("every(0, print)"), "test.lua:1: every: argument #1 (n) must be > 0, got 0");
  EXPECT_EQ(error("every(3)"),
            "test.lua:1: every: missing argument #2 (callback), like every(n, callback)");
  EXPECT_EQ(error("every(3, 4)"),
            "test.lua:1: every: argument #2 (callback) must be a function, got 4");
  EXPECT_EQ(error("every(1, print, 3)"), "test.lua:1: every: takes 2 arguments, got 3");
}

TEST_F(SchemaForms, ErrorsInsideACallbackKeepTheirOwnWord) {
  EXPECT_EQ(error("every(1, function(n)\n  error('inside')\nend)"),
            "test.lua:2: error: inside\ntraceback:\n"
            "  test.lua:2: in function <test.lua:1>\n"
            "  test.lua:1: in main chunk");
}

TEST_F(SchemaForms, PositionalNameInATable) {
  expect_runs(interpreter_, R"(
    local name, density = material{ "rock" }
    assert(name == "rock" and density == 2650)
    name, density = material{ "soil", density = 1800 }
    assert(name == "soil" and density == 1800)
  )");
  EXPECT_EQ(error("material{ density = 1 }"),
            "test.lua:1: material: missing item #1 (name), like material{ name, ... }");
  EXPECT_EQ(error("material{ 'rock', 'granite' }"),
            "test.lua:1: material: too many positional items: material takes 1, got 2");
  EXPECT_EQ(error("material{ 5 }"), "test.lua:1: material: item #1 (name) must be a string, got 5");
  EXPECT_EQ(error("material{ 'rock', densty = 1 }"),
            "test.lua:1: material: unknown key 'densty' (did you mean 'density'?)");
}

}  // namespace
}  // namespace edem
