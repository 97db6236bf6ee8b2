// Small Lua helpers shared by the commands and the runner: script positions, describing a
// value in a message, pushing points and fields.
#pragma once

#include <string>
#include <string_view>

#include "core/vec2.hpp"

struct lua_State;
struct lua_Debug;

namespace edem {

// The file of a stack frame as the user wrote it: the path given for files (never Lua's
// shortened "..." form), else Lua's short source.
std::string source_of(const lua_Debug& frame);

// "FILE:LINE: " of the innermost Lua frame on the stack, skipping C functions; "" if none.
std::string where(lua_State* L);

// How many levels the call stack of `L` has (level 0, the running function, included). Found by
// halving, as Lua's own traceback does: lua_getstack walks from the top, so counting level by
// level would be quadratic in a deep recursion's hundreds of thousands of frames.
int stack_levels(lua_State* L);

// A value as an error message shows it after "got": 5, "abc", true, nil, a table.
std::string describe(lua_State* L, int index);

// Pushes a point as {x = , y = , [1] = x, [2] = y}, so both p.x and p[1] work and any
// command accepts it back as a point.
void push_point(lua_State* L, Vec2 point);

// t[key] = value for the table on top of the stack.
void set_field(lua_State* L, const char* key, double value);
void set_field(lua_State* L, const char* key, long long value);
void set_field(lua_State* L, const char* key, int value);
void set_field(lua_State* L, const char* key, std::string_view value);

}  // namespace edem
