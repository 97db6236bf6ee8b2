// Raising a command's error in Lua with the script position and the command name.
#include "adaptor.hpp"

#include <lua.hpp>
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

void raise_callback_error(lua_State* L, std::string_view message, std::vector<std::string> frames) {
  raise(L, std::string(message), std::move(frames));
}

}  // namespace edem
