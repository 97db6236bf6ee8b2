// `edem sweep TABLE SCRIPT`: a run of SCRIPT for each row of TABLE, with the row's settings, on
// the local cores (--jobs runs at a time, --threads each) or as a Slurm job array (--slurm), and
// every run's result{} row gathered into OUT/sweep.csv as runs end (sweep_runs.hpp).
//
// Before any run the table is read and checked against the settings{} SCRIPT declares; a bad
// table stops the sweep with a message naming its row and column.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "sweep_table.hpp"

namespace edem {

struct SweepOptions {
  std::string table, script;
  std::string out;       // "": TABLE's name without its extension, and "_sweep"
  int jobs = 0;          // runs at a time; 0: as many as the cores hold at `threads` each
  int threads = 1;       // each run's threads
  bool resume = false;   // run only the rows without an ok outcome of their settings
  std::string only;      // run this row alone
  bool collect = false;  // run nothing: gather what the runs left, say what is missing
  bool quiet = false;
  Settings common;  // --set for every run
  // Slurm: write a job-array script (one task a `chunk` of rows) and submit it with sbatch.
  bool slurm = false;
  bool submit = true;  // false: write the script only
  int chunk = 1;
  std::string partition, time;
  int task = -1;  // the array task to run (the job script's own call): rows task*chunk ...
  // A signal's number: pass it on to the runs, start no more.
  const std::atomic<int>* stop = nullptr;
  std::vector<std::string> stdlib_dirs;  // searched first for require "edem.x" (InterpreterOptions)
};

// The whole sweep; returns the exit status: 0 when every run selected ended ok, 1 when one did
// not, 2 for a bad table or command line, 128 + signal when stopped by one.
int run_sweep(const SweepOptions& options);

}  // namespace edem
