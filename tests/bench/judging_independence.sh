#!/usr/bin/env bash
# Does what breaks depend on how fast a step's load comes off? The seed's Case 3 at 158 m with Set P,
# no bolts (scripts/paper/case.lua), judged at equilibrium (touching sections that fail: the worst
# first, judge{ neighbours = "wait" }) and judged every 10 cycles, each with the
# load released over 1, 100 and 10,000 cycles under local and under adaptive damping; and the
# every-10-cycles mode with case.lua's 20,000-cycle release, the speed baseline. Prints, for each
# judging mode, the crack counts and crown settlements with their spread ((max - min) / mean), and
# each run's seconds and cycles; exits 1 if the equilibrium mode's spread is over 3 % in cracks or
# 2 % in crown settlement.
#   bash tests/bench/judging_independence.sh [--edem PATH] [--out DIR] [--jobs N] [--threads M] [--keep]
#        [--set KEY=VALUE]...
# --keep: a run whose row.csv is in DIR already is taken as it is, not run again (a go resumed).
# --set: a case.lua setting given to every run (e.g. prepass_damping=adaptive), as many as wanted.
# And, judged at equilibrium under local damping released over 100 cycles (case.lua's release),
# with 1 and 2 m zones at the opening (1.5 m above), for the charts of speed against accuracy that
# it draws at its end (tests/bench/judging_chart.lua: OUT/judging_cracks.png, OUT/judging_crown.png).
# One thread a run and two runs at a time on two cores take about 50 minutes (tests/bench/RESULTS.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
edem=$root/build/interp/edem out=judging-independence jobs=2 threads=1 keep=0
extra=""  # --set KEY=VALUE ... for every run
while [[ $# -gt 0 ]]; do
  case $1 in
    --edem) edem=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    --set)
      if [[ ! ${2:-} =~ ^[a-z_]+=[^[:space:]]+$ ]]; then
        echo "judging_independence.sh: --set needs KEY=VALUE, got '${2:-}'" >&2
        exit 2
      fi
      extra+=" --set $2"; shift 2 ;;
    *) echo "judging_independence.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
edem=$(cd "$(dirname "$edem")" && pwd)/$(basename "$edem")
mkdir -p "$out"
out=$(cd "$out" && pwd)

runs=()
for judge in equilibrium cycles; do
  for damping in local adaptive; do
    for release in 1 100 10000; do runs+=("$judge $damping $release"); done
  done
done
runs+=("cycles local 20000")
# Zone size near the opening (case.lua's edge; 1.5 m is the runs' above): 1 and 2 m.
for edge in 1 2; do runs+=("equilibrium local 100 $edge"); done

run_one() {
  local judge=$1 damping=$2 release=$3 edge=${4:-}
  local name=${judge}_${damping}_${release}${edge:+_edge$edge}
  local dir=$out/$name
  # The engine's rule for each mode: touching sections wait at equilibrium, all break otherwise.
  local neighbours=break
  [[ $judge == equilibrium ]] && neighbours=wait
  [[ $keep == 1 && -f $dir/row.csv ]] && return 0
  mkdir -p "$dir"
  (cd "$dir" && "$edem" --threads "$threads" --out "$dir" --set set=P --set case=3 --set depth=158 \
     --set judge="$judge" --set damping="$damping" --set release="$release" --set threads="$threads" \
     --set neighbours="$neighbours" ${edge:+--set edge=$edge} $extra --set table="$dir/row.csv" \
     run "$root/scripts/paper/case.lua" > "$dir/log" 2>&1) ||
    echo "judging_independence.sh: $name failed (its log: $dir/log)" >&2
}
export -f run_one
export edem out threads root keep extra
printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one {}'

# One line a run: mode, damping, release, cracks, crown settlement, seconds, cycles (from the log).
summary=$out/summary.csv
# And one line a zone size (zones.csv), the 1.5 m one from the runs at that size.
zones=$out/zones.csv
echo "judge,damping,release,cracks,crown_m,seconds,cycles" > "$summary"
echo "edge,cracks,crown_m,seconds,cycles" > "$zones"
for run in "${runs[@]}"; do
  read -r judge damping release edge <<< "$run"
  dir=$out/${judge}_${damping}_${release}${edge:+_edge$edge}
  [[ -f $dir/row.csv ]] || continue
  row=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
                 { print $col["cracks"] "," $col["crown_settlement_m"] "," $col["seconds"] }' "$dir/row.csv")
  cycles=$(awk '$1 ~ /^[0-9]+$/ && NF >= 9 { sum += $3 } END { print sum + 0 }' "$dir/log")
  if [[ -n $edge ]]; then
    echo "$edge,$row,$cycles" >> "$zones"
  else
    echo "$judge,$damping,$release,$row,$cycles" >> "$summary"
    [[ "$judge $damping $release" == "equilibrium local 100" ]] && echo "1.5,$row,$cycles" >> "$zones"
  fi
done
column -s, -t "$summary"
column -s, -t "$zones"
# The charts of speed against accuracy (tests/bench/judging_chart.lua), beside the tables.
"$edem" --quiet --set summary="$summary" --set zones="$zones" --set out="$out" run "$root/tests/bench/judging_chart.lua"
awk -F, 'NR > 1 && !($1 == "cycles" && $3 == 20000) {
           n[$1]++; c = $4 + 0; u = $5 + 0
           if (!(($1) in cmin) || c < cmin[$1]) cmin[$1] = c; if (!(($1) in cmax) || c > cmax[$1]) cmax[$1] = c
           if (!(($1) in umin) || u < umin[$1]) umin[$1] = u; if (!(($1) in umax) || u > umax[$1]) umax[$1] = u
           csum[$1] += c; usum[$1] += u }
         NR > 1 { t[$1 " " $3] = $6 }
         END {
           bad = 0
           for (m in n) {
             cs = (cmax[m] - cmin[m]) / (csum[m] / n[m]); us = (umax[m] - umin[m]) / (usum[m] / n[m])
             printf "judged at %s, %d runs: cracks %d to %d (spread %.1f %%), crown %.4f to %.4f m (spread %.1f %%)\n",
                    m, n[m], cmin[m], cmax[m], 100 * cs, umin[m], umax[m], 100 * us
             if (m == "equilibrium" && (cs > 0.03 || us > 0.02)) bad = 1
           }
           exit bad
         }' "$summary"
