#!/usr/bin/env bash
# The seed paper's study in one command: every run of scripts/paper/case.lua the
# trends need, then scripts/paper/trends.lua over their rows.
#
#   bash scripts/paper/study.sh [--edem PATH] [--out DIR] [--jobs N] [--threads T] [--members M]
#                               [--mirror] [--origins K] [--reduced] [--strict] [--resume] [--list | --only RUN | --judge]
#                               [-- --set KEY=VALUE ...]
#
#   --edem     the edem to run [build/interp/edem]
#   --out      where the table, the pictures and the logs go [paper-study]
#   --jobs     runs at a time [1]
#   --threads  threads each run cycles on [2]
#   --members  runs of each case, their releases 10 cycles apart: 0, -10, +10, -20, ... cycles from
#              case.lua's (--set release_offset); each trend is then judged over every pairing of
#              them (trends.lua) [1]
#   --mirror   one more member of each case: its mirror image about the cavern's axis (case.lua's
#              mirror = true and first = right: the joints dip the other way, the arch's right half
#              dug first); the mesh and where crackseed{ auto } lays its cuts are new, so it shows
#              the spread the discretisation gives (trends.lua swaps its sides back) (neither key
#              again after --)
#   --origins K  K more members of each case, each with its potential cracks laid through a point of
#              its own (case.lua's origin_x, origin_y): the k-th point is (4.8 u, 4.8 v) m with (u, v)
#              the k-th point of the R2 low-discrepancy sequence, (frac(0.5 + 0.75488 k), frac(0.5 +
#              0.56984 k)), so that the offsets of the 4.8 m grid of cuts against the cavern are
#              spread evenly and fixed before any run; like the mirror image, a fair discretisation of
#              the same problem. With two or more members of each case trends.lua also judges each
#              trend on the members' means (trends_means.md: a one-sided Welch test at 95 %) [0]
#   --reduced  the version the default test suite runs: zones twice as large (edge 3 m near the
#              cavern, 20 m far) and the first 8 of the 16 steps; the same runs and trends (edem
#              takes a --set key once, so none of these three again after --)
#   --strict   exit 1 unless every trend holds
#   --resume   keep the runs that already wrote their row in OUT (a study cut short, or more
#              --members on top of a study made by the same edem) and run only the rest
#   --list     print the study's runs, one a line (as --only takes them), and stop
#   --only RUN one of those runs alone: its row, log and pictures in OUT, nothing gathered or
#              judged; exit 1 when it wrote no row (ctest runs the reduced study's runs so, each a
#              test of its own, so that they share the cores with the rest of the suite)
#   --judge    run nothing: gather and judge the rows the runs (--only) left in OUT; exit 1 when
#              one is missing (give the same --members, --mirror as the runs had)
#   after --    more settings for every run (e.g. -- --set set=M)
#
# The runs, with case.lua's defaults (Set P, judged at equilibrium): Cases 1, 2 and 3 at 158 m
# without bolts; Case 3 at 212 m and 262 m without bolts; Case 3 at 158 m with bolt patterns 1 and
# 2; each --members times
# (members after the first add _member-K to their names, the mirror image _member-mirror). Each
# writes its own row (OUT/TAG.csv, a row after each step in OUT/TAG_steps.csv) and pictures;
# OUT/study.csv and OUT/steps.csv gather them; OUT/trends.md has the verdicts at the runs' ends, and
# OUT/trends_common_step.md after the last step all runs reached; with more than one member of each,
# OUT/trends_means.md the verdicts at the runs' ends on the members' means; OUT/figure12.png the seed's
# Figure 12, Case 3 at 158 m without bolts and with both patterns on one chart (figure12.lua, from the
# first members' profiles). Exit 1 when a run wrote no row (a script error, not a stop: a stop is
# recorded in the row), or with --strict a trend fails.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
edem=build/interp/edem out=paper-study jobs=1 threads=2 members=1 mirror=0 origins=0 reduced=0 strict=false
resume=0
list=0 only='' judge=0
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --edem) edem=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --members) members=$2; shift 2 ;;
    --mirror) mirror=1; shift ;;
    --origins) origins=$2; shift 2 ;;
    --reduced) reduced=1; shift ;;
    --strict) strict=true; shift ;;
    --resume) resume=1; shift ;;
    --list) list=1; shift ;;
    --only) only=$2; shift 2 ;;
    --judge) judge=1; shift ;;
    --) shift; extra=("$@"); break ;;
    *) echo "study.sh: unknown option '$1' (see the comment at the top of $0)" >&2; exit 2 ;;
  esac
