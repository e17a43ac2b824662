#!/usr/bin/env bash
# ctest fuzz_build (label fuzz): configures and builds tests/fuzz with clang in
# a build folder of its own.   build_fuzzers.sh SOURCE_DIR BUILD_DIR
# Fails (never skips) when clang or its libFuzzer runtime is missing.
# RAYLAB_TEST_JOBS: parallel compile jobs (default: all cores).
set -euo pipefail
src=$1 bin=$2
cxx=${RAYLAB_FUZZ_CXX:-clang++}
if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "FAIL: '$cxx' not found. The fuzz tests need clang with libFuzzer:" >&2
  echo "      apt-get install clang libclang-rt-14-dev   (bash install.sh --test installs them)" >&2
  exit 1
fi
cmake -S "$src" -B "$bin" -DCMAKE_CXX_COMPILER="$(command -v "$cxx")" -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$bin" -j "${RAYLAB_TEST_JOBS:-$(nproc)}"
