// The one place where C++ exceptions become Lua errors.
//
// Lua is built as C++ here, so lua_error throws and Lua's pcall catches everything: a C++
// exception escaping a C function would surface as an anonymous error. Every Lua-facing
// function therefore runs its body through guarded(), which catches edem::Error and any
// std::exception (bad_alloc included) and raises "FILE:LINE: name: message" as a Lua error
// after leaving the catch block. Lua's own errors pass through untouched. Nothing else catches.
//
// A Lua function that the engine calls back (an every() callback, a history fn) runs in its
// own pcall; its failure comes back through the engine as a CallbackError, whose message is
// already complete and is raised as it is.
#pragma once

#include <exception>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"

struct lua_State;

namespace edem {

// A Lua function called back from the engine failed: `what()` is the whole first line,
// "FILE:LINE: word: message" at the callback's own line; `frames` the traceback lines of the
// callback, whose Lua frames have unwound by the time the error reaches guarded().
class CallbackError : public Error {
 public:
  CallbackError(const std::string& message, std::vector<std::string> callback_frames)
      : Error(message), frames(std::move(callback_frames)) {}
  std::vector<std::string> frames;
};

// Raises "FILE:LINE: name: message" (the position of the calling script line) as a Lua error.
[[noreturn]] void raise_error(lua_State* L, std::string_view name, std::string_view message);

// Says "FILE:LINE: name: warning: message" on stderr, once for each such line: the command ran,
// but what it did is likely not what the script meant.
void warn(lua_State* L, std::string_view name, std::string_view message);
// Says "FILE:LINE: name: message" on stdout (none with --quiet), once for each such line.
void note(lua_State* L, std::string_view name, std::string_view message);

// Raises a CallbackError's message as it is, keeping its frames for the traceback.
[[noreturn]] void raise_callback_error(lua_State* L, std::string_view message,
                                       std::vector<std::string> frames);

// Runs `body` (returning its number of Lua results); an exception becomes a Lua error
// attributed to `name`, the command or iterator the user called.
template <typename Body>
int guarded(lua_State* L, std::string_view name, Body&& body) {
  std::string message;
  std::vector<std::string> frames;
  bool from_callback = false;
  try {
    return body();
  } catch (const CallbackError& e) {
    message = e.what();
    frames = e.frames;
    from_callback = true;
  } catch (const Error& e) {
    message = e.what();
  } catch (const std::bad_alloc&) {
    message = "out of memory";
  } catch (const std::exception& e) {
    message = std::string("internal error: ") + e.what();
  }
  // Outside the handlers: lua_error throws.
  if (from_callback) raise_callback_error(L, message, std::move(frames));
  raise_error(L, name, message);
}

}  // namespace edem