done
[[ $members =~ ^[1-9][0-9]*$ ]] || { echo "study.sh: --members must be a whole number >= 1, got '$members'" >&2; exit 2; }
[[ $origins =~ ^[0-9]+$ ]] || { echo "study.sh: --origins must be a whole number >= 0, got '$origins'" >&2; exit 2; }
[[ -n $only && $judge == 1 ]] && { echo "study.sh: --only runs one run, --judge none; not both" >&2; exit 2; }

common=(--set "threads=$threads")
if [[ $reduced == 1 ]]; then
  common+=(--set edge=3 --set far=20 --set stages=8)
fi
cases=(
  "case=1 depth=158 bolts=none"
  "case=2 depth=158 bolts=none"
  "case=3 depth=158 bolts=none"
  "case=3 depth=212 bolts=none"
  "case=3 depth=262 bolts=none"
  "case=3 depth=158 bolts=1"
  "case=3 depth=158 bolts=2"
)
runs=()  # each case once, then again for each further member
for ((k = 1; k <= members; k++)); do
  offset=$(( (k / 2) * 10 * (k % 2 == 0 ? -1 : 1) ))
  for c in "${cases[@]}"; do
    if [[ $k == 1 ]]; then runs+=("$c"); else runs+=("$c member=$k release_offset=$offset"); fi
  done
done
if [[ $mirror == 1 ]]; then
  for c in "${cases[@]}"; do runs+=("$c member=mirror"); done
