// Schema forms checked on stand-in commands: plain positional arguments with a function,
// every(100, f); a positional name in a table, material{ "rock", density = 2650 }; functions
// given by key, apply{ fn = f, x = 2 }; a list of numbers or a name, load{ stress = "insitu" };
// strings taking the rest of the table, pick{ "a", "b" }; and f() standing for f{}.
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

const Command& apply_command() {
  static const Command command{
      .name = "apply",
      .help = "calls fn(x), then after(result) if given",
      .keys =
          {
              {"fn", Type::function, "", any_value, kRequired, "first"},
              {"x", Type::number, "", any_value, "1", "argument"},
              {"after", Type::function, "", any_value, kOptional, "second"},
              {"label", Type::string, "", any_value, R"("z")", "read after the functions"},
          },
      .run = no_run,
  };
  return command;
}

// apply{...}: returns after(fn(x)) and the label: functions given by key stay callable.
int apply(lua_State* L) {
  return guarded(L, "apply", [&] {
    const Args args = read_args(L, apply_command(), lua_upvalueindex(1));
    lua_pushvalue(L, args.get<FunctionArg>("fn").index);
    lua_pushnumber(L, args.number("x"));
    lua_call(L, 1, 1);
    if (args.has("after")) {
      lua_pushvalue(L, args.get<FunctionArg>("after").index);
      lua_insert(L, -2);
      lua_call(L, 1, 1);
    }
    lua_pushstring(L, args.string("label").c_str());
    return 2;
  });
}

const std::vector<std::string>& load_names() {
  static const std::vector<std::string> names = {"insitu", "zero"};
  return names;
}

const Command& load_command() {
  static const Command command{
      .name = "load",
      .help = "a stress as numbers or a name",
      .keys =
          {{"stress", Type::numbers_or_name, "Pa", ge(-10), kRequired, "stress", {}, load_names}},
      .run = no_run,
      .bare_call = true,
  };
  return command;
}

// load{...}: returns the name, or the numbers.
int load(lua_State* L) {
  return guarded(L, "load", [&] {
    const Args args = read_args(L, load_command(), lua_upvalueindex(1));
    if (const auto* name = args.find<std::string>("stress")) {
      lua_pushstring(L, name->c_str());
      return 1;
    }
    const auto& numbers = args.get<std::vector<double>>("stress");
    for (const double n : numbers) lua_pushnumber(L, n);
    return static_cast<int>(numbers.size());
  });
}

const std::vector<std::string>& pick_names() {
  static const std::vector<std::string> names = {"alpha", "beta", "gamma"};
  return names;
}

const Command& pick_command() {
  static const Command command{
      .name = "pick",
      .help = "names, any number",
      .positional =
          {{"first", Type::number, "", any_value, kRequired, "a number"},
           {"names", Type::strings, "", any_value, kRequired, "names", {}, pick_names, true}},
      .keys = {{"k", Type::number, "", any_value, "0", "a key"}},
      .run = no_run,
      .bare_call = true,
  };
  return command;
}

// pick{...}: returns the names joined by commas.
int pick(lua_State* L) {
  return guarded(L, "pick", [&] {
    const Args args = read_args(L, pick_command(), lua_upvalueindex(1));
    std::string joined;
    for (const auto& name : args.get<std::vector<std::string>>("names"))
      joined += (joined.empty() ? "" : ",") + name;
    lua_pushstring(L, joined.c_str());
    return 1;
  });
}

const Command& go_command() {
  static const Command command{
      .name = "go",
      .help = "all keys optional",
      .keys = {{"speed", Type::number, "m/s", gt(0), "2", "how fast"}},
      .run = no_run,
      .bare_call = true,
  };
  return command;
}

int go(lua_State* L) {
  return guarded(L, "go", [&] {
    const Args args = read_args(L, go_command(), lua_upvalueindex(1));
    lua_pushnumber(L, args.number("speed"));
    return 1;
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
    add(interpreter_, apply_command(), apply);
    add(interpreter_, load_command(), load);
    add(interpreter_, pick_command(), pick);
    add(interpreter_, go_command(), go);
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

TEST_F(SchemaForms, FunctionsGivenByKeyStayCallable) {
  expect_runs(interpreter_, R"(
    local r, label = apply{ fn = function(x) return x * 10 end, x = 4 }
    assert(r == 40 and label == "z")
    r, label = apply{ after = function(y) return y + 1 end, fn = function(x) return -x end,
                      label = "b", x = 2 }
    assert(r == -1 and label == "b", r)
  )");
  EXPECT_EQ(error("apply{ fn = 3 }"), "test.lua:1: apply: fn must be a function, got 3");
}

TEST_F(SchemaForms, NumbersOrAName) {
  expect_runs(interpreter_, R"(
    assert(load{ stress = "insitu" } == "insitu")
    local a, b, c = load{ stress = {1, 2, 3} }
    assert(a == 1 and b == 2 and c == 3)
  )");
  EXPECT_EQ(error("load{ stress = 'insito' }"),
            "test.lua:1: load: stress must be one of insitu, zero, got \"insito\" (did you mean "
            "'insitu'?)");
  EXPECT_EQ(error("load{ stress = {1, -20} }"),
            "test.lua:1: load: stress[2] must be >= -10, got -20");
  EXPECT_EQ(error("load{ stress = 5 }"),
            "test.lua:1: load: stress must be a list of numbers or a name, got 5");
  EXPECT_EQ(error("load{ stress = true }"),
            "test.lua:1: load: stress must be a list of numbers or a name, got true");
  EXPECT_EQ(error("load()"), "test.lua:1: load: missing required key 'stress'");
}

TEST_F(SchemaForms, StringsTakingTheRestOfTheTable) {
  expect_runs(interpreter_, R"(
    assert(pick{ 1, "alpha" } == "alpha")
    assert(pick{ 1, "gamma", "alpha", "gamma", k = 3 } == "gamma,alpha,gamma")
  )");
  EXPECT_EQ(error("pick{ 1 }"),
            "test.lua:1: pick: missing item #2 (names), like pick{ first, ..., ... }");
  EXPECT_EQ(error("pick{ 1, 'alpha', 'betta' }"),
            "test.lua:1: pick: item #3 must be one of alpha, beta, gamma, got \"betta\" (did you "
            "mean 'beta'?)");
  EXPECT_EQ(error("pick{ 1, 'alpha', {} }"),
            "test.lua:1: pick: item #3 must be a string, got a table");
}

TEST_F(SchemaForms, BareCallStandsForAnEmptyTable) {
  expect_runs(interpreter_, "assert(go() == 2 and go{} == 2 and go{ speed = 3 } == 3)");
  EXPECT_EQ(error("go(3)"), "test.lua:1: go: expects a table, like go{ ... }, got 3");
  EXPECT_TRUE(test::contains(error("material()"), "material: expects a table, like "));
}

}  // namespace
}  // namespace edem
