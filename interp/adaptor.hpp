// The one place where C++ exceptions become Lua errors.
//
// Lua is built as C++ here, so lua_error throws and Lua's pcall catches everything: a C++
// exception escaping a C function would surface as an anonymous error. Every Lua-facing
// function therefore runs its body through guarded(), which catches edem::Error and any
// std::exception (bad_alloc included) and raises "FILE:LINE: name: message" as a Lua error
// after leaving the catch block. Lua's own errors pass through untouched. Nothing else catches.
#pragma once

#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "core/error.hpp"

struct lua_State;

namespace edem {

// Raises "FILE:LINE: name: message" (the position of the calling script line) as a Lua error.
[[noreturn]] void raise_error(lua_State* L, std::string_view name, std::string_view message);

// Runs `body` (returning its number of Lua results); an exception becomes a Lua error
// attributed to `name`, the command or iterator the user called.
template <typename Body>
int guarded(lua_State* L, std::string_view name, Body&& body) {
  std::string message;
  try {
    return body();
  } catch (const Error& e) {
    message = e.what();
  } catch (const std::bad_alloc&) {
    message = "out of memory";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
  }
  raise_error(L, name, message);  // outside the handlers: lua_error throws
}

}  // namespace edem