fi
for ((k = 1; k <= origins; k++)); do
  point=$(awk -v k="$k" 'function frac(x) { return x - int(x) }
    BEGIN { printf "origin_x=%.2f origin_y=%.2f", 4.8 * frac(0.5 + 0.7548776662 * k), 4.8 * frac(0.5 + 0.5698402910 * k) }')
  for c in "${cases[@]}"; do runs+=("$c member=origin-$k $point"); done
done
if [[ $list == 1 ]]; then printf '%s\n' "${runs[@]}"; exit 0; fi
if [[ -n $only ]]; then
  printf '%s\n' "${runs[@]}" | grep -qxF -- "$only" || {
    echo "study.sh: --only '$only' is not one of this study's runs (--list shows them)" >&2; exit 2
  }
fi

edem=$(cd "$(dirname "$edem")" && pwd)/$(basename "$edem")
[[ -x $edem ]] || { echo "study.sh: no edem at $edem (build it, or give --edem)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)


name_of() {  # name_of "case=1 depth=158 bolts=none member=2 release_offset=-10" -> case-1_depth-158_bolts-none_member-2
  local kept=() kv
  for kv in $1; do [[ $kv == release_offset=* || $kv == origin_[xy]=* ]] || kept+=("$kv"); done
  echo "${kept[*]}" | tr ' =' '_-'
}

one_run() {  # one_run "case=1 depth=158 bolts=none"
  local settings=() name
  for kv in $1; do [[ $kv == member=* ]] || settings+=(--set "$kv"); done
  [[ $1 == *member=mirror* ]] && settings+=(--set mirror=true --set first=right)
  name=$(name_of "$1")
  if [[ $resume == 1 && -f $out/$name.csv ]]; then echo "study: $1 kept from before"; return; fi
  rm -f "$out/$name.csv" "$out/${name}_steps.csv"
  if (cd "$out" && "$edem" --quiet --threads "$threads" "${common[@]}" "${extra[@]}" "${settings[@]}" \
        --set "table=$name.csv" run "$here/case.lua" > "$name.log" 2>&1); then
    echo "study: $1 done ($(tail -n 1 "$out/$name.log" | cut -c1-160))"
  else
    echo "study: $1 failed; its last lines:"; tail -n 3 "$out/$name.log"
  fi
}
export -f one_run name_of
export edem out threads here resume
export common_flat="${common[*]}" extra_flat="${extra[*]}"

if [[ -n $only ]]; then
  one_run "$only"
  [[ -f $out/$(name_of "$only").csv ]] || { echo "study: $only wrote no row" >&2; exit 1; }
  exit 0
fi
started=$(date +%s)
if [[ $judge == 0 ]]; then
  printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c \
    'common=($common_flat); extra=($extra_flat); one_run "$1"' _ {}
else
  missing=0
  for r in "${runs[@]}"; do
    [[ -f $out/$(name_of "$r").csv ]] || { echo "study: no row from $r in $out" >&2; missing=1; }
  done
  [[ $missing == 0 ]] || exit 1
fi

# One table of the runs' ends (study.csv) and one of their rows after each step (steps.csv): the
# header once, then each run's rows.
gather() {  # gather SUFFIX FILE
  local tables=() r f
  for r in "${runs[@]}"; do
    f="$out/$(name_of "$r")$1.csv"
    [[ -f $f ]] && tables+=("$f")
  done
  for f in "${tables[@]}"; do  # rows kept by --resume from an older case.lua would not line up
    [[ $(head -n 1 "$f") == "$(head -n 1 "${tables[0]}")" ]] || {
      echo "study: $f has other columns than ${tables[0]} (an older case.lua's? run it again)" >&2
      exit 1
    }
  done
  {
    [[ ${#tables[@]} -gt 0 ]] && head -n 1 "${tables[0]}"
    for f in "${tables[@]}"; do tail -n +2 "$f"; done
  } > "$out/$2"
  echo "${#tables[@]}"
}
written=$(gather "" study.csv)
gather _steps steps.csv > /dev/null
echo "study: $written of ${#runs[@]} runs wrote a row, $(($(date +%s) - started)) s; table $out/study.csv"
set_arg=()
for kv in "${extra[@]}"; do [[ $kv == set=* ]] && set_arg=(--set "$kv"); done
cd "$out"
# The trends after the last step every run reached (before any collapse), then at the runs' ends.
"$edem" --quiet "${set_arg[@]}" --set tables=steps.csv --set step=common --set markdown=trends_common_step.md \
  run "$here/trends.lua"
echo
trends=0
"$edem" --quiet "${set_arg[@]}" --set tables=study.csv --set markdown=trends.md --set strict=$strict \
  run "$here/trends.lua" || trends=$?
if (( members > 1 || mirror == 1 || origins > 0 )); then  # the same rows judged on their means
  echo
  "$edem" --quiet "${set_arg[@]}" --set tables=study.csv --set judge=means --set markdown=trends_means.md \
    run "$here/trends.lua" || trends=$?
fi
[[ $written == "${#runs[@]}" ]] || { echo "study: only $written of ${#runs[@]} runs wrote their row" >&2; exit 1; }
# The seed's Figure 12 from the first members' profiles (case.lua's TAG_profile.csv).
set_name=P
for kv in "${extra[@]}"; do [[ $kv == set=* ]] && set_name=${kv#set=}; done
profiles=("case3_${set_name}_h158_none_profile.csv" "case3_${set_name}_h158_pattern1_profile.csv"
          "case3_${set_name}_h158_pattern2_profile.csv")
if [[ -f ${profiles[0]} && -f ${profiles[1]} && -f ${profiles[2]} ]]; then
  "$edem" --quiet --set none="${profiles[0]}" --set pattern1="${profiles[1]}" --set pattern2="${profiles[2]}" \
    run "$here/figure12.lua"
else  # rows kept by --resume from a case.lua before the profiles were written
  echo "study: no figure12.png: a profile of Case 3 at 158 m is missing (${profiles[*]})"
fi
exit $trends
