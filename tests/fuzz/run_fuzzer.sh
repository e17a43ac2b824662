#!/usr/bin/env bash
# ctest fuzz_* (label fuzz): runs one libFuzzer target for SECONDS over a fresh
# copy of its committed seed corpus (new inputs go to the copy, never to the
# source tree).   run_fuzzer.sh FUZZER CORPUS WORK_DIR SECONDS
# Any crash, sanitizer report, uncaught exception, leak, timeout (one input
# over 10 s) or out-of-memory makes libFuzzer exit non-zero: the test fails and
# the input that did it is left in WORK_DIR/artifacts.
set -uo pipefail
fuzzer=$1 corpus=$2 work=$3 seconds=$4
[ -x "$fuzzer" ] || { echo "FAIL: $fuzzer not built (see the fuzz_build test)" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
cp -R "$corpus/." "$work/corpus/"
cd "$work"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus"
rc=$?
if [ "$rc" -ne 0 ]; then
  echo "FAIL: $(basename "$fuzzer") exited with $rc. Inputs that did it:" >&2
  for f in "$work"/artifacts/*; do [ -e "$f" ] && echo "  $f   (reproduce: $fuzzer $f)" >&2; done
  exit 1
fi
