// A script's settings: settings{} declares the keys `--set KEY=VALUE` may give, with their
// defaults, and out_dir() tells where --out puts the files commands write.
#include <fmt/format.h>

#include <algorithm>
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
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

}  // namespace edem
