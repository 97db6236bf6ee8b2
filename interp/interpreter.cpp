// The Lua state, running a script, and turning whatever stops it into one clear message.
#include "interpreter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <lua.hpp>

#include "commands.hpp"
#include "core/names.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

// Registry keys of Lua's own error() and assert(): errors they raise are the script's own.
constexpr const char* kErrorKey = "edem.error";
constexpr const char* kAssertKey = "edem.assert";

// A message "SOURCE:LINE: text" taken apart.
struct Located {
  std::string source, line, text;
};

std::optional<Located> split_position(std::string_view message) {
  for (size_t colon = message.find(':'); colon != std::string_view::npos;
       colon = message.find(':', colon + 1)) {
    size_t end = colon + 1;
    while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
    if (end > colon + 1 && message.substr(end, 2) == ": ")
      return Located{std::string(message.substr(0, colon)),
                     std::string(message.substr(colon + 1, end - colon - 1)),
                     std::string(message.substr(end + 2))};
  }
  return std::nullopt;
}

// Lua shortens long file names to "...tail"; give back the path the user wrote.
std::string full_source(lua_State* L, const std::string& source) {
  if (source.rfind("...", 0) != 0) return source;
  lua_Debug frame;
  for (int level = 1; lua_getstack(L, level, &frame); ++level) {
    lua_getinfo(L, "S", &frame);
    if (source == frame.short_src) return source_of(frame);
  }
  return source;
}

// True when the function that raised the error (stack level 1) is error() or assert().
bool raised_by_script(lua_State* L) {
  lua_Debug frame;
  if (!lua_getstack(L, 1, &frame)) return false;
  lua_getinfo(L, "f", &frame);
  lua_getfield(L, LUA_REGISTRYINDEX, kErrorKey);
  lua_getfield(L, LUA_REGISTRYINDEX, kAssertKey);
  const bool own = lua_rawequal(L, -3, -2) || lua_rawequal(L, -3, -1);
  lua_pop(L, 3);
  return own;
}

// The names of the global functions: the commands first (a tie goes to a command), then
// Lua's own and the script's, sorted so the hint never depends on hash order.
std::vector<std::string> global_functions(lua_State* L) {
  std::vector<std::string> names;
  for (const Command* command : commands()) names.emplace_back(command->name);
  const auto first_other = static_cast<std::ptrdiff_t>(names.size());
  lua_pushglobaltable(L);
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_isfunction(L, -1))
      names.emplace_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  std::sort(names.begin() + first_other, names.end());
  return names;
}

// "blok" from Lua's "attempt to call a nil value (global 'blok')".
std::optional<std::string> called_undefined(std::string_view text) {
  constexpr std::string_view head = "attempt to call a nil value (global '";
  if (text.rfind(head, 0) != 0 || text.size() < head.size() + 2 || !text.ends_with("')"))
    return std::nullopt;
  return std::string(text.substr(head.size(), text.size() - head.size() - 2));
}

std::string error_text(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING || lua_type(L, 1) == LUA_TNUMBER) return lua_tostring(L, 1);
  if (luaL_getmetafield(L, 1, "__tostring") != LUA_TNIL) {
    lua_pop(L, 1);
    std::string text = luaL_tolstring(L, 1, nullptr);
    lua_pop(L, 1);
    return text;
  }
  return fmt::format("(error object is a {} value)", luaL_typename(L, 1));
}

// The first line: "FILE:LINE: word: message".
std::string headline(lua_State* L) {
  std::string message = error_text(L);
  const std::string& command_error = context_of(L).last_command_error;
  if (message == command_error) return message;
  const auto located = split_position(message);
  // coroutine.wrap re-raises with its own position in front: the command's error is inside.
  if (located && located->text == command_error) return command_error;
  const bool own = raised_by_script(L);
  std::string location, text;
  if (located) {
    location = full_source(L, located->source) + ":" + located->line;
    text = located->text;
  } else {
    location = where(L);  // error("x", 0), assert(false), error objects: where it was raised
    location = location.empty() ? "?" : location.substr(0, location.size() - 2);
    text = message;
  }
  if (!own) {
    if (const auto name = called_undefined(text))
      return fmt::format("{}: {}: unknown command{}", location, *name,
                         did_you_mean(*name, global_functions(L)));
  }
  return fmt::format("{}: {}: {}", location, own ? "error" : "lua", text);
}

// "\ntraceback:\n  FILE:LINE: in function 'f'\n  ..." when the error is inside a function.
std::string traceback(lua_State* L) {
  std::vector<std::string> lines;
  lua_Debug frame;
  for (int level = 1; lua_getstack(L, level, &frame); ++level) {
    lua_getinfo(L, "Sln", &frame);
    if (frame.currentline <= 0) continue;  // C functions: the command itself, pcall, ...
    std::string what;
    if (std::strcmp(frame.what, "main") == 0)
      what = "main chunk";
    else if (frame.name != nullptr)
      what = fmt::format("function '{}'", frame.name);
    else
      what = fmt::format("function <{}:{}>", source_of(frame), frame.linedefined);
    lines.push_back(fmt::format("  {}:{}: in {}", source_of(frame), frame.currentline, what));
  }
  if (lines.size() < 2) return {};
  constexpr size_t head = 8, tail = 3;  // deep recursion: the ends tell the story
  if (lines.size() > head + tail + 1) {
    const size_t hidden = lines.size() - head - tail;
    lines.erase(lines.begin() + head, lines.end() - tail);
    lines.insert(lines.begin() + head, fmt::format("  ... ({} more)", hidden));
  }
  return fmt::format("\ntraceback:\n{}", fmt::join(lines, "\n"));
}

