#include "sweep.hpp"

#include <fmt/format.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <lua.hpp>
#include <mutex>
#include <thread>

#include "core/error.hpp"
#include "core/names.hpp"
#include "errors.hpp"
#include "interpreter.hpp"
#include "sweep_runs.hpp"
#include "sweep_slurm.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The settings SCRIPT declares, learnt by running it up to its settings{} call
// (settings_probe.hpp).
std::vector<DeclaredSetting> declared_settings(const std::string& script,
                                               const std::vector<std::string>& stdlib_dirs) {
  SettingsProbe probe;
  Interpreter interpreter({.quiet = true, .stdlib_dirs = stdlib_dirs, .probe = &probe});
  lua_pushcfunction(interpreter.state(), [](lua_State*) { return 0; });  // nothing printed
  lua_setglobal(interpreter.state(), "print");
  const auto error = interpreter.run_file(script);
  if (probe.reached) return probe.declared;
  const auto where = error ? split_position(*error) : std::nullopt;
  if (!probe.first_command.empty())
    fail(
        "{}{}: {} comes before any settings{{}}: declare the script's settings at its top "
        "(local s = settings{{ KEY = default, ... }}) so that the sweep can check the table "
        "against them",
        where ? where->source : script, where ? ":" + where->line : "", probe.first_command);
  if (error) fail("{} (read up to its settings{{}})", *error);
  fail(
      "{}: the script declares no settings{{}}: give its keys and defaults (local s = settings{{ "
      "KEY = default, "
      "... }}) so that the sweep can check the table against them",
      script);
}

// The cores this process may use (its CPU affinity: a cluster's share, a container's limit).
int usable_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

std::string duration_text(double seconds) {
  if (seconds < 90) return fmt::format("{:.0f} s", seconds);
  if (seconds < 5400) return fmt::format("{:.0f} min", seconds / 60);
  return fmt::format("{:.1f} h", seconds / 3600);
}

