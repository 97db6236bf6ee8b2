#!/usr/bin/env bash
# Regenerates EDEM's documentation from the repository, with one command:
#   bash scripts/make-docs.sh [BUILD_DIR]      (default: build; build it first)
# - the language reference in README.md, from the command schema (`edem reference --update`);
# - the main example's picture, scripts/examples/jointed_cavern.png, which README.md shows, and
#   the staged tunnel tutorial's crown history and cracks (tunnel_crown.png, tunnel_cracks.png);
# - the verification chapter, tests/verification/README.md: each verification script run with
#   `--set report=DIR` writes its own section (its opening comment, a table of its checks and a
#   chart of their errors against their tolerances, edem.check), assembled in file order.
# The speed and accuracy charts next to the benchmarks are remade by their benchmark commands
# (tests/bench/RESULTS.md), which take minutes of quiet machine each.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
edem=$build/interp/edem
[ -x "$edem" ] || { echo "make-docs: no $edem; build EDEM first" >&2; exit 1; }

"$edem" reference --update "$root/README.md"

(cd "$root/scripts/examples" && "$edem" --quiet run jointed_cavern.lua)
echo "make-docs: scripts/examples/jointed_cavern.png"
(cd "$root/scripts/examples" && "$edem" --quiet run staged_tunnel.lua > /dev/null)
echo "make-docs: scripts/examples/tunnel_crown.png, tunnel_cracks.png"

chapter=$root/tests/verification
report=$chapter/report
rm -rf "$report" && mkdir -p "$report"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scripts=("$chapter"/*.lua)
# Side by side, one thread each (as ctest runs them); a failing script fails the command.
printf '%s\n' "${scripts[@]}" | OMP_NUM_THREADS=1 xargs -P "$(nproc)" -I{} sh -c \
  'name=$(basename "$1" .lua); mkdir -p "$2/$name" && cd "$2/$name" && "$3" --quiet --set report="$4" run "$1" > "$2/$name.log" 2>&1 || { echo "make-docs: $1 failed:"; tail -5 "$2/$name.log"; exit 255; }' \
  _ {} "$work" "$edem" "$report"

{
  cat <<'HEAD'
# Verification

Each problem below is a script in this folder, run by ctest (`ctest -L verification`); it
prints every measured value beside the closed-form or published one, the error and the
tolerance; its opening comment, the text of its section below, names the source of the closed
form and why the tolerance is what it is. This chapter is what those scripts wrote the last time
`bash scripts/make-docs.sh` ran: the table of checks, and a chart of each check's error over its
tolerance (below 1 passes). Scripts under `long/` take minutes and run with `ctest -L long`.

HEAD
  for script in "${scripts[@]}"; do
    name=$(basename "$script" .lua)
    cat "$report/$name.md"
    echo
  done
} > "$chapter/README.md"
rm "$report"/*.md  # assembled into the chapter; the charts stay beside it
echo "make-docs: tests/verification/README.md (${#scripts[@]} problems)"
