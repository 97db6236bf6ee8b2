#!/usr/bin/env bash
# Two threads pinned to one core wait for each other at every barrier: the run must notice, say so
# once, go on with one thread, and end with the same state, bit for bit, as a run on one thread.
# Usage: crowded.sh EDEM SCRIPT
set -euo pipefail
edem=$1 script=$2
cpu=$(awk '/^Cpus_allowed_list/ { split($2, a, /[,-]/); print a[1] }' /proc/self/status)
alone=$("$edem" --threads 1 run "$script")
crowded_err=$(mktemp)
trap 'rm -f "$crowded_err"' EXIT
crowded=$(taskset -c "$cpu" "$edem" --threads 2 run "$script" 2>"$crowded_err")
echo "--threads 1:"; echo "$alone"
echo "--threads 2 on CPU $cpu:"; echo "$crowded"; cat "$crowded_err"
sum() { grep -o 'checksum [0-9a-f]*' <<<"$1"; }
[[ -n "$(sum "$alone")" && "$(sum "$alone")" == "$(sum "$crowded")" ]] || { echo "FAIL: the states differ"; exit 1; }
grep -q 'threads asked 2, used at the end 1' <<<"$crowded" || { echo "FAIL: two threads on one core kept both"; exit 1; }
[[ $(grep -c 'cycle: note: the 2 threads waited for each other' "$crowded_err") == 1 ]] ||
  { echo "FAIL: the run did not say once that it took fewer threads"; exit 1; }
echo "crowded: one thread taken, said once, the same state"
