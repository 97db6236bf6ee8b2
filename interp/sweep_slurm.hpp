// edem sweep on a Slurm cluster: a job array whose task K runs the K-th chunk of the table's rows
// (`edem sweep --task K`), written to OUT/sweep.sbatch and submitted with sbatch. The scheduler
// places the tasks; the folder OUT, seen by every node, carries the files.
#pragma once

#include <vector>

#include "sweep.hpp"
#include "sweep_runs.hpp"

namespace edem {

// Writes the job script for `rows` (their chunks' tasks only) and submits it unless
// options.submit is off; returns the exit status.
int submit_to_slurm(const SweepOptions& options, const SweepTable& table,
                    const std::vector<const SweepRow*>& rows, const RunPlan& plan);

}  // namespace edem
