#!/usr/bin/env bash
# Runs out_of_memory.lua under a 600 MB address-space limit: it must stop with status 1 and an
# error naming the loop's line (7), not a bare "not enough memory".
# Usage: out_of_memory.sh EDEM
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# AddressSanitizer reserves terabytes of address space and cannot start under a limit.
[[ -z ${ASAN_OPTIONS:-} ]] || { echo "SKIP: no address-space limit under AddressSanitizer"; exit 77; }
err=$(cd "$here" && ulimit -v 600000 && "$1" --quiet --threads 1 run out_of_memory.lua 2>&1 >/dev/null)
status=$?
echo "status $status: $err"
[[ $status == 1 ]] || { echo "FAIL: expected status 1"; exit 1; }
[[ $err == "out_of_memory.lua:7: memory: not enough memory"* ]] || { echo "FAIL: the error names no line"; exit 1; }
echo "out_of_memory: the line named"