std::string absolute(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

std::string default_out(const std::string& table) {
  return fs::path(table).stem().string() + "_sweep";
}

// The runs the options select: --only's row, else every row (with --resume, those without an
// ok outcome of their settings).
std::vector<const SweepRow*> selected_rows(const SweepOptions& options, const SweepTable& table,
                                           const std::string& out) {
  std::vector<const SweepRow*> rows;
  if (!options.only.empty()) {
    std::vector<std::string> names;
    for (const SweepRow& row : table.rows) {
      names.push_back(row.name);
      if (row.name == options.only) rows.push_back(&row);
    }
    if (rows.empty())
      fail("--only {}: {} has no row of that name{}", options.only, table.path,
           did_you_mean_or_list(options.only, names));
  } else {
    for (const SweepRow& row : table.rows) rows.push_back(&row);
  }
  if (options.resume)
    std::erase_if(rows, [&](const SweepRow* row) {
      const auto o = outcome_of(out, *row, options.common);
      return o && o->status == "ok";
    });
  return rows;
}

void refuse_foreign_folder(const SweepTable& table, const SweepRow& row, const std::string& out) {
  const std::string folder = (fs::path(out) / row.name).string();
  if (!is_run_folder(folder))
    fail("{}: row '{}' would run in {}, which holds files of something else than a run: give "
         "another --out",
         table.path, row.name, folder);
}

// What the runs so far say, and a guess of the time left.
struct Tally {
  int done = 0, failed = 0, left = 0;
  double seconds = 0.0;  // of the runs ended
};

std::string tally_text(const Tally& t, int jobs) {
  std::string text = fmt::format("{} done, {} failed, {} left", t.done, t.failed, t.left);
  const int ended = t.done + t.failed;
  if (t.left > 0 && ended > 0)
    text += fmt::format(", about {} to go",
                        duration_text(t.seconds / ended * std::ceil(double(t.left) / jobs)));
  return text;
}

int run_locally(const SweepOptions& options, const SweepTable& table,
                const std::vector<const SweepRow*>& rows, const RunPlan& plan) {
  const int cores = usable_cores();
  int threads = std::clamp(options.threads, 1, cores);
  if (threads < options.threads)
    fmt::print("sweep: --threads {} is more than the {} cores here; each run takes {}\n",
               options.threads, cores, threads);
  int jobs = options.jobs > 0 ? options.jobs : cores / threads;
  if (jobs * threads > cores) {
    // Runs sharing cores are many times slower: OpenMP's barriers wait on descheduled threads.
    const int fit = std::max(1, cores / threads);
    fmt::print(
        "sweep: --jobs {} of {} thread{} would ask for more than the {} cores here; {} at a time\n",
        jobs, threads, threads == 1 ? "" : "s", cores, fit);
    jobs = fit;
  }
  jobs = std::min<int>(jobs, static_cast<int>(rows.size()));
  RunPlan each = plan;
  each.threads = threads;
  fmt::print("sweep: {} run{} of {}, {} at a time on {} thread{} each; rows gathered in {}\n",
             rows.size(), rows.size() == 1 ? "" : "s", fs::path(plan.script).filename().string(),
             jobs, threads, threads == 1 ? "" : "s", (fs::path(plan.out) / "sweep.csv").string());
  std::fflush(stdout);

  std::mutex mutex;  // guards next, tally, printing and gathering
  size_t next = 0;
  Tally tally{.done = 0, .failed = 0, .left = static_cast<int>(rows.size()), .seconds = 0.0};
  const auto started = Clock::now();
  const auto work = [&] {
    for (;;) {
      const SweepRow* row = nullptr;
      {
        const std::lock_guard lock(mutex);
        if (next == rows.size() || (options.stop != nullptr && options.stop->load() != 0)) return;
        row = rows[next++];
      }
      const RunOutcome o = run_row(each, *row, options.stop);
      const std::lock_guard lock(mutex);
      --tally.left;
      ++(o.status == "ok" ? tally.done : tally.failed);
      tally.seconds += o.seconds;
      try {
        gather(plan.out, table, options.common);
      } catch (const std::exception& e) {  // the next run's gathering, or --collect, tries again
        fmt::print(stderr, "edem: sweep: cannot gather the rows: {}\n", e.what());
      }
      if (!options.quiet || o.status != "ok") {
        fmt::print("sweep: {} {} in {}{} ({})\n", row->name, o.status, duration_text(o.seconds),
                   o.message.empty() ? "" : ": " + o.message, tally_text(tally, jobs));
        std::fflush(stdout);
      }
    }
  };
  std::vector<std::thread> workers;
  for (int k = 0; k < jobs; ++k) workers.emplace_back(work);
  for (std::thread& w : workers) w.join();
  const Gathered g = gather(plan.out, table, options.common);
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  fmt::print("sweep: {} ok, {} failed, {} not run, in {}; {}\n", g.ok, g.failed, g.missing,
             duration_text(seconds), (fs::path(plan.out) / "sweep.csv").string());
  if (options.stop != nullptr && options.stop->load() != 0) return 128 + options.stop->load();
  return tally.failed == 0 && tally.left == 0 ? 0 : 1;
}

// The Slurm array task `task`: its chunk of rows, one after another, then the rows gathered.
int run_task(const SweepOptions& options, const SweepTable& table, RunPlan plan) {
  plan.pass_on_signals = false;  // Slurm signals every process of a cancelled task itself
  const size_t first = static_cast<size_t>(options.task) * static_cast<size_t>(options.chunk);
  if (first >= table.rows.size())
    fail("--task {}: the table has {} rows, {} a task", options.task, table.rows.size(),
         options.chunk);
  bool all_ok = true;
  for (size_t r = first; r < std::min(table.rows.size(), first + options.chunk); ++r) {
    if (options.stop != nullptr && options.stop->load() != 0) break;
    if (const auto o = outcome_of(plan.out, table.rows[r], options.common);
        options.resume && o && o->status == "ok")
      continue;
    if (!options.only.empty() && table.rows[r].name != options.only) continue;
    refuse_foreign_folder(table, table.rows[r], plan.out);
    const RunOutcome o = run_row(plan, table.rows[r], options.stop);
    fmt::print("sweep: {} {} in {}{}\n", table.rows[r].name, o.status, duration_text(o.seconds),
               o.message.empty() ? "" : ": " + o.message);
    all_ok = all_ok && o.status == "ok";
    try {
      gather(plan.out, table, options.common);  // the last task to end leaves every row gathered
    } catch (const std::exception& e) {         // the run's outcome is kept; --collect gathers it
      fmt::print(stderr, "edem: sweep: cannot gather the rows: {}\n", e.what());
    }
  }
  if (options.stop != nullptr && options.stop->load() != 0) return 128 + options.stop->load();
  return all_ok ? 0 : 1;
}

int collect(const SweepTable& table, const std::string& out, const Settings& common) {
  const Gathered g = gather(out, table, common);
  std::vector<std::string> missing, failed;
  for (const SweepRow& row : table.rows) {
    const auto o = outcome_of(out, row, common);
    if (!o)
      missing.push_back(row.name);
    else if (o->status != "ok")
      failed.push_back(fmt::format("{} ({})", row.name, o->status));
  }
  fmt::print("sweep: {} ok, {} failed, {} without an outcome; {}\n", g.ok, g.failed, g.missing,
             (fs::path(out) / "sweep.csv").string());
  if (!failed.empty()) fmt::print("sweep: failed: {}\n", fmt::join(failed, ", "));
  if (!missing.empty())
    fmt::print("sweep: not run (or still running): {}\n", fmt::join(missing, ", "));
  return failed.empty() && missing.empty() ? 0 : 1;
}

}  // namespace

