// Error messages: the headline "FILE:LINE: word: message" and the traceback.
#include "errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/names.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// Registry keys of Lua's own error() and assert(): errors they raise are the script's own.
constexpr const char* kErrorKey = "edem.error";
constexpr const char* kAssertKey = "edem.assert";

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

}  // namespace

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

void remember_error_functions(lua_State* L) {
  for (const auto& [name, key] : {std::pair{"error", kErrorKey}, {"assert", kAssertKey}}) {
    lua_getglobal(L, name);
    lua_setfield(L, LUA_REGISTRYINDEX, key);
  }
}

std::string error_headline(lua_State* L) {
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

std::vector<std::string> traceback_lines(lua_State* L, int first, int last) {
  const int deepest = stack_levels(L) - 1;
  if (last < 0 || last > deepest) last = deepest;
  // A deep recursion (a stack overflow has hundreds of thousands of frames) shows its first and
  // last frames, as format_traceback() would keep them: each lua_getstack walks from the top,
  // so walking every level would be quadratic.
  constexpr int kHead = 8, kTail = 3;
  const bool cut = last - first + 1 > kHead + kTail;
  std::vector<std::string> lines;
  lua_Debug frame;
  for (int level = first; level <= last && lua_getstack(L, level, &frame); ++level) {
    if (cut && level == first + kHead) {
      lines.push_back(fmt::format("  ... ({} more)", last - kTail - level + 1));
      level = last - kTail;
      continue;
    }
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
  return lines;
}

std::string format_traceback(std::vector<std::string> lines) {
  if (lines.size() < 2) return {};
  constexpr size_t head = 8, tail = 3;  // deep recursion: the ends tell the story
  if (lines.size() > head + tail + 1) {
    size_t hidden = 0;  // the lines left out, and those a cut among them stands for
    for (auto line = lines.begin() + head; line != lines.end() - tail; ++line) {
      size_t more = 0;
      hidden += std::sscanf(line->c_str(), "  ... (%zu more)", &more) == 1 ? more : 1;
    }
    lines.erase(lines.begin() + head, lines.end() - tail);
    lines.insert(lines.begin() + head, fmt::format("  ... ({} more)", hidden));
  }
  return fmt::format("\ntraceback:\n{}", fmt::join(lines, "\n"));
}

// Runs where the error happened, stack intact. A callback's error carries the frames of the
// callback (gone by now) to show above those of the command that ran it.
int message_handler(lua_State* L) {
  std::string text;
  try {
    const Context& context = context_of(L);
    text = error_headline(L);
    std::vector<std::string> lines;
    if (text == context.last_command_error) lines = context.last_error_frames;
    const auto here = traceback_lines(L, 1);
    lines.insert(lines.end(), here.begin(), here.end());
    text += format_traceback(std::move(lines));
  } catch (const std::exception&) {
    lua_settop(L, 1);  // formatting failed (out of memory): keep Lua's own message
    return 1;
  }
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

}  // namespace edem
