#!/bin/bash
# One stage's solution through its own `raylab check --solution` on Mesa's
# softpipe (ctest label softpipe): the views rendered twice there, the
# function checks against their double-precision references, as grading on
# a machine with that driver would run them.
#   run_softpipe_check.sh RAYLAB_EXE STAGE SIZE [CHECKS]
# CHECKS: raylab check --checks (default: all of the stage's checks); what
# softpipe's bugs keep out is listed in tests/CMakeLists.txt.
set -euo pipefail
usage="usage: run_softpipe_check.sh RAYLAB_EXE STAGE SIZE [CHECKS]"
raylab=${1:?$usage} stage=${2:?$usage} size=${3:?$usage} checks=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export GALLIUM_DRIVER=softpipe

# The driver really is softpipe (a Mesa without it would run nothing here,
# or another driver).
"$raylab" demo --stage 01 --headless --frames 1 --size 8x6 --backend egl --out "$tmp/probe" \
    >"$tmp/probe.txt" 2>&1 || { echo "FAIL: $(tail -1 "$tmp/probe.txt")" >&2; exit 1; }
grep -q ' on softpipe$' "$tmp/probe.txt" ||
    { echo "FAIL: GALLIUM_DRIVER=softpipe gave: $(head -1 "$tmp/probe.txt")" >&2; exit 1; }

args=(check --stage "$stage" --solution --size "$size" --backend egl --timeout 300)
[[ -n $checks ]] && args+=(--checks "$checks")
"$raylab" "${args[@]}"