// The message handler of the script's pcall: runs where the error happened, stack intact.
int message_handler(lua_State* L) {
  std::string text;
  try {
    text = headline(L) + traceback(L);
  } catch (const std::exception&) {
    lua_settop(L, 1);  // formatting failed (out of memory): keep Lua's own message
    return 1;
  }
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

// "dir/?.lua;dir/?/init.lua;" for each directory, in order.
std::string search_path(const std::vector<std::string>& dirs) {
  std::string path;
  for (const auto& dir : dirs) path += fmt::format("{0}/?.lua;{0}/?/init.lua;", dir);
  return path;
}

std::string package_path(lua_State* L) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  std::string path = lua_tostring(L, -1);
  lua_pop(L, 2);
  return path;
}

void set_package_path(lua_State* L, const std::string& path) {
  lua_getglobal(L, "package");
  lua_pushlstring(L, path.data(), path.size());
  lua_setfield(L, -2, "path");
  lua_pop(L, 1);
}

// "FILE:LINE: syntax: message" from the parser's "SOURCE:LINE: message".
std::string load_error(int status, const std::string& path, const std::string& message) {
  if (status == LUA_ERRSYNTAX) {
    if (const auto located = split_position(message))
      return fmt::format("{}:{}: syntax: {}", path, located->line, located->text);
    return fmt::format("{}:0: syntax: {}", path, message);
  }
  if (status == LUA_ERRMEM) return fmt::format("{}: memory: not enough memory", path);
  return fmt::format("edem: {}", message);
}

}  // namespace

Interpreter::Interpreter(InterpreterOptions options)
    : state_(luaL_newstate(), lua_close), L_(state_.get()) {
  if (L_ == nullptr) throw std::bad_alloc();
  context_.quiet = options.quiet;
  attach(L_, context_);
  luaL_openlibs(L_);
  for (const auto& [name, key] : {std::pair{"error", kErrorKey}, {"assert", kAssertKey}}) {
    lua_getglobal(L_, name);
    lua_setfield(L_, LUA_REGISTRYINDEX, key);
  }
  register_commands(L_);
  std::vector<std::string> dirs = options.stdlib_dirs;
  dirs.emplace_back(EDEM_STDLIB_DIR);
  stdlib_path_ = search_path(dirs);
  lua_path_ = package_path(L_);
  set_package_path(L_, stdlib_path_ + lua_path_);
}

Interpreter::~Interpreter() = default;

std::optional<std::string> Interpreter::run_file(const std::string& path,
                                                 const std::vector<std::string>& args) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return fmt::format("edem: '{}' is a directory, not a script", path);
  if (std::FILE* file = std::fopen(path.c_str(), "r"))
    std::fclose(file);
  else
    return fmt::format("edem: cannot open '{}': {}", path, std::strerror(errno));

  // Modules next to the script come after the stdlib and before Lua's defaults.
  const fs::path dir = fs::path(path).parent_path();
  const std::string script_path = search_path({dir.empty() ? std::string(".") : dir.string()});
  set_package_path(L_, stdlib_path_ + script_path + lua_path_);
  lua_settop(L_, 0);
  lua_pushcfunction(L_, message_handler);
  const int status = luaL_loadfile(L_, path.c_str());
  if (status == LUA_OK) {
    if (!lua_checkstack(L_, static_cast<int>(args.size()) + 2))
      return fmt::format("edem: too many arguments for '{}'", path);
    lua_createtable(L_, static_cast<int>(args.size()), 1);  // arg, as the lua program sets it
    lua_pushstring(L_, path.c_str());
    lua_rawseti(L_, -2, 0);
    for (size_t i = 0; i < args.size(); ++i) {
      lua_pushstring(L_, args[i].c_str());
      lua_rawseti(L_, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setglobal(L_, "arg");
    for (const auto& a : args) lua_pushstring(L_, a.c_str());
  }
  return run_loaded(status, path, static_cast<int>(args.size()));
}

std::optional<std::string> Interpreter::run_string(std::string_view code, const std::string& name) {
  lua_settop(L_, 0);
  lua_pushcfunction(L_, message_handler);
  const std::string chunk = "@" + name;
  const int status = luaL_loadbuffer(L_, code.data(), code.size(), chunk.c_str());
  return run_loaded(status, name, 0);
}

std::optional<std::string> Interpreter::run_loaded(int status, const std::string& path, int nargs) {
  if (status != LUA_OK) {
    const char* text = lua_tostring(L_, -1);
    std::string message = text != nullptr ? text : "(no message)";
    lua_settop(L_, 0);
    return load_error(status, path, message);
  }
  status = lua_pcall(L_, nargs, 0, 1);
  if (status == LUA_OK) {
    lua_settop(L_, 0);
    return std::nullopt;
  }
  std::string message;
  if (status == LUA_ERRMEM)
    message = fmt::format("{}: memory: not enough memory", path);
  else if (lua_type(L_, -1) == LUA_TSTRING)
    message = lua_tostring(L_, -1);
  else
    message = fmt::format("{}: lua: error while reporting an error", path);
  lua_settop(L_, 0);
  return message;
}

}  // namespace edem
