// What a script shares with whoever runs it: settings{} declares the keys `--set KEY=VALUE` may
// give, with their defaults; out_dir() tells where --out puts the files commands write; result{}
// reports the run's result row (result.csv there), which edem sweep gathers.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "csv.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// A --set value as the default's type reads it; the message names what was given.
void push_given(lua_State* L, const std::string& key, const std::string& text, int default_type) {
  if (default_type == LUA_TSTRING) {
    lua_pushlstring(L, text.data(), text.size());
    return;
  }
  if (default_type == LUA_TBOOLEAN) {
    if (text != "true" && text != "false")
      fail("--set {}={}: {} is true or false (its default is), got \"{}\"", key, text, key, text);
    lua_pushboolean(L, text == "true");
    return;
  }
  if (text.empty() || lua_stringtonumber(L, text.c_str()) != text.size() + 1)
    fail("--set {}={}: {} is a number (its default is), got \"{}\"", key, text, key, text);
}

int run_settings(lua_State* L, Context& context, const Args& args) {
  const int defaults = args.get<TableArg>("defaults").index;
  std::vector<std::string> keys;
  lua_pushnil(L);
  while (lua_next(L, defaults) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) fail("the defaults are named keys, key = value; got a key {}", describe(L, -2));
    const std::string key = lua_tostring(L, -2);
    const int type = lua_type(L, -1);
    if (type != LUA_TNUMBER && type != LUA_TSTRING && type != LUA_TBOOLEAN)
      fail("the default of {} must be a number, a string or a boolean (it sets the type --set gives), got {}", key,
           describe(L, -1));
    keys.push_back(key);
    lua_pop(L, 1);
  }
  std::sort(keys.begin(), keys.end());
  if (context.probe != nullptr) {  // edem sweep wants the declarations only: stop here
    context.probe->reached = true;
    for (const std::string& key : keys) {
      lua_getfield(L, defaults, key.c_str());
      context.probe->declared.push_back({key, luaL_typename(L, -1), luaL_tolstring(L, -1, nullptr)});
      lua_pop(L, 2);
    }
    fail("the settings are read; the script stops here (edem sweep checks its table)");
  }
  for (const auto& [key, text] : context.settings)
    if (!std::binary_search(keys.begin(), keys.end(), key))
      fail("--set {}={}: this script has no setting '{}'{} (its settings: {})", key, text, key,
           did_you_mean(key, keys), fmt::join(keys, ", "));
  lua_createtable(L, 0, static_cast<int>(keys.size()));
  const int result = lua_gettop(L);
  for (const std::string& key : keys) {
    lua_getfield(L, defaults, key.c_str());
    const int type = lua_type(L, -1);
    const auto given = std::find_if(context.settings.begin(), context.settings.end(),
                                    [&](const auto& s) { return s.first == key; });
    if (given != context.settings.end()) {
      lua_pop(L, 1);
      push_given(L, key, given->second, type);
    }
    lua_setfield(L, result, key.c_str());
  }
  return 1;
}

int run_out_dir(lua_State* L, Context& context, const Args&) {
  const std::string dir = context.out_dir.empty() ? "." : context.out_dir;
  lua_pushlstring(L, dir.data(), dir.size());
  return 1;
}

// A result's value as text: integers as such, other numbers in the fewest digits that read back
// exactly.
std::string value_text(lua_State* L, int index) {
  if (lua_isinteger(L, index)) return fmt::format("{}", lua_tointeger(L, index));
  if (lua_type(L, index) == LUA_TNUMBER) return fmt::format("{}", lua_tonumber(L, index));
  if (lua_type(L, index) == LUA_TBOOLEAN) return lua_toboolean(L, index) ? "true" : "false";
  return lua_tostring(L, index);
}

int run_result(lua_State* L, Context& context, const Args& args) {
  const int values = args.get<TableArg>("values").index;
  std::vector<std::pair<std::string, std::string>> given;
  lua_pushnil(L);
  while (lua_next(L, values) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) fail("the result is named values, key = value; got a key {}", describe(L, -2));
    const std::string key = lua_tostring(L, -2);
    const int type = lua_type(L, -1);
    if (type != LUA_TNUMBER && type != LUA_TSTRING && type != LUA_TBOOLEAN)
      fail("{} must be a number, a string or a boolean, got {}", key, describe(L, -1));
    for (const char* own : {"name", "status", "seconds", "message"})
      if (key == own) fail("'{}' is a column edem sweep writes itself; give the result another name", key);
    given.emplace_back(key, value_text(L, -1));
    lua_pop(L, 1);
  }
  std::sort(given.begin(), given.end());  // a table's own order is Lua's whim
  for (auto& [key, value] : given) {
    const auto same = std::find_if(context.results.begin(), context.results.end(),
                                   [&](const auto& r) { return r.first == key; });
    if (same != context.results.end()) same->second = value;
    else context.results.emplace_back(key, value);
  }
  // Written whole each time, through a temporary file, so that a reader never sees half a row.
  const std::string file = context.output_path("result.csv");
  const std::string temporary = file + ".tmp";
  {
    std::ofstream out(temporary);
    std::vector<std::string> keys, texts;
    for (const auto& [key, value] : context.results) {
      keys.push_back(key);
      texts.push_back(value);
    }
    out << csv_line(keys) << '\n' << csv_line(texts) << '\n';
    if (!out) fail("cannot write {}", temporary);
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0) fail("cannot write {}", file);
  return 0;
}

}  // namespace

const Command& settings_command() {
  static const Command command{
      .name = "settings",
      .help =
          "Declares the script's settings with their defaults and returns their values: the default, or what "
          "`--set KEY=VALUE` gave, read as the default's type (a number, true or false, or text). A --set key "
          "the script does not declare is an error, as is a value of the wrong type.",
      .form = Form::call,
      .positional =
          {
              {"defaults", Type::table, "", any_value, kRequired,
               "key = default for each setting (a number, a string or a boolean)"},
          },
      .run = run_settings,
      .returns = "a table of the settings' values",
      .usage = "local s = settings{ depth = 158, bolts = \"none\", strict = false }\nprint(s.depth)",
  };
  return command;
}

const Command& out_dir_command() {
  static const Command command{
      .name = "out_dir",
      .help = "The folder `--out` named, where the files commands write go (\".\" without --out).",
      .form = Form::call,
      .run = run_out_dir,
      .returns = "a string",
      .usage = "local f = io.open(out_dir() .. \"/table.csv\", \"w\")",
  };
  return command;
}

const Command& result_command() {
  static const Command command{
      .name = "result",
      .help =
          "Reports the run's result: named values written as one row (a header, then the values) to "
          "result.csv in the --out folder. A later call adds columns or replaces values, so a script may report "
          "as it goes; the columns are in the order first given, a call's own in alphabetical order. `edem "
          "sweep` gathers each run's row beside its settings (name, status, seconds and message are the sweep's own "
          "columns, not a result's).",
      .form = Form::call,
      .positional =
          {
              {"values", Type::table, "", any_value, kRequired,
               "key = value for each result (a number, a string or a boolean)"},
          },
      .run = run_result,
      .usage = "result{ cracks = info().cracks, crown = gp_near(0, 5).uy }",
  };
  return command;
}

}  // namespace edem
