// The interpreter's state that commands share: the current model and run options.
//
// One Context per lua_State, owned by the Interpreter and reached from Lua C functions through
// the state's extra space (context_of), so the language keeps no global mutable state.
//
// Lua functions that the model keeps (every() callbacks, history fns) are called back from
// inside engine calls; `running` says on which Lua thread, and for which command, so that
// they run on the thread that is executing (never a suspended one) and their errors name it.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "settings_probe.hpp"
#include "io/field_output.hpp"
#include "model/model.hpp"

struct lua_State;

namespace edem {

// A command executing now: set by the command dispatcher for the duration of one call.
struct Running {
  lua_State* L = nullptr;          // the thread that called it
  std::string_view command;        // its name
  std::string cycling_at;          // "FILE:LINE" of a cycle() or solve() call, else empty
  const Running* outer = nullptr;  // the command it runs inside (from a callback), if any
};

struct Context {
  std::unique_ptr<Model> current;  // null until the first command needs a model
  bool quiet = false;              // --quiet: commands print no progress
  int threads = 0;                 // --threads: OpenMP threads of every model; 0: default
  std::string last_command_error;  // the last "FILE:LINE: command: message" raised
  // Traceback lines ("  FILE:LINE: in ...") of a callback that failed, shown above those of
  // the command that was cycling when last_command_error is reported.
  std::vector<std::string> last_error_frames;
  lua_State* lua = nullptr;        // the main thread while the state is open, else null
  Running* running = nullptr;      // the innermost command executing now
  bool histories_written = false;  // history_write() wrote the current model's histories
  std::string out_dir;             // --out: where relative files that commands write go; "": here
  std::vector<std::pair<std::string, std::string>> settings;  // --set KEY=VALUE, as given
  std::string script_path;         // the script being run, and its text (kept in checkpoints)
  std::string script_text;
  std::map<std::string, FieldSeries> outputs;  // output{} series by XDMF file
  std::vector<std::string> stage_outputs;      // output{ at = "stage" }: their files
  std::set<std::string> said;                  // warnings and notes said so far (each once)
  // Where the script was running a moment ago (a count hook notes it): Lua's own out-of-memory
  // error carries no position, and this names the line it ran out near.
  std::string recent_source;
  int recent_line = 0;
  std::vector<std::pair<std::string, std::string>> results;  // result{}: KEY, VALUE as written
  SettingsProbe* probe = nullptr;  // edem sweep's look at the settings (settings_probe.hpp); null: a run

  // Appends a frame of the current model to the series of `file` (output{}).
  void write_frame(const std::string& file) { outputs.at(file).append(model().field_frame()); }
  // A frame to each output{ at = "stage" } series (before an excavation, at the end).
  void write_stage_frames() {
    for (const std::string& file : stage_outputs) write_frame(file);
  }
  // The progress line of long runs (every model gets it; none with --quiet), and whether a
  // terminal line is showing that the next output must clear first.
  std::function<void(const RunProgress&)> progress;
  std::function<void(const PrepassProgress&)> prepass_progress;
  double progress_every = 0.0;  // [s]
  bool progress_line_open = false;
  // Raised (to the signal's number) by SIGINT or SIGTERM: cycling stops at the end of its cycle
  // and the model is saved (cmd_solve.cpp). Null: signals are not caught.
  const std::atomic<int>* stop = nullptr;
  int interrupted_by = 0;  // the signal that ended the script, once it has

  // Prints what a run says about itself (Model::set_notice) on stderr, after the position of the
  // command cycling; nothing with --quiet.
  void say_run_notice(const std::string& text);

  // Clears a terminal progress line still showing (after a run, or before its error).
  void close_progress_line();

  // Where a command writes `file`: under out_dir when that is set and `file` is relative.
  std::string output_path(const std::string& file) const;

  // The current model; a script that starts without model{} gets a default one.
  Model& model() {
    if (!current) replace_model(std::make_unique<Model>());
    return *current;
  }

  // Makes `next` the current model (with the run's thread count), dropping the old one.
  void replace_model(std::unique_ptr<Model> next) {
    next->set_threads(threads);
    next->set_progress(progress, progress_every);
    next->set_prepass_progress(prepass_progress);
    next->set_notice([this](const std::string& text) { say_run_notice(text); });
    next->set_stop(stop);
    current = std::move(next);
    histories_written = false;
  }

  // The command cycling the model now (cycle() or solve()), or nullptr.
  const Running* cycling() const {
    for (const Running* r = running; r != nullptr; r = r->outer)
      if (!r->cycling_at.empty()) return r;
    return nullptr;
  }
};

// Makes `context` reachable from every C function running in `L`.
void attach(lua_State* L, Context& context);

// The Context attached to `L`.
Context& context_of(lua_State* L);

}  // namespace edem
