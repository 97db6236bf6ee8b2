// Reaching the Context from a lua_State: a pointer in the state's extra space.
#include "context.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <lua.hpp>

namespace edem {

static_assert(LUA_EXTRASPACE >= sizeof(Context*), "the Context pointer must fit");

void attach(lua_State* L, Context& context) {
  *static_cast<Context**>(lua_getextraspace(L)) = &context;
}

Context& context_of(lua_State* L) {
  return **static_cast<Context**>(lua_getextraspace(L));
}

void Context::close_progress_line() {
  if (!progress_line_open) return;
  std::fputs("\r\033[K", stdout);  // back to the line's start, erase it
  std::fflush(stdout);
  progress_line_open = false;
}

void Context::say_run_notice(const std::string& text) {
  if (quiet) return;
  close_progress_line();
  const Running* run = cycling();
  std::string at = "edem: ";
  if (run != nullptr) at = run->cycling_at + ": " + std::string(run->command) + ": ";
  std::fflush(stdout);  // in order with what the script printed
  std::fprintf(stderr, "%snote: %s\n", at.c_str(), text.c_str());
}

std::string Context::output_path(const std::string& file) const {
  const std::filesystem::path path(file);
  if (out_dir.empty() || path.is_absolute()) return file;
  return (std::filesystem::path(out_dir) / path).string();
}

}  // namespace edem
