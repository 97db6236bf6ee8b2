// Turning whatever stops a script into one clear message: "FILE:LINE: word: message", then a
// short traceback when the error happened inside a function.
//
// The word is the command that failed (`jset: spacing must be > 0, got -2`), or `syntax`, `lua`
// (a Lua runtime error), `error` (the script's own error() or assert()); an unknown global
// function becomes `blok: unknown command (did you mean 'block'?)`. Used by the runner's
// pcall and by the pcall around Lua functions that the model calls back (callbacks.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct lua_State;

namespace edem {

// Remembers Lua's error() and assert() so that errors they raise count as the script's own.
// Call once, after the standard libraries are open.
void remember_error_functions(lua_State* L);

// The first line for the error object at index 1, in a message handler (the stack where the
// error happened is intact).
std::string error_headline(lua_State* L);

// "  FILE:LINE: in function 'f'" for the Lua frames at stack levels first..last (last < 0:
// all), innermost first; C functions are left out.
std::vector<std::string> traceback_lines(lua_State* L, int first, int last = -1);

// "\ntraceback:\n" and the lines (long ones shortened in the middle), or "" for fewer than two.
std::string format_traceback(std::vector<std::string> lines);

// The message handler of the runner's pcall: the headline and the traceback as one string.
int message_handler(lua_State* L);

// "FILE:LINE: text" taken apart; nothing if the message has no position.
struct Located {
  std::string source, line, text;
};
std::optional<Located> split_position(std::string_view message);

}  // namespace edem
