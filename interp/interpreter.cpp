// The Lua state, running a script, and writing the histories nobody wrote at its end.
#include "interpreter.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <lua.hpp>
#include <unistd.h>

#include "adaptor.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "errors.hpp"
#include "progress_line.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

// "dir/?.lua;dir/?/init.lua;" for each directory, in order.
std::string search_path(const std::vector<std::string>& dirs) {
  std::string path;
  for (const auto& dir : dirs) path += fmt::format("{0}/?.lua;{0}/?/init.lua;", dir);
  return path;
}

std::string package_path(lua_State* L) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  std::string path = lua_tostring(L, -1);
  lua_pop(L, 2);
  return path;
}

void set_package_path(lua_State* L, const std::string& path) {
  lua_getglobal(L, "package");
  lua_pushlstring(L, path.data(), path.size());
  lua_setfield(L, -2, "path");
  lua_pop(L, 1);
}

// Writes the current model's histories to the file at index 1 (the end-of-run write).
int write_histories_at_end(lua_State* L) {
  return guarded(L, "history", [&] {
    Context& context = context_of(L);
    const std::string file = lua_tostring(L, 1);
    context.model().write_histories(file);
    context.histories_written = true;
    if (!context.quiet) {
      const size_t count = context.model().histories().size();
      fmt::print("history: {} histor{} written to {}\n", count, count == 1 ? "y" : "ies", file);
    }
    return 0;
  });
}

// A progress line: on a terminal one line rewritten in place, otherwise a plain line.
void show_progress(Context& context, bool terminal, const std::string& line) {
  if (terminal) {
    fmt::print("\r{}\033[K", line);
    context.progress_line_open = true;
  } else {
    fmt::print("{}\n", line);
  }
  std::fflush(stdout);
}

// The progress lines of cycling and of the prepass.
void start_progress(Context& context, const InterpreterOptions& options) {
  if (options.quiet || options.progress_seconds == 0.0) return;
  const bool terminal = ::isatty(::fileno(stdout)) != 0;
  context.progress_every = options.progress_seconds > 0.0 ? options.progress_seconds : terminal ? 0.5 : 10.0;
  context.progress = [&context, terminal, last = RunProgress{}](const RunProgress& p) mutable {
    if (context.quiet) return;  // quiet set after the start (tests, embedding) silences it too
    if (p.run_cycles < last.run_cycles || last.seconds > p.seconds) last = RunProgress{};  // a new run
    show_progress(context, terminal, progress_line(last, p));
    last = p;
  };
  context.prepass_progress = [&context, terminal](const PrepassProgress& p) {
    if (!context.quiet) show_progress(context, terminal, prepass_progress_line(p));
  };
}

// A --set value as Lua reads it: a number when the whole text is one, true or false, else the
// text itself (so `--set depth=158` gives arg.depth == 158, a number).
void push_setting(lua_State* L, const std::string& value) {
  if (value == "true" || value == "false") {
    lua_pushboolean(L, value == "true");
    return;
  }
  if (!value.empty() && lua_stringtonumber(L, value.c_str()) == value.size() + 1) return;
  lua_pushlstring(L, value.data(), value.size());
}

// "FILE:LINE: syntax: message" from the parser's "SOURCE:LINE: message".
std::string load_error(int status, const std::string& path, const std::string& message) {
  if (status == LUA_ERRSYNTAX) {
    if (const auto located = split_position(message))
      return fmt::format("{}:{}: syntax: {}", path, located->line, located->text);
    return fmt::format("{}:0: syntax: {}", path, message);
  }
  if (status == LUA_ERRMEM) return fmt::format("{}: memory: not enough memory", path);
  return fmt::format("edem: {}", message);
}

// Notes the running script line every kPositionEvery Lua instructions (a fraction of a percent of
// a pure-Lua loop's time).
constexpr int kPositionEvery = 10000;

void note_position(lua_State* L, lua_Debug* ar) {
  if (lua_getinfo(L, "Sl", ar) == 0 || ar->currentline <= 0 || ar->source[0] != '@') return;
  Context& context = context_of(L);
  if (context.recent_source != ar->source + 1) context.recent_source = ar->source + 1;
  context.recent_line = ar->currentline;
}

// Lua's out-of-memory error, at the line the script was running near when it ran out.
std::string out_of_memory(const Context& context, const std::string& path) {
  if (context.recent_line <= 0) return fmt::format("{}: memory: not enough memory", path);
  return fmt::format("{}:{}: memory: not enough memory (the script ran out of it near this line)",
                     context.recent_source, context.recent_line);
}

}  // namespace

