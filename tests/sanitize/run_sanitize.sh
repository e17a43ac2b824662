#!/usr/bin/env bash
# ctest sanitize_* (label sanitize): the project built with gcc's
# AddressSanitizer + UndefinedBehaviorSanitizer in a build folder of its own,
# then its unit and numerics tests and a few headless renders run there.
#   run_sanitize.sh build  SOURCE_DIR BUILD_DIR   configure + build the needed targets
#   run_sanitize.sh tests  SOURCE_DIR BUILD_DIR   ctest -L unit|numerics in that build (not the sweeps)
#   run_sanitize.sh render SOURCE_DIR BUILD_DIR   raylab render --stage 01 / 08 (+ a debug view),
#                                                 and the fur track's f3 lab and f4 fur shader
# Every report (ASan, LeakSanitizer, UBSan) of every process, children
# included, is written to BUILD_DIR/sanitizer-reports-STEP/; any file there
# fails the step even if the process's exit code was swallowed (e.g. a test
# that expects `raylab` to fail). Third-party leaks only are suppressed, in
# lsan.supp next to this script. RAYLAB_TEST_JOBS: parallel jobs (default: all cores).
set -euo pipefail
step=$1 src=$2 bin=$3
jobs=${RAYLAB_TEST_JOBS:-$(nproc)}
here=$(cd "$(dirname "$0")" && pwd)

reports="$bin/sanitizer-reports-$step"
rm -rf "$reports"
mkdir -p "$reports"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:strict_init_order=1:log_path=$reports/asan"
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$reports/ubsan"

# Mesa's EGL unloads its DRI driver (llvmpipe) at eglTerminate. The driver
# keeps some allocations (184 bytes) reachable only from its own globals;
# once it is unloaded LeakSanitizer no longer scans them and reports a leak
# whose stack lies in "<unknown module>", which no suppression can name. Keeping
# the driver loaded (preloaded, so dlclose does not unmap it) removes that
# false report without hiding anything of ours. verify_asan_link_order=0:
# the driver comes before libasan in the preload list, which is harmless here.
keep_loaded() {
  local lib
  for lib in /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so /usr/lib64/dri/swrast_dri.so /usr/lib/dri/swrast_dri.so; do
    if [ -f "$lib" ]; then
      export LD_PRELOAD="$lib${LD_PRELOAD:+:$LD_PRELOAD}"
      export ASAN_OPTIONS="$ASAN_OPTIONS:verify_asan_link_order=0"
      return
    fi
  done
  echo "run_sanitize.sh: no swrast_dri.so found to keep loaded; Mesa's unloaded-driver leaks may be reported" >&2
}

check_reports() {
  local found=0
  for f in "$reports"/*; do
    [ -e "$f" ] || continue
    found=1
    echo "==== sanitizer report $f" >&2
    cat "$f" >&2
  done
  if [ "$found" -ne 0 ]; then echo "FAIL: sanitizer reports above (step $step)" >&2; exit 1; fi
}
trap check_reports EXIT

case "$step" in
  build)
    # -O0 -g1: compiles twice as fast as -O1 -g (the build is most of this
    # group's time). gcc, the compiler of the main build: clang 14 compiles
    # this build a fifth faster, but its -O0 build loses one first hit in
    # 40,000 in ShellSlots.EveryFirstHitIsAmongTheSlots (a rounding edge
    # gcc's builds do not meet; not yet understood).
    # -Wno-maybe-uninitialized: gcc 12 false positives inside <regex> with sanitizers.
    # UBSan without its pointer checks (null, alignment, object-size,
    # pointer-overflow): ASan reports the bad accesses they look for, and
    # they were a third of this build (raylab_cli's first unity file: 20.7 s
    # with them, 13.7 s without, 13.4 s with ASan alone); the arithmetic
    # checks (signed overflow, shifts, float-to-int, division by zero, bool
    # and enum loads, array bounds, a missing return) stay.
    flags="-fsanitize=address,undefined -fno-sanitize=null,alignment,object-size,pointer-overflow -fno-omit-frame-pointer -fno-sanitize-recover=all -Wno-maybe-uninitialized"
    cmake -S "$src" -B "$bin" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=g++ \
      "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g1" \
      "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
    # Only what the steps below run (raylab and raylab-labgen come with the tests).
    cmake --build "$bin" -j "$jobs" --target unit_tests numerics_tests bench_report_tests raylab
    ;;
  tests)
    keep_loaded
    # Without the sweeps that repeat one code path over many scales, places
    # or distances (the reference tracer at -O0 made them three quarters of
    # this step's time): each path they take runs here once, in the same
    # test at one scale (LightBuffer.EveryBlockingSphereIsInTheRaysCell,
    # SceneScaleCommand.*, the torus and BVH tests beside them).
    sweeps='AtAnyScaleAndPlace|^DemoScenes/SceneScale\.|AtEveryDistance|AHugeMeshFitsTheGlslStack'
    ctest --test-dir "$bin" -L '^(unit|numerics)$' -E "$sweeps" --output-on-failure -j "$jobs"
    ;;
  render)
    keep_loaded
    out="$bin/sanitize-renders"
    mkdir -p "$out"
    "$bin/raylab" render --stage 01 --out "$out/stage01.png"
    "$bin/raylab" render --stage 08 --out "$out/stage08.png"
    "$bin/raylab" render --stage 05 --view depth --out "$out/stage05-depth.png"
    "$bin/raylab" render --stage f3 --out "$out/f3.png"
    "$bin/raylab" render --stage f4 --solution --technique fur_shader --out "$out/f4.png"
    ;;
  *) echo "run_sanitize.sh: unknown step '$step' (build, tests, render)" >&2; exit 2 ;;
esac
