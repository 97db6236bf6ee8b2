#!/usr/bin/env bash
# The floor plan as layers: a source folder may include only itself and the folders below it.
#
#   interp/          the Lua commands
#   model/           the Model facade: every Model:: method
#   solver/          the cycle, its stages, runs to a criterion, excavation's release
#   prepass/ bolt/ crack/ contact/ constitutive/   the physics, in this order
#   state/           the flat arrays and the types they hold
#   io/ geom/        files and pictures; polygons, cutting and zoning
#   core/            ids, errors, vectors, the Def vocabulary
#
# Usage: layers.sh SOURCE_DIR. Prints each include that runs back up and exits 1 if there is one.
set -euo pipefail
root=${1:?usage: layers.sh SOURCE_DIR}

order=(interp model solver prepass bolt crack contact constitutive state io geom core)
rank() {  # position of a folder in `order`; empty when it is not a layer (a system header)
  local i
  for i in "${!order[@]}"; do [[ ${order[$i]} == "$1" ]] && { echo "$i"; return 0; }; done
  return 0
}

bad=0 files=0
for layer in "${order[@]}"; do
  if [[ $layer == interp ]]; then dir=$root/interp; else dir=$root/engine/$layer; fi
  [[ -d $dir ]] || { echo "layers: no folder $dir"; exit 1; }
  mine=$(rank "$layer")
  while IFS= read -r file; do
    files=$((files + 1))
    while IFS=: read -r line target; do
      theirs=$(rank "${target%%/*}")
      if [[ -n $theirs && $theirs -lt $mine ]]; then
        echo "${file#"$root"/}:$line: includes \"$target\": $layer may not include ${target%%/*}, a layer above it"
        bad=$((bad + 1))
      fi
      if [[ $target == *..* ]]; then
        echo "${file#"$root"/}:$line: includes \"$target\": name includes from the source root, not by .."
        bad=$((bad + 1))
      fi
    done < <(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" |
             sed -E 's/^([0-9]+):[^"]*"([^"]*)".*/\1:\2/' || true)
  done < <(find "$dir" -maxdepth 1 -name '*.[ch]pp' | sort)
done

echo "layers: ${#order[@]} folders, $files files, $bad includes that run back up"
[[ $bad == 0 ]]
