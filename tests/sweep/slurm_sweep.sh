#!/usr/bin/env bash
# edem sweep on a real Slurm cluster: installs slurm-wlm and munge (scripts/install-deps.sh
# --slurm), starts a single-node cluster here (slurm_cluster.sh), submits the 8-row sweep of
# eight.csv with `edem sweep --slurm` and checks its gathered table equals a local sweep's; then
# submits it again, cancels one running task and one waiting with scancel, and checks that
# `--slurm --resume` runs just those two and the table is whole and the same. Stops the daemons
# it started, also on failure.
#
#   bash tests/sweep/slurm_sweep.sh EDEM WORKDIR
set -euo pipefail
edem=$(realpath "$1")
work=$(realpath -m "$2")
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "slurm_sweep: FAIL: $*" >&2; exit 1; }

bash "$here/../../scripts/install-deps.sh" --slurm >&2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
trap 'bash "$here/slurm_cluster.sh" stop "$work/daemons"' EXIT
eval "$(bash "$here/slurm_cluster.sh" start "$work/daemons")"

runs=(--set cycles=100000)  # about 2 s a run: long enough to be cancelled while it runs
table=$here/eight.csv script=$here/settle.lua

# The gathered table without its seconds column (times differ from run to run).
without_seconds() {
  python3 -c 'import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
k = rows[0].index("seconds")
for r in rows: print(",".join(r[:k] + r[k + 1:]))' "$1"
}

# Waits until the job in OUT/slurm/job_id has left the queue.
wait_for_job() {
  local id
  id=$(cat "$1/slurm/job_id")
  for _ in $(seq 1 600); do
    [[ -z $(squeue -h -j "$id" -o %i 2>/dev/null) ]] && return 0
    sleep 0.5
  done
  fail "job $id still queued after 300 s"
}

"$edem" sweep --jobs 2 "${runs[@]}" --out local "$table" "$script" > local.txt
without_seconds local/sweep.csv > local.csv
[[ $(grep -c ',ok,' local.csv) == 8 ]] || fail "the local sweep did not run all 8 rows: $(cat local.txt)"

# 1. The whole table through the cluster.
"$edem" sweep --slurm "${runs[@]}" --out through_slurm "$table" "$script"
wait_for_job through_slurm
without_seconds through_slurm/sweep.csv > through_slurm.csv
diff local.csv through_slurm.csv || fail "the cluster's table differs from the local one"
echo "slurm_sweep: 8 rows through Slurm equal the local sweep's"

# 2. One task cancelled while it runs (row a, task 0), one before it starts (row h, task 7).
"$edem" sweep --slurm "${runs[@]}" --out cancelled "$table" "$script"
id=$(cat cancelled/slurm/job_id)
scancel "${id}_7"
for _ in $(seq 1 200); do [[ -f cancelled/a/log.txt ]] && break; sleep 0.1; done
sleep 0.5
scancel "${id}_0"
wait_for_job cancelled
without_seconds cancelled/sweep.csv > cancelled.csv
status_a=$(grep '^a,' cancelled.csv | cut -d, -f5 || true)  # name,height,density,cycles,status
[[ $status_a == interrupted ]] || fail "row a, cancelled while running, is '$status_a', not interrupted"
! grep -q '^h,' cancelled.csv || fail "row h ran though its task was cancelled before it started"
[[ $(grep -c ',ok,' cancelled.csv) == 6 ]] || fail "not the other 6 rows ok: $(cat cancelled.csv)"
echo "slurm_sweep: cancelled: a interrupted, h never ran, the other six ok"

"$edem" sweep --slurm --resume "${runs[@]}" --out cancelled "$table" "$script" | tee resumed.txt
grep -q '#SBATCH --array=0,7$' cancelled/sweep.sbatch || fail "--resume did not submit tasks 0 and 7 alone: $(grep array cancelled/sweep.sbatch)"
wait_for_job cancelled
without_seconds cancelled/sweep.csv > resumed.csv
diff local.csv resumed.csv || fail "after --resume the table differs from the local one"
echo "slurm_sweep: --resume ran the two cancelled rows; the table equals the local sweep's"
