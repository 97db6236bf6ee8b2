// Reaching the Context from a lua_State: a pointer in the state's extra space.
#include "context.hpp"

#include <lua.hpp>

namespace edem {

static_assert(LUA_EXTRASPACE >= sizeof(Context*), "the Context pointer must fit");

void attach(lua_State* L, Context& context) {
  *static_cast<Context**>(lua_getextraspace(L)) = &context;
}

Context& context_of(lua_State* L) {
  return **static_cast<Context**>(lua_getextraspace(L));
}

}  // namespace edem
