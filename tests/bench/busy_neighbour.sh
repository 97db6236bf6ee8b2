#!/usr/bin/env bash
# Two threads beside one busy process: busy_neighbour.lua's run time alone on two threads, beside
# a busy loop on two threads, and beside it on one thread, the three taken in turn, median of
# RUNS rounds, for each EDEM binary given.
# Usage: busy_neighbour.sh [RUNS] EDEM...     (e.g. 3 build/interp/edem)
set -euo pipefail
runs=$1; shift
here=$(cd "$(dirname "$0")" && pwd)
busy=
stop_busy() { [[ -n $busy ]] && kill "$busy" 2>/dev/null; wait "$busy" 2>/dev/null || true; busy=; }
trap stop_busy EXIT
seconds() {  # EDEM THREADS: the run's wall time
  local start=$EPOCHREALTIME
  "$1" --quiet --threads "$2" run "$here/busy_neighbour.lua" > /dev/null 2>&1 || { echo "$1 failed" >&2; exit 1; }
  awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { print b - a }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
for edem in "$@"; do
  alone=() beside2=() beside1=()
  for ((r = 0; r < runs; ++r)); do
    alone+=("$(seconds "$edem" 2)")
    sh -c 'while :; do :; done' & busy=$!
    sleep 0.5
    beside2+=("$(seconds "$edem" 2)")
    beside1+=("$(seconds "$edem" 1)")
    stop_busy
  done
  a=$(median "${alone[@]}") b2=$(median "${beside2[@]}") b1=$(median "${beside1[@]}")
  awk -v e="$edem" -v a="$a" -v b2="$b2" -v b1="$b1" 'BEGIN {
    printf "%s: alone 2 threads %.2f s; beside a busy process: 2 threads %.2f s, 1 thread %.2f s; " \
           "2 beside / 2 alone %.2f, 2 beside / 1 beside %.2f\n", e, a, b2, b1, b2 / a, b2 / b1 }'
done
