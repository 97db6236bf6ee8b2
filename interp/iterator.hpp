// Iterators over model items for `for x in things() do ... end`.
#pragma once

#include <lua.hpp>

#include "context.hpp"
#include "adaptor.hpp"

namespace edem {

// One step of an iterator closure: upvalue 1 is the 0-based position of the next item;
// count(model) says how many there are, keep(L, model, i) whether item i is given (the others
// are passed over without building anything), push(L, model, i) pushes item i.
template <typename Count, typename Keep, typename Push>
int iterator_step(lua_State* L, const char* name, Count&& count, Keep&& keep, Push&& push) {
  return guarded(L, name, [&] {
    const Model& model = context_of(L).model();
    const size_t total = count(model);
    auto next = static_cast<size_t>(lua_tointeger(L, lua_upvalueindex(1)));
    while (next < total && !keep(L, model, next)) ++next;
    if (next >= total) return 0;
    lua_pushinteger(L, static_cast<lua_Integer>(next + 1));
    lua_replace(L, lua_upvalueindex(1));
    push(L, model, next);
    return 1;
  });
}

template <typename Count, typename Push>
int iterator_step(lua_State* L, const char* name, Count&& count, Push&& push) {
  return iterator_step(L, name, count, [](lua_State*, const Model&, size_t) { return true; }, push);
}

}  // namespace edem