Interpreter::Interpreter(InterpreterOptions options)
    : state_(luaL_newstate(), lua_close), L_(state_.get()) {
  if (L_ == nullptr) throw std::bad_alloc();
  context_.quiet = options.quiet;
  context_.threads = options.threads;
  context_.out_dir = options.out_dir;
  start_progress(context_, options);
  settings_ = options.settings;
  context_.settings = options.settings;
  context_.stop = options.stop;
  context_.probe = options.probe;
  context_.lua = L_;
  attach(L_, context_);
  lua_sethook(L_, note_position, LUA_MASKCOUNT, kPositionEvery);
  luaL_openlibs(L_);
  remember_error_functions(L_);
  register_commands(L_);
  std::vector<std::string> dirs = options.stdlib_dirs;
  dirs.emplace_back(EDEM_STDLIB_DIR);
  stdlib_path_ = search_path(dirs);
  lua_path_ = package_path(L_);
  set_package_path(L_, stdlib_path_ + lua_path_);
}

Interpreter::~Interpreter() {
  // The model holds references to Lua functions: release them while the state is open. A
  // model made while the state closes (a __gc calling a command) keeps its references.
  context_.current.reset();
  state_.reset();
  context_.lua = nullptr;
}

std::optional<std::string> Interpreter::run_file(const std::string& path,
                                                 const std::vector<std::string>& args) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return fmt::format("edem: '{}' is a directory, not a script", path);
  if (std::FILE* file = std::fopen(path.c_str(), "r"))
    std::fclose(file);
  else
    return fmt::format("edem: cannot open '{}': {}", path, std::strerror(errno));

  {
    std::ifstream in(path, std::ios::binary);
    context_.script_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    context_.script_path = path;
  }
  // Modules next to the script come after the stdlib and before Lua's defaults.
  const fs::path dir = fs::path(path).parent_path();
  const std::string script_path = search_path({dir.empty() ? std::string(".") : dir.string()});
  set_package_path(L_, stdlib_path_ + script_path + lua_path_);
  lua_settop(L_, 0);
  lua_pushcfunction(L_, message_handler);
  const int status = luaL_loadfile(L_, path.c_str());
  if (status == LUA_OK) {
    if (!lua_checkstack(L_, static_cast<int>(args.size()) + 2))
      return fmt::format("edem: too many arguments for '{}'", path);
    lua_createtable(L_, static_cast<int>(args.size()), 1);  // arg, as the lua program sets it
    lua_pushstring(L_, path.c_str());
    lua_rawseti(L_, -2, 0);
    for (size_t i = 0; i < args.size(); ++i) {
      lua_pushstring(L_, args[i].c_str());
      lua_rawseti(L_, -2, static_cast<lua_Integer>(i + 1));
    }
    for (const auto& [key, value] : settings_) {
      push_setting(L_, value);
      lua_setfield(L_, -2, key.c_str());
    }
    lua_setglobal(L_, "arg");
    for (const auto& a : args) lua_pushstring(L_, a.c_str());
  }
  if (auto error = run_loaded(status, path, static_cast<int>(args.size()))) return error;
  if (auto error = write_stage_frames_at_end(path)) return error;
  return write_pending_histories(path);
}

std::optional<std::string> Interpreter::write_stage_frames_at_end(const std::string& path) {
  if (context_.stage_outputs.empty() || !context_.current) return std::nullopt;
  try {
    context_.write_stage_frames();
  } catch (const Error& e) {
    return fmt::format("{}: output at the end of the script: {}", path, e.what());
  }
  return std::nullopt;
}

std::optional<std::string> Interpreter::write_pending_histories(const std::string& path) {
  if (!context_.current || context_.current->histories().empty() || context_.histories_written)
    return std::nullopt;
  const std::string file = context_.output_path(fs::path(path).stem().string() + "_history.csv");
  lua_settop(L_, 0);
  lua_pushcfunction(L_, message_handler);
  lua_pushcfunction(L_, write_histories_at_end);
  lua_pushlstring(L_, file.data(), file.size());
  std::optional<std::string> error = run_loaded(LUA_OK, path, 1);
  if (error) error = fmt::format("{}: {}", path, *error);  // no script line is running
  return error;
}

std::optional<std::string> Interpreter::run_string(std::string_view code, const std::string& name) {
  lua_settop(L_, 0);
  lua_pushcfunction(L_, message_handler);
  const std::string chunk = "@" + name;
  const int status = luaL_loadbuffer(L_, code.data(), code.size(), chunk.c_str());
  return run_loaded(status, name, 0);
}

std::optional<std::string> Interpreter::run_loaded(int status, const std::string& path, int nargs) {
  if (status != LUA_OK) {
    const char* text = lua_tostring(L_, -1);
    std::string message = text != nullptr ? text : "(no message)";
    lua_settop(L_, 0);
    return load_error(status, path, message);
  }
  status = lua_pcall(L_, nargs, 0, 1);
  if (status == LUA_OK) {
    lua_settop(L_, 0);
    return std::nullopt;
  }
  std::string message;
  if (status == LUA_ERRMEM)
    message = out_of_memory(context_, path);
  else if (lua_type(L_, -1) == LUA_TSTRING)
    message = lua_tostring(L_, -1);
  else
    message = fmt::format("{}: lua: error while reporting an error", path);
  lua_settop(L_, 0);
  return message;
}

}  // namespace edem