int run_sweep(const SweepOptions& options) {
  std::string out;
  SweepTable table;
  std::vector<const SweepRow*> rows;
  RunPlan plan;
  try {
    if (!options.slurm && options.task < 0 &&
        (!options.partition.empty() || !options.time.empty() || options.chunk != 1))
      fail("--partition, --time and --chunk are for --slurm");
    table = read_sweep_table(options.table);
    if (!fs::is_regular_file(options.script)) fail("{}: no such script", options.script);
    check_sweep_table(table, declared_settings(options.script, options.stdlib_dirs),
                      fs::path(options.script).filename().string(), options.common);
    out = absolute(options.out.empty() ? default_out(options.table) : options.out);
    rows = selected_rows(options, table, out);
    // A run's folder is emptied when it starts: never anything else. (A Slurm task checks its
    // own rows when it runs them: the others' may be running.)
    if (options.task < 0)
      for (const SweepRow* row : rows) refuse_foreign_folder(table, *row, out);
    std::error_code ec;
    const std::string edem = fs::read_symlink("/proc/self/exe", ec).string();
    if (ec) fail("cannot find this edem's own path to start the runs with: {}", ec.message());
    fs::create_directories(out);
    plan = RunPlan{.edem = edem,
                   .script = absolute(options.script),
                   .out = out,
                   .threads = std::max(1, options.threads),
                   .common = options.common,
                   .pass_on_signals = true};
  } catch (const std::exception& e) {
    fmt::print(stderr, "edem: sweep: {}\n", e.what());
    return 2;
  }
  try {
    if (options.collect) return collect(table, out, options.common);
    if (options.task >= 0) return run_task(options, table, plan);
    if (rows.empty()) {
      fmt::print("sweep: every run has its outcome already (--resume); {}\n",
                 (fs::path(out) / "sweep.csv").string());
      gather(out, table, options.common);
      return 0;
    }
    if (options.slurm) return submit_to_slurm(options, table, rows, plan);
    return run_locally(options, table, rows, plan);
  } catch (const std::exception& e) {
    fmt::print(stderr, "edem: sweep: {}\n", e.what());
    return 1;
  }
}

}  // namespace edem
