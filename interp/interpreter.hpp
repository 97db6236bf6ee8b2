// The Lua state that runs EDEM scripts: standard Lua plus the commands, the stdlib on
// package.path, and errors reported as "FILE:LINE: word: message" (errors.hpp).
//
// The first line of every error names the script line and one lowercase word: the command
// that failed (`jset: spacing must be > 0, got -2`), or `syntax`, `lua` (a Lua runtime
// error), `error` (the script's own error() or assert()); an unknown global function becomes
// `blok: unknown command (did you mean 'block'?)`. A short traceback follows when the error
// happened inside a function.
//
// When a script file ends without error and its model recorded histories that no
// history_write() wrote, they go to "<script name without .lua>_history.csv" in the working
// directory.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "context.hpp"

struct lua_State;

namespace edem {

struct InterpreterOptions {
  bool quiet = false;                    // commands print no progress
  int threads = 0;                       // OpenMP threads of every model; 0: OpenMP's default
  // --set key=value: arg.key in the script (a number or boolean when the text reads as one)
  std::vector<std::pair<std::string, std::string>> settings = {};
  std::string out_dir = {};  // --out: relative files that commands write go there (Context::out_dir)
  // --progress: seconds between progress lines of a long run; < 0: 0.5 on a terminal (one line,
  // rewritten), 10 otherwise (plain lines); 0: none. None at all when quiet.
  double progress_seconds = -1.0;
  std::vector<std::string> stdlib_dirs = {};  // searched first for require "edem.x"
  // Raised to a signal's number by the caller's SIGINT / SIGTERM handler: cycling stops at the
  // end of its cycle and the model is saved to interrupted.h5 (Context::stop). Null: none.
  const std::atomic<int>* stop = nullptr;
  // edem sweep's look at the script's settings{} (settings_probe.hpp); null for a run.
  SettingsProbe* probe = nullptr;
};

class Interpreter {
 public:
  explicit Interpreter(InterpreterOptions options = {});
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  // Runs a script file with `args` as arg[1], ... (and as `...`). Returns nothing on success,
  // else the error message to print (without a final newline).
  std::optional<std::string> run_file(const std::string& path,
                                      const std::vector<std::string>& args = {});

  // Runs Lua source as if it were the file `name` (for tests and embedding).
  std::optional<std::string> run_string(std::string_view code, const std::string& name);

  Context& context() { return context_; }
  lua_State* state() { return state_.get(); }

 private:
  std::optional<std::string> run_loaded(int status, const std::string& path, int nargs);
  // The last frame of each output{ at = "stage" } series once the script has run.
  std::optional<std::string> write_stage_frames_at_end(const std::string& path);
  std::optional<std::string> write_pending_histories(const std::string& path);

  std::vector<std::pair<std::string, std::string>> settings_;  // InterpreterOptions::settings
  std::string stdlib_path_;  // package.path entries of the stdlib, searched first
  std::string lua_path_;     // Lua's own package.path, searched last
  Context context_;
  std::unique_ptr<lua_State, void (*)(lua_State*)> state_;  // closed before context_ goes
  lua_State* L_ = nullptr;                                  // state_.get()
};

}  // namespace edem
