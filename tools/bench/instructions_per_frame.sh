#!/bin/bash
# Instructions one headless demo frame costs on llvmpipe, counted by
# callgrind (valgrind) rather than timed: on a shared machine frame times
# move by 10-30% between runs, instruction counts by well under 1%.
#
#   tools/bench/instructions_per_frame.sh [ROOT] [raylab demo options...]
#
# ROOT: a RayLab tree whose shaders to run (default: this one); the shaders
# are read at run time (RAYLAB_ROOT), so a copy with one edited file measures
# that edit against the original with the same binary. Options go to
# `raylab demo --headless` (e.g. --depth 1, --no-shadows); the scene and
# size come from SCENE (default pro) and SIZE (default 200x150). Prints millions of instructions per frame:
# (a 3-frame run minus a 1-frame run) / 2, after a warm-up run that fills
# Mesa's shader cache for valgrind's view of the CPU. LP_NUM_THREADS=0 keeps
# llvmpipe's work on the counted thread. About 3 minutes at 200x150.
# Used for docs/bench/README.md, "Where a pro frame's instructions go".
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '2,16p' "$0"; exit 0 ;; esac
here=$(cd "$(dirname "$0")/../.." && pwd)
root=$here
if [[ $# -gt 0 && -d $1 ]]; then root=$(cd "$1" && pwd); shift; fi
raylab=${RAYLAB:-$here/build/raylab}
command -v valgrind >/dev/null || { echo "instructions_per_frame.sh: valgrind not found (apt install valgrind)" >&2; exit 2; }
[[ -x $raylab ]] || { echo "instructions_per_frame.sh: $raylab not built" >&2; exit 2; }
scene=${SCENE:-pro} size=${SIZE:-200x150}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
count() {
    local log
    log=$(RAYLAB_ROOT=$root LP_NUM_THREADS=0 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        "$raylab" demo --headless --scene "$scene" --size "$size" --frames "$1" --out "$out/f$1" "${@:2}" 2>&1) ||
        { echo "instructions_per_frame.sh: raylab demo failed: $(tail -1 <<<"$log")" >&2; exit 1; }
    rm -rf "$out/f$1"
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p' <<<"$log"
}
count 1 "$@" >/dev/null
one=$(count 1 "$@")
three=$(count 3 "$@")
echo "$(( (three - one) / 2 / 1000000 )) M instructions per frame ($root, demo --scene $scene --size $size $*)"
