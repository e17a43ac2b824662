#!/usr/bin/env bash
# Sets up RayLab on Debian 12 / Ubuntu 22.04+: installs the packages it needs
# with apt, then configures and builds Release into build/. Safe to run twice.
#   bash install.sh          what the demo, the window, the students' and the
#                            instructors' commands and the page need; builds
#                            raylab and its tools (no test binaries)
#   bash install.sh --test   that, plus the test tools (browsers, WebKit's
#                            driver, Slurm, libFuzzer, Xvfb, gnuplot, Embree,
#                            ...) and the test binaries, then the whole suite
set -euo pipefail
cd "$(dirname "$0")"

run_tests=0
for arg in "$@"; do
  case "$arg" in
    --test) run_tests=1 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "install.sh: unknown option '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake pkg-config                 # toolchain
  libsdl2-dev libsdl2-image-dev                    # window, input, PNG I/O
  libglew-dev libglm-dev libgl1-mesa-dev           # OpenGL loading and maths
  libegl-dev libegl1-mesa-dev libgl1-mesa-dri      # headless EGL (surfaceless Mesa, llvmpipe)
  libosmesa6-dev                                   # headless OSMesa backend
  libzip-dev                                       # zip uploads (PrairieLearn keeps a zip as a file)
  libsodium-dev                                    # keyed pseudonyms (raylab grade --anonymise)
  libcli11-dev nlohmann-json3-dev                  # command line, scene files
  libtinyobjloader-dev                             # OBJ meshes (fur track)
  libimgui-dev                                     # on-screen overlay (Dear ImGui + its SDL2/OpenGL3 backends)
  emscripten                                       # the web page's core: the C++ CPU modules in WebAssembly
  zip unzip                                        # `raylab autograder` (Gradescope's zip)
  python3-venv                                     # `raylab similarity`'s detector (copydetect, PyPI)
)
# What only the tests and the benchmarks need (install.sh --test).
test_packages=(
  libgtest-dev libgmock-dev                        # the test suite (GoogleTest)
  glslang-tools                                    # Khronos reference GLSL compiler (tests)
  gnuplot-nox                                      # `raylab bench`'s speed-vs-error plot (bench.png)
  libembree-dev                                    # `raylab bench`'s embree-cast row (optional in CMake)
  xvfb xauth                                       # windowed-mode tests without a display
  clang libclang-rt-14-dev clang-format            # libFuzzer targets (ctest -L fuzz), tools/check-format.sh
  chromium                                         # the web build's tests (ctest -L web): WebGL 2 headless
  firefox-esr                                      # the same tests in a second engine (ctest -L firefox)
  webkit2gtk-driver                                # the page's Check in WebKitGTK, Safari's engine (ctest -L webkit)
  slurm-wlm munge                                  # the cluster test (ctest -L cluster): a one-node Slurm cluster
)
[ "$run_tests" -eq 0 ] || packages+=("${test_packages[@]}")
# The web build (web/) compiles with TypeScript from the npm registry: Node.js
# and npm from Debian unless a Node.js is already installed (NodeSource's
# nodejs package brings its own npm and conflicts with Debian's).
command -v npm >/dev/null || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  echo "install.sh: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Downloads, while the C++ compiles (they wait on the network, the compiler
# on the CPU): the exact packages of web/package-lock.json, and `raylab
# similarity`'s detector, copydetect from PyPI, in its own virtual
# environment (tools/similarity/requirements.txt pins it).
mkdir -p build
trap 'kill $(jobs -p) 2>/dev/null || true' EXIT
npm --prefix web ci --no-audit --no-fund --loglevel=error > build/npm-ci.log 2>&1 &
npm_ci=$!
{ [ -x tools/similarity/.venv/bin/python ] || python3 -m venv tools/similarity/.venv
  tools/similarity/.venv/bin/pip install -q --disable-pip-version-check -r tools/similarity/requirements.txt
} > build/similarity-venv.log 2>&1 &
venv=$!
# (A download that failed says so after the build, with its log.)
finished() {  # PID WHAT LOG
  wait "$1" && return 0
  cat "$3" >&2
  echo "install.sh: $2 failed (its output is above and in $3)" >&2
  exit 1
}

# The test binaries only with --test (a quarter of the build); a build
# folder that already has them keeps them.
tests=OFF
{ [ "$run_tests" -eq 1 ] || grep -q '^RAYLAB_BUILD_TESTS:BOOL=ON' build/CMakeCache.txt 2>/dev/null; } && tests=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAYLAB_BUILD_TESTS=$tests
cmake --build build -j "$(nproc)"
echo "install.sh: built build/raylab$([ $tests = ON ] && echo ' and the tests')"

# The web build: tsc, the editor's bundle, the core in WebAssembly.
finished $npm_ci "npm ci (web/)" build/npm-ci.log
npm --prefix web run --silent build
echo "install.sh: built web/dist (serve it with: npm --prefix web run serve)"

finished $venv "setting up tools/similarity/.venv (copydetect)" build/similarity-venv.log
echo "install.sh: set up tools/similarity/.venv (copydetect)"

if [ "$run_tests" -eq 1 ]; then
  ctest --test-dir build --output-on-failure -j "$(nproc)"
fi
