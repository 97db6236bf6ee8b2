// Raising a command's error in Lua with the script position and the command name.
#include "adaptor.hpp"

#include <lua.hpp>
#include <cstdio>
#include <stdexcept>

#include "context.hpp"
#include "lua_util.hpp"

namespace edem {

namespace {

[[noreturn]] void raise(lua_State* L, const std::string& text, std::vector<std::string> frames) {
  // Remembered so that the runner prints it as is rather than as a plain Lua error.
  Context& context = context_of(L);
  context.last_command_error = text;
  context.last_error_frames = std::move(frames);
  lua_pushlstring(L, text.data(), text.size());
  lua_error(L);
  throw std::logic_error("lua_error returned");  // unreachable: keeps [[noreturn]] honest
}

}  // namespace

void raise_error(lua_State* L, std::string_view name, std::string_view message) {
  std::string text = where(L);
  text.append(name).append(": ").append(message);
  raise(L, text, {});
}

namespace {
void say_once(lua_State* L, std::string_view name, std::string_view kind, std::string_view message, FILE* to) {
  Context& context = context_of(L);
  std::string text = where(L);
  text.append(name).append(": ").append(kind).append(message);
  if (!context.said.insert(text).second) return;
  context.close_progress_line();
  std::fflush(stdout);  // in order with what the script printed
  std::fprintf(to, "%s\n", text.c_str());
}
}  // namespace

void warn(lua_State* L, std::string_view name, std::string_view message) {
  say_once(L, name, "warning: ", message, stderr);
}

void note(lua_State* L, std::string_view name, std::string_view message) {
  if (!context_of(L).quiet) say_once(L, name, "", message, stdout);
}

void raise_callback_error(lua_State* L, std::string_view message, std::vector<std::string> frames) {
  raise(L, std::string(message), std::move(frames));
}

}  // namespace edem
