#!/usr/bin/env bash
# The seed paper's study: scripts/paper/case.lua for each row of a table, run by edem sweep, then
# the trends judged over the rows the sweep gathered (trends.lua) and the seed's Figure 12.
#
#   bash scripts/paper/study.sh OUT [TABLE] [edem sweep options: --jobs N, --threads M, --resume,
#                                    --only NAME, --collect, --slurm ..., --set KEY=VALUE ...]
#
#   OUT    the sweep's folder: a folder a run (its log, rows, pictures), sweep.csv, trends.md (the
#          verdicts at the runs' ends), trends_common_step.md (after the last step all runs
#          reached), trends_means.md (a table with members: on their means), figure12.png
#   TABLE  study.csv: Cases 1, 2, 3 at 158 m, Case 3 at 212 and 262 m, Case 3 at 158 m with bolt
#          patterns 1 and 2 [default]; study_members.csv: each of those also as its mirror image
#          and with its cuts laid through another point, judged on the members' means too
#   The reduced study (the default suite's): --set edge=3 --set far=20 --set stages=8
#   --set step_cycles=20000. Set M:
#   --set set=M. EDEM=PATH picks the edem [build/interp/edem].
# Exit 1 when a run failed or has no row (with --collect: has not run), else trends.lua's status.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
edem=${EDEM:-build/interp/edem}
out=${1:?give the folder of the study: bash scripts/paper/study.sh OUT [TABLE] [sweep options]}
shift
table=$here/study.csv
if [[ $# -gt 0 && $1 != -* ]]; then table=$1; shift; fi
set_name=P
for option in "$@"; do [[ $option == set=* ]] && set_name=${option#set=}; done

ran=0
"$edem" sweep --out "$out" "$@" "$table" "$here/case.lua" || ran=$?
[[ " $* " == *" --only "* || " $* " == *" --slurm "* ]] && exit $ran  # one run, or runs still to come
judge=(--quiet --set sweep="$out" --set set="$set_name")
"$edem" "${judge[@]}" --set step=common --set markdown="$out/trends_common_step.md" run "$here/trends.lua"
echo
trends=0
"$edem" "${judge[@]}" --set markdown="$out/trends.md" run "$here/trends.lua" || trends=$?
if head -n 1 "$table" | grep -q mirror; then  # members: the same rows judged on their means
  echo
  "$edem" "${judge[@]}" --set judge=means --set markdown="$out/trends_means.md" run "$here/trends.lua" || trends=$?
fi
profiles=()
for name in case3 case3_pattern1 case3_pattern2; do
  profiles+=("$(ls "$out/$name"/case3_"${set_name}"_h158_*_profile.csv 2>/dev/null | head -n 1)")
done
if [[ -n ${profiles[0]} && -n ${profiles[1]} && -n ${profiles[2]} ]]; then
  "$edem" --quiet --set none="${profiles[0]}" --set pattern1="${profiles[1]}" --set pattern2="${profiles[2]}" \
    --set file="$out/figure12.png" run "$here/figure12.lua"
fi
(( ran == 0 )) || exit 1
exit $trends
