#!/usr/bin/env bash
# Sets up RayLab on Debian 12 / Ubuntu 22.04+: installs the packages it needs
# with apt, then configures and builds Release into build/. Safe to run twice.
#   bash install.sh          install + build
#   bash install.sh --test   install + build + run the whole test suite
set -euo pipefail
cd "$(dirname "$0")"

run_tests=0
for arg in "$@"; do
  case "$arg" in
    --test) run_tests=1 ;;
    -h|--help) sed -n '2,5p' "$0"; exit 0 ;;
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
  libgtest-dev libgmock-dev                        # tests
  glslang-tools                                    # Khronos reference GLSL compiler (tests)
  gnuplot-nox                                      # `raylab bench` speed-vs-error plot (bench.png)
  libembree-dev                                    # `raylab bench`'s embree-cast row (optional in CMake)
  xvfb xauth                                       # windowed-mode tests without a display
  clang libclang-rt-14-dev clang-format            # tests: libFuzzer targets (ctest -L fuzz), tools/check-format.sh
  chromium                                         # the web build's tests (ctest -L web): WebGL 2 headless
  firefox-esr                                      # the same tests in a second engine (ctest -L firefox)
  webkit2gtk-driver                                # the page's Check in WebKitGTK, Safari's engine (ctest -L webkit)
  emscripten                                       # the web page's core: the C++ CPU modules in WebAssembly
  slurm-wlm munge                                  # the cluster test (ctest -L cluster): a one-node Slurm cluster
  zip unzip                                        # `raylab autograder` (Gradescope's zip) and its test
  python3-venv                                     # `raylab similarity`'s detector (copydetect, PyPI)
)
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

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
echo "install.sh: built build/raylab"

# The web build: the exact packages of web/package-lock.json, then tsc.
npm --prefix web ci --no-audit --no-fund --loglevel=error
npm --prefix web run --silent build
echo "install.sh: built web/dist (serve it with: npm --prefix web run serve)"

# `raylab similarity`'s detector: copydetect from PyPI in its own virtual
# environment (tools/similarity/requirements.txt pins it).
[ -x tools/similarity/.venv/bin/python ] || python3 -m venv tools/similarity/.venv
tools/similarity/.venv/bin/pip install -q --disable-pip-version-check -r tools/similarity/requirements.txt
echo "install.sh: set up tools/similarity/.venv (copydetect)"

if [ "$run_tests" -eq 1 ]; then
  ctest --test-dir build --output-on-failure -j "$(nproc)"
fi
