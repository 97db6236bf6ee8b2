// Raising a command's error in Lua with the script position and the command name.
#include "adaptor.hpp"

#include <lua.hpp>
#include <stdexcept>

#include "context.hpp"
#include "lua_util.hpp"

namespace edem {

void raise_error(lua_State* L, std::string_view name, std::string_view message) {
  std::string text = where(L);
  text.append(name).append(": ").append(message);
  // Remembered so that the runner prints it as is rather than as a plain Lua error.
  context_of(L).last_command_error = text;
  lua_pushlstring(L, text.data(), text.size());
  lua_error(L);
  throw std::logic_error("lua_error returned");  // unreachable: keeps [[noreturn]] honest
}

}  // namespace edem
