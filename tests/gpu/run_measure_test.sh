#!/bin/bash
# tools/gpu/measure.sh here, on llvmpipe, in its quick mode (ctest label
# gpu): the command docs/bench/README.md shows runs as written and gives a
# table of every stage and both tracks; a wrong reference picture makes it
# fail and name the view; bad usage is a one-line error.
#   run_measure_test.sh RAYLAB_EXE   (ctest passes this build's binary)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
raylab=${1:?usage: run_measure_test.sh RAYLAB_EXE}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A folder laid out like the RayLab folder, so the docs' command runs as
# written (its output stays out of the source tree); RAYLAB (measure.sh's
# override) is the binary under test, from whatever build folder ctest used.
export RAYLAB=$raylab
mkdir -p "$tmp/raylab"
for part in tools tests assets framework solution labs CMakeLists.txt; do
    ln -s "$root/$part" "$tmp/raylab/$part"
done
cd "$tmp/raylab"
tools/gpu/measure.sh --quick --out gpu-quick >"$tmp/quick.txt" 2>"$tmp/quick.err" ||
    fail "the quick run failed: $(tail -3 "$tmp/quick.err")"
table=gpu-quick/measure.md
grep -q '^# RayLab measured on OpenGL' "$table" || fail "no GL strings in $table"
stages=$("$raylab" stages | grep -c '^  [0-9a-z]')
passed=$(grep -c '^| [0-9a-z-]* | pass |' "$table" || true)
[[ $passed == "$stages" ]] || fail "$passed of $stages stages pass in $table"
grep -q '^| 160x120 | lite |' "$table" || fail "no ray-tracer bench row in $table"
grep -q '^| .* | sphere, [0-9]* |' "$table" || fail "no fur bench row in $table"
cmp -s "$table" <(sed -n '/^# RayLab/,$p' "$tmp/quick.txt") || fail "the printed table is not $table"

# A wrong reference: stage 01's front view compared with another picture.
mkdir -p "$tmp/refs"
cp -r "$root/tests/reference/01-raycast" "$tmp/refs/"
cp "$tmp/refs/01-raycast/moving.png" "$tmp/refs/01-raycast/front.png"
if tools/gpu/measure.sh --no-bench --stages 01 --references "$tmp/refs" --out "$tmp/wrong" \
    >/dev/null 2>&1; then
    fail "a wrong reference picture passed"
fi
grep -q '^| 01-raycast | FAIL | 5/6 | .* | front |' "$tmp/wrong/measure.md" ||
    fail "the failed view is not named: $(grep 01-raycast "$tmp/wrong/measure.md")"

# Bad usage: exit 2, one line naming the cause, nothing written.
set +e
err=$(tools/gpu/measure.sh --stages 99 --out "$tmp/bad" 2>&1 >/dev/null)
rc=$?
set -e
[[ $rc == 2 ]] || fail "an unknown stage exited $rc, not 2"
[[ ! -e $tmp/bad ]] || fail "an unknown stage still wrote $tmp/bad"
[[ $(wc -l <<<"$err") == 1 && $err == *"unknown stage '99'"* ]] || fail "unclear error: $err"
err=$(tools/gpu/measure.sh --frobnicate 2>&1 >/dev/null) && fail "an unknown option passed"
[[ $err == *"unknown option '--frobnicate'"* ]] || fail "unclear error: $err"
echo "measure.sh: quick run, wrong reference and bad usage behave"
