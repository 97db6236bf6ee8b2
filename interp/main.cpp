// The edem program: runs a script, prints the language reference, or says its version.
//
//   edem [-q] [--threads N] [--progress S] [--out DIR] [--set KEY=VALUE]... run FILE.lua [ARGS...]
//        (or: edem FILE.lua [ARGS...]; the options may follow `run` too)
//   edem reference [--update README.md]
//   edem info FILE.h5 [--script]   (what a checkpoint holds)
//   edem sweep [--jobs N] [--threads M] [--out DIR] [--resume] [--only NAME] [--collect]
//              [--slurm [--partition P] [--time T] [--chunk K] [--no-submit]] [--set KEY=VALUE]...
//              TABLE SCRIPT   (a run of SCRIPT a row of TABLE: sweep.hpp)
//   edem --version | --help
//
// Exit status: 0 on success, 1 when the script stops on an error (the message on stderr),
// 2 for a wrong command line.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "checkpoint_summary.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "interpreter.hpp"
#include "reference.hpp"
#include "sweep.hpp"

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string script;
  std::vector<std::string> script_args;
  bool quiet = false;
  int threads = 0;  // 0: OpenMP's default
  bool reference = false;
  std::string update;  // README to rewrite with the reference
  std::string checkpoint;   // edem info FILE
  bool show_script = false; // edem info --script
  std::vector<std::string> settings;  // --set KEY=VALUE, as given
  std::string out_dir;                // --out DIR
  double progress = -1.0;             // --progress SECONDS; < 0: the default
  std::string error_file;             // --error-file: the error is written there too (edem sweep's runs)
  edem::SweepOptions sweep;           // edem sweep
  std::vector<std::string> sweep_settings;
};

// An installed edem finds its stdlib next to itself: PREFIX/bin/edem, PREFIX/share/edem/stdlib.
std::vector<std::string> stdlib_near_executable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path dir = exe.parent_path().parent_path() / "share" / "edem" / "stdlib";
  if (!fs::is_directory(dir, ec)) return {};
  return {dir.string()};
}

// KEY=VALUE pairs of --set; a key must be a Lua name (arg.KEY), given once.
std::vector<std::pair<std::string, std::string>> parse_settings(const std::vector<std::string>& given) {
  std::vector<std::pair<std::string, std::string>> settings;
  for (const std::string& text : given) {
    const size_t equals = text.find('=');
    if (equals == std::string::npos)
      throw CLI::ValidationError("--set", fmt::format("'{}' has no '=': give KEY=VALUE", text));
    const std::string key = text.substr(0, equals);
    if (!edem::is_identifier(key))
      throw CLI::ValidationError(
          "--set", fmt::format("'{}': the key must be a name (letters, digits, _; not a digit first)", key));
    for (const auto& [seen, value] : settings)
      if (seen == key) throw CLI::ValidationError("--set", fmt::format("'{}' is given twice", key));
    settings.emplace_back(key, text.substr(equals + 1));
  }
  return settings;
}

// The signal that asked a running script to stop (0: none). A signal handler may touch nothing
// but a lock-free atomic, so this one flag lives outside the model; the model only reads it.
std::atomic<int> stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// Seconds a run has to stop by itself after the first signal: cycling stops within a cycle and
// saves; work that does not look at the flag (meshing, a prepass step) is ended when they are up.
constexpr unsigned kStopGraceSeconds = 20;

