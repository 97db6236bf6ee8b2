// The schema layer: every command checks its arguments before touching the model, rejects
// unknown keys with a hint, and a failed command leaves the model exactly as it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <lua.hpp>
#include <set>

#include "commands.hpp"
#include "interp_test.hpp"
#include "schema.hpp"

namespace edem {
namespace {

using test::contains;
using test::error_of;
using test::expect_runs;
using test::starts_with;

constexpr const char* kSquare = "block{ x = {0, 10}, y = {0, 10} }\n";

TEST(Schema, UnknownKeyIsRejectedWithAHint) {
  EXPECT_EQ(error_of("block{ xx = {0, 10}, y = {0, 10} }"),
            "test.lua:1: block: unknown key 'xx' (did you mean 'x'?)");
}

TEST(Schema, UnknownKeyWithoutAHintListsTheKeys) {
  EXPECT_EQ(error_of("crack{ from = {0, 0}, to = {1, 1}, colour = 3 }"),
            "test.lua:1: crack: unknown key 'colour' (keys: from, to)");
}

TEST(Schema, MessagesNameTheKeyAndTheValue) {
  EXPECT_EQ(error_of(std::string(kSquare) + "jset{ angle = 10, spacing = -2 }"),
            "test.lua:2: jset: spacing must be > 0, got -2");
  EXPECT_EQ(error_of("jset{ angle = -400, spacing = 1 }"),
            "test.lua:1: jset: angle must be in [-360, 360], got -400");
  EXPECT_EQ(error_of("model{ tolerance = 1 }"),
            "test.lua:1: model: tolerance must be in (0, 0.001], got 1");
  EXPECT_EQ(error_of("jset{ angle = 0, spacing = {1, 2, -1} }"),
            "test.lua:1: jset: spacing[3] must be > 0, got -1");
}

TEST(Schema, NonFiniteNumbersAreRejected) {
  for (const char* value : {"0/0", "1/0", "-1/0", "math.huge"}) {
    const std::string message = error_of(std::string("zone{ edge = ") + value + " }");
    EXPECT_TRUE(starts_with(message, "test.lua:1: zone: edge must be a finite number, got "));
  }
}

TEST(Schema, WrongTypesAreRejected) {
  EXPECT_EQ(error_of("model{ title = true }"),
            "test.lua:1: model: title must be a string, got true");
  EXPECT_EQ(error_of("jset{ angle = {}, spacing = 1 }"),
            "test.lua:1: jset: angle must be a number, got a table");
  EXPECT_EQ(error_of("jset{ angle = 0, spacing = 1, seed = 0.5 }"),
            "test.lua:1: jset: seed must be an integer, got 0.5");
  EXPECT_EQ(error_of("region{ name = 'a', polygon = {{0, 0}, {1, 0}, {0, 1}}, glued = 1 }"),
            "test.lua:1: region: glued must be true or false, got 1");
}

TEST(Schema, CommandsTakeOneTable) {
  EXPECT_TRUE(contains(error_of("block(3)"), "block: expects a table, like "));
  EXPECT_TRUE(contains(error_of("block()"), "block: expects a table, like "));
  EXPECT_TRUE(contains(error_of("zone({edge = 1}, {})"), "got 2 arguments"));
  EXPECT_EQ(error_of("info({})"), "test.lua:1: info: takes no arguments, got 1");
}

TEST(Schema, AcceptedForms) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    block{ {0, 0}, {10, 0}, {10, 10}, {0, 10} }
    jset{ angle = 0, spacing = 2.5, origin = {x = 0, y = 1} }        -- named point
    jset{ angle = 90, spacing = {1, 2}, seed = 7.0 }                  -- list, integral float
    region{ name = "a", polygon = {{1, 1}, {3, 1}, {3, 3}, {1, 3}} }
    zone{ edge = 1, far = 2, near = "a" }                             -- one name
    zone{ edge = 1, near = {{4, 4}, {6, 4}, {6, 6}} }                 -- one polygon
    zone{ edge = 1, near = {"a", {{4, 4}, {6, 4}, {6, 6}}} }          -- a list of both
  )");
  EXPECT_EQ(interpreter.context().model().joint_set_count(), 2);
  const auto picture = std::filesystem::temp_directory_path() /
                       ("edem_schema_forms_" + std::to_string(::getpid()) + ".svg");
  expect_runs(interpreter,
              "plot{ file = '" + picture.string() + "', show = 'blocks', size = {200, 100} }");
  EXPECT_TRUE(std::filesystem::exists(picture));
  std::filesystem::remove(picture);
}

TEST(Schema, PointsHandedOutAreAcceptedBack) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kSquare) + R"(
    local b = blocks()()
    crack{ from = b.vertices[1], to = b.centroid }
  )");
}

