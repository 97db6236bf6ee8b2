// The runs of an `edem sweep`: each row run as its own edem process in a folder of its own,
// what became of it kept beside it (run.csv), and every run's row gathered into one table.
//
//   OUT/NAME/          the run's --out and working folder: its files, log.txt, result.csv
//   OUT/NAME/run.csv   its settings, status (ok, error, interrupted, crashed), seconds, result
//   OUT/sweep.csv      one row a run that has ended, in the table's order
#pragma once

#include <atomic>
#include <optional>
#include <string>

#include "sweep_table.hpp"

namespace edem {

struct RunOutcome {
  std::string status;  // ok, error, interrupted (a signal asked it to stop), crashed
  double seconds = 0.0;
  std::string message;  // why it did not end well
  Settings settings;    // as it ran
  Settings results;     // its result{} row
};

struct RunPlan {
  std::string edem;    // the executable
  std::string script;  // absolute
  std::string out;     // the sweep's folder, absolute
  int threads = 1;
  Settings common;  // --set for every run
  // Pass a stop signal on to the run: locally, where each run has a process group of its own;
  // not in a Slurm task, whose runs Slurm signals itself (a second signal would end a run
  // before it saves).
  bool pass_on_signals = true;
};

// Whether `folder` may be emptied for a run: missing, empty, or a run's (marked so when the run
// started, or holding what became of one).
bool is_run_folder(const std::string& folder);

// Runs `row` and waits for it; a signal number in `stop` is passed on to it once (it then saves
// its model and ends). Writes and returns the outcome.
RunOutcome run_row(const RunPlan& plan, const SweepRow& row, const std::atomic<int>* stop);

// The outcome `row` left in `out`, if it ran with the row's settings.
std::optional<RunOutcome> outcome_of(const std::string& out, const SweepRow& row,
                                     const Settings& common);

struct Gathered {
  int ok = 0, failed = 0, missing = 0;
};

// Writes out/sweep.csv from the outcomes there (under a lock, for tasks ending at once on a
// cluster): name, the table's columns and those of --set for every run, status, seconds, the
// results' columns, message. A result named like a setting fills that setting's column (the
// value the script used).
Gathered gather(const std::string& out, const SweepTable& table, const Settings& common);

}  // namespace edem
