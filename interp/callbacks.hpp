// Lua functions that the model keeps and calls back between cycles: every() callbacks and
// history fns.
//
// Each is a std::function holding a shared reference to the Lua function in the registry;
// the reference is released when the engine drops the last copy (cancel(), a new model{},
// the interpreter closing), never after the Lua state is closed. A call runs in a pcall on
// the thread of the command executing now (Context::running), so it never touches a
// suspended coroutine. A failure unwinds the engine as a CallbackError that names the line
// inside the function that failed and the command that was cycling:
//
//   test.lua:7: every: error in the callback (while cycle() at test.lua:12 was running): ...
//
// and its traceback shows the callback's frames above those of the cycling command.
#pragma once

#include <functional>
#include <string>

#include "core/physics_defs.hpp"

struct lua_State;

namespace edem {

// every(n, f): the function at `index` called as f(cycle) with the cycle number.
std::function<void(long cycle)> lua_callback(lua_State* L, int index);

// history{ name = , fn = f }: the function at `index` called as f(), which must return a
// number. `name` is the history's name for messages.
std::function<double()> lua_sampler(lua_State* L, int index, const std::string& name);

// judge{ criterion = f }: the function at `index` called as f(section) with a read-only view of
// an intact section; it returns nil, "shear" or "tension" (anything else is an error that
// names the function's definition). One view is made once and refilled for every call (a
// table per call would cost more than the criterion): it is valid during the call only.
std::function<CrackMode(const SectionView&)> lua_criterion(lua_State* L, int index);

// Pushes a read-only table of a section (the criterion's argument, and sections()): an empty
// proxy whose metatable's __index holds the fields.
void push_section(lua_State* L, const SectionView& section);
// Sets the fields of a section on the table at the top of the stack.
void set_section_fields(lua_State* L, const SectionView& section);

}  // namespace edem