// The grace is over: the signal that asked to stop ends the process, as if it were not caught.
extern "C" void stop_now(int) {
  const int signal = stop_signal.load();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// The first SIGINT or SIGTERM asks cycling to stop at the end of its cycle (the model is then
// saved); a second one, or the end of the grace, ends the process at once.
extern "C" void ask_to_stop(int signal) {
  stop_signal.store(signal);
  std::signal(signal, SIG_DFL);
  std::signal(SIGALRM, stop_now);
  ::alarm(kStopGraceSeconds);
  const char text[] = "\nedem: stopping at the end of this cycle (again to quit at once)\n";
  [[maybe_unused]] const auto written = ::write(2, text, sizeof text - 1);
}

// A sweep passes the first SIGINT or SIGTERM on to its runs (which save their models and end)
// and starts no more; a second one ends it at once.
extern "C" void ask_sweep_to_stop(int signal) {
  stop_signal.store(signal);
  std::signal(signal, SIG_DFL);
  const char text[] = "\nedem: sweep: stopping the runs (again to quit at once)\n";
  [[maybe_unused]] const auto written = ::write(2, text, sizeof text - 1);
}

int run_script(const Options& options, std::vector<std::pair<std::string, std::string>> settings) {
  if (!options.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(options.out_dir, ec);
    if (ec || !fs::is_directory(options.out_dir)) {
      fmt::print(stderr, "edem: --out: cannot make the directory '{}': {}\n", options.out_dir,
                 ec ? ec.message() : "a file of that name is in the way");
      return 2;
    }
  }
  edem::Interpreter interpreter({.quiet = options.quiet,
                                 .threads = options.threads,
                                 .settings = std::move(settings),
                                 .out_dir = options.out_dir,
                                 .progress_seconds = options.progress,
                                 .stdlib_dirs = stdlib_near_executable(),
                                 .stop = &stop_signal});
  std::signal(SIGINT, ask_to_stop);
  std::signal(SIGTERM, ask_to_stop);
  const auto error = interpreter.run_file(options.script, options.script_args);
  if (!error) return 0;
  std::fflush(stdout);  // what the script printed comes before the error
  fmt::print(stderr, "{}\n", *error);
  if (!options.error_file.empty()) std::ofstream(options.error_file) << *error << '\n';
  // Stopped by a signal: the status a shell expects of one (130 for SIGINT).
  const int interrupted = interpreter.context().interrupted_by;
  return interrupted != 0 ? 128 + interrupted : 1;
}

int print_reference(const Options& options) {
  const std::string reference = edem::reference_markdown();
  if (options.update.empty()) {
    fmt::print("{}", reference);
    return 0;
  }
  std::ifstream in(options.update);
  std::stringstream text;
  if (in) text << in.rdbuf();  // a missing README is created with just the reference
  std::ofstream out(options.update);
  out << edem::with_reference(text.str(), reference);
  if (!out) {
    fmt::print(stderr, "edem: cannot write '{}'\n", options.update);
    return 1;
  }
  fmt::print("edem: updated the language reference in {}\n", options.update);
  return 0;
}

int print_checkpoint(const Options& options) {
  try {
    fmt::print("{}", edem::checkpoint_summary(options.checkpoint, options.show_script));
    return 0;
  } catch (const edem::Error& e) {
    fmt::print(stderr, "edem: {}\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"EDEM: a scriptable 2D distinct element code for jointed rock.", "edem"};
  app.set_version_flag("--version", "edem " EDEM_VERSION);
  app.fallthrough();
  app.add_flag("-q,--quiet", options.quiet, "print no progress while running");
  app.add_option("--threads", options.threads,
                 "threads for cycling the model (default: OMP_NUM_THREADS, else the cores the process may "
                 "run on); at most one per 1000 zones, which a smaller model could not keep busy, and fewer "
                 "while they wait for each other (another process busy on the same cores)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--set", options.settings,
                 "KEY=VALUE for the script, as arg.KEY (a number or boolean when VALUE reads as "
                 "one, else text); repeat it for more, e.g. --set case=3 --set bolts=none")
      ->allow_extra_args(false);
  app.add_option("--out", options.out_dir,
                 "directory (made if missing) for the files commands write when given a relative "
                 "name: plot, chart, profile, history_write, save and the end-of-run histories "
                 "(restore reads relative names from there too)");
  app.add_option("--progress", options.progress,
                 "seconds between progress lines of a long cycle() or solve{} (cycle, ratio, "
                 "cracks, stage, cycles/s): on a terminal one line rewritten every 0.5 s, "
                 "otherwise a plain line every 10 s; 0: none")
      ->check(CLI::Range(0.0, 1e9));
  app.add_flag("--reference", options.reference,
               "print the language reference (markdown) and exit");
  app.add_option("script", options.script, "Lua script to run (same as 'edem run SCRIPT')");
  app.add_option("args", options.script_args, "arguments for the script: arg[1], ...");

  auto* run = app.add_subcommand("run", "run a Lua script");
  run->add_option("script", options.script, "Lua script to run")->required();
  run->add_option("args", options.script_args, "arguments for the script: arg[1], ...");

  auto* reference = app.add_subcommand("reference", "print the language reference (markdown)");
  reference->add_option("--update", options.update,
                        "rewrite the reference section of this file (README.md) instead");
  auto* info = app.add_subcommand("info", "summarise a checkpoint written by save()");
  info->add_option("file", options.checkpoint, "the checkpoint (.h5)")->required();
  info->add_flag("--script", options.show_script, "also print the script saved in it");
  app.add_option("--error-file", options.error_file, "also write the error to this file")->group("");

  auto* sweep = app.add_subcommand(
      "sweep",
      "run SCRIPT once for each row of TABLE (CSV, or YADE's blank-separated batch table: a header of the "
      "script's settings{} keys and an optional name column, a row a run), each run in a folder of its own "
      "under --out, its result{} row gathered into OUT/sweep.csv as runs end; locally or as a Slurm job array");
  sweep->add_option("table", options.sweep.table, "the table of runs")->required();
  sweep->add_option("script", options.sweep.script, "the Lua script each row runs")->required();
  sweep->add_option("--out", options.sweep.out, "the sweep's folder [TABLE's name without extension + _sweep]");
  sweep->add_option("--jobs", options.sweep.jobs,
                    "runs at a time [as many as the cores hold at --threads each; never more]")
      ->check(CLI::Range(1, 4096));
  sweep->add_option("--threads", options.sweep.threads, "threads of each run (Slurm: cpus per task) [1]")
      ->check(CLI::Range(1, 4096));
  sweep->add_option("--set", options.sweep_settings, "KEY=VALUE for every run (a key the table has not)")
      ->allow_extra_args(false);
  sweep->add_flag("--resume", options.sweep.resume,
                  "run only the rows without an ok outcome of their settings in --out");
  sweep->add_option("--only", options.sweep.only, "run the row of this name alone");
  sweep->add_flag("--collect", options.sweep.collect,
                  "run nothing: gather the outcomes in --out into sweep.csv and say what is missing");
  sweep->add_flag("--slurm", options.sweep.slurm,
                  "write OUT/sweep.sbatch, a Slurm job array of the runs, and submit it with sbatch");
  sweep->add_option("--partition", options.sweep.partition, "Slurm: the partition");
  sweep->add_option("--time", options.sweep.time, "Slurm: each task's time limit (e.g. 1:00:00)");
  sweep->add_option("--chunk", options.sweep.chunk, "Slurm: rows a task runs, one after another [1]")
      ->check(CLI::Range(1, 1000000));
  sweep->add_flag("!--no-submit", options.sweep.submit, "Slurm: write the job script, do not submit it");
  sweep->add_option("--task", options.sweep.task, "run this array task's rows (the job script's call)")
      ->check(CLI::Range(0, 1 << 30))
      ->group("");
  app.require_subcommand(0, 1);

  std::vector<std::pair<std::string, std::string>> settings;
  try {
    app.parse(argc, argv);
    settings = parse_settings(options.settings);
    options.sweep.common = parse_settings(options.sweep_settings);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (options.reference || reference->parsed()) return print_reference(options);
  if (info->parsed()) return print_checkpoint(options);
  if (sweep->parsed()) {
    if (!options.settings.empty() || !options.out_dir.empty() || options.threads != 0) {
      fmt::print(stderr, "edem: sweep: give --set, --out and --threads after 'sweep' (they are the sweep's)\n");
      return 2;
    }
    options.sweep.quiet = options.quiet;
    options.sweep.stdlib_dirs = stdlib_near_executable();
    options.sweep.stop = &stop_signal;
    std::signal(SIGCHLD, SIG_DFL);  // an inherited "ignore" would make the runs' exit statuses unreadable
    std::signal(SIGINT, ask_sweep_to_stop);
    std::signal(SIGTERM, ask_sweep_to_stop);
    return edem::run_sweep(options.sweep);
  }
  if (options.script.empty()) {
    fmt::print(stderr, "{}", app.help());
    return 2;
  }
  return run_script(options, std::move(settings));
}
