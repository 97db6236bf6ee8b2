// Small Lua helpers: positions, value descriptions, pushing points and fields.
#include "lua_util.hpp"

#include <fmt/format.h>

#include <lua.hpp>

#include "schema.hpp"

namespace edem {

std::string source_of(const lua_Debug& frame) {
  if (frame.source != nullptr && frame.source[0] == '@') return frame.source + 1;
  return frame.short_src;
}

std::string where(lua_State* L) {
  lua_Debug frame;
  for (int level = 1; lua_getstack(L, level, &frame); ++level) {
    lua_getinfo(L, "Sl", &frame);
    if (frame.currentline > 0) return fmt::format("{}:{}: ", source_of(frame), frame.currentline);
  }
  return {};
}

int stack_levels(lua_State* L) {
  lua_Debug frame;
  int known = 0, beyond = 1;  // level `known` exists, level `beyond` is to be tried
  while (lua_getstack(L, beyond, &frame)) {
    known = beyond;
    beyond *= 2;
  }
  while (known + 1 < beyond) {  // level known exists, level beyond does not
    const int middle = known + (beyond - known) / 2;
    (lua_getstack(L, middle, &frame) ? known : beyond) = middle;
  }
  return lua_getstack(L, 0, &frame) ? known + 1 : 0;
}

std::string describe(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, index)) return std::to_string(lua_tointeger(L, index));
      return show_number(lua_tonumber(L, index));
    case LUA_TBOOLEAN:
      return lua_toboolean(L, index) ? "true" : "false";
    case LUA_TSTRING: {
      // Long strings are cut: the message must stay one readable line.
      std::string_view text = lua_tostring(L, index);
      if (text.size() > 40) return fmt::format("\"{}...\"", text.substr(0, 37));
      return fmt::format("\"{}\"", text);
    }
    case LUA_TNIL:
    case LUA_TNONE:
      return "nil";
    default:
      return fmt::format("a {}", luaL_typename(L, index));
  }
}

void push_point(lua_State* L, Vec2 point) {
  lua_createtable(L, 2, 2);
  set_field(L, "x", point.x);
  set_field(L, "y", point.y);
  lua_pushnumber(L, point.x);
  lua_rawseti(L, -2, 1);
  lua_pushnumber(L, point.y);
  lua_rawseti(L, -2, 2);
}

void set_field(lua_State* L, const char* key, double value) {
  lua_pushnumber(L, value);
  lua_setfield(L, -2, key);
}

void set_field(lua_State* L, const char* key, long long value) {
  lua_pushinteger(L, static_cast<lua_Integer>(value));
  lua_setfield(L, -2, key);
}

void set_field(lua_State* L, const char* key, int value) {
  set_field(L, key, static_cast<long long>(value));
}

void set_field(lua_State* L, const char* key, std::string_view value) {
  lua_pushlstring(L, value.data(), value.size());
  lua_setfield(L, -2, key);
}

}  // namespace edem