TEST(Schema, FailedCommandsApplyNothing) {
  Interpreter interpreter;
  expect_runs(interpreter, std::string(kSquare) + "jset{ angle = 0, spacing = 2 }");
  Model& model = interpreter.context().model();
  const ModelInfo before = model.info();
  for (const char* bad : {
           "jset{ angle = 45, spacing = 1, gap = -1 }",         // a bad value
           "jset{ angle = 45, spacing = 1, spacingg = 2 }",     // an unknown key
           "jset{ angle = 45, spacing = {1, 0} }",              // a bad list item
           "jset{ angle = 45, spacing = 1, region = 'none' }",  // an unknown region (engine)
           "block{ x = {5, 15}, y = {0, 10} }",                 // overlapping (engine)
           "region{ name = 'r', polygon = {{0, 0}, {1, 1}, {1, 0}, {0, 1}} }",
       }) {
    error_of(interpreter, bad);
    const ModelInfo after = interpreter.context().model().info();
    EXPECT_EQ(after.joint_sets, before.joint_sets) << bad;
    EXPECT_EQ(after.blocks, before.blocks) << bad;
    EXPECT_EQ(after.regions, before.regions) << bad;
  }
}

TEST(Schema, FailedModelKeepsTheCurrentModel) {
  Interpreter interpreter;
  expect_runs(interpreter, "model{ title = 'first' }");
  error_of(interpreter, "model{ title = 'second', tolerance = -1 }");
  EXPECT_EQ(interpreter.context().model().title(), "first");
}

TEST(Schema, CommandsBeforeModelUseADefaultModel) {
  Interpreter interpreter;
  EXPECT_EQ(interpreter.context().current, nullptr);
  expect_runs(interpreter, kSquare);
  ASSERT_NE(interpreter.context().current, nullptr);
  EXPECT_EQ(interpreter.context().model().info().blocks, 1);
  expect_runs(interpreter, "model{ title = 'fresh' }");
  EXPECT_EQ(interpreter.context().model().info().blocks, 0);
}

TEST(Schema, EngineErrorsBecomeLuaErrorsThatPcallCatches) {
  Interpreter interpreter;
  expect_runs(interpreter, R"(
    local ok, message = pcall(zone, { edge = 1 })
    assert(not ok)
    assert(type(message) == "string", "a string, not an anonymous error")
    assert(message:find("test.lua:2: zone: no blocks to zone", 1, true), message)
  )");
}

TEST(Schema, RangesReadAsWritten) {
  EXPECT_EQ(gt(0).text(), "> 0");
  EXPECT_EQ(ge(0).text(), ">= 0");
  EXPECT_EQ(between(-360, 360).text(), "[-360, 360]");
  EXPECT_EQ(above_upto(0, 1e-3).text(), "(0, 0.001]");
  EXPECT_EQ(any_value.text(), "");
  EXPECT_TRUE(above_upto(0, 1).contains(1));
  EXPECT_FALSE(above_upto(0, 1).contains(0));
}

// Defaults are Lua literals checked against their own key when the state is made; this
// makes every command's defaults go through the reader once more, explicitly.
TEST(Schema, EveryDefaultPassesItsOwnKey) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  for (const Command* command : commands()) {
    EXPECT_NO_THROW(push_defaults(L, *command)) << command->name;
    lua_settop(L, 0);
  }
  lua_close(L);
}

TEST(Schema, TheRegistryIsWellFormed) {
  std::set<std::string_view> names;
  for (const Command* command : commands()) {
    EXPECT_TRUE(names.insert(command->name).second) << "two commands named " << command->name;
    EXPECT_FALSE(command->help.empty()) << command->name;
    EXPECT_NE(command->run, nullptr) << command->name;
    std::set<std::string_view> keys;
    for (size_t i = 0; i < command->positional.size(); ++i) {
      const Key& key = command->positional[i];
      EXPECT_TRUE(keys.insert(key.name).second) << command->name << "." << key.name;
      if (key.rest) {
        EXPECT_EQ(i + 1, command->positional.size()) << "a rest item must come last";
        EXPECT_TRUE(key.type == Type::polygon || key.type == Type::strings) << command->name;
      }
    }
    for (const Key& key : command->keys) {
      EXPECT_TRUE(keys.insert(key.name).second) << command->name << "." << key.name;
      EXPECT_FALSE(key.help.empty()) << command->name << "." << key.name;
      EXPECT_FALSE(key.rest) << "only positional items take the rest";
      if (key.type == Type::number) {
        EXPECT_FALSE(key.unit.empty()) << command->name << "." << key.name;
      }
    }
    if (command->form == Form::call) {
      EXPECT_TRUE(command->keys.empty()) << command->name;
      EXPECT_FALSE(command->bare_call) << "a call-form command takes f() already";
    }
  }
}

}  // namespace
}  // namespace edem
