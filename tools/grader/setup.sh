#!/usr/bin/env bash
# Installs what grading needs and builds RayLab headless (-DRAYLAB_WINDOW=OFF:
# no window, no Dear ImGui) into build/. Gradescope runs it as setup.sh at
# the root of `raylab autograder`'s bundle (as root, in /autograder/source);
# examples/prairielearn/Dockerfile runs it from the tree.
# Targets Ubuntu 22.04 (Gradescope's default image; packages from main and
# universe) and Debian 12, where it is tested.
#   bash setup.sh            apt-get install, then build
#   bash setup.sh --no-apt   build only (the packages are installed already)
#   --configure-only         stop after CMake (the tests: a full build takes minutes)
# RAYLAB_BUILD_DIR overrides the build folder (default: build/ in the sources).
set -euo pipefail

apt=1
configure_only=0
for arg in "$@"; do
  case "$arg" in
    --no-apt) apt=0 ;;
    --configure-only) configure_only=1 ;;
    -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

# At the bundle's root the sources are beside this script; in the tree it
# lives in tools/grader/.
here="$(cd "$(dirname "$0")" && pwd)"
if [ -f "$here/CMakeLists.txt" ]; then src="$here"; else src="$(cd "$here/../.." && pwd)"; fi
build="${RAYLAB_BUILD_DIR:-$src/build}"

# What the headless build and grading use: no libimgui-dev, no test tools.
packages=(
  build-essential cmake pkg-config                 # toolchain (Ubuntu 22.04: gcc 11, cmake 3.22)
  libsdl2-dev libsdl2-image-dev                    # PNG I/O (SDL2_image); no window is opened
  libglew-dev libglm-dev libgl1-mesa-dev           # OpenGL loading and maths
  libegl-dev libegl1-mesa-dev libgl1-mesa-dri      # headless EGL on Mesa llvmpipe
  libosmesa6-dev                                   # the OSMesa fallback
  libzip-dev                                       # zip uploads (PrairieLearn keeps a zip as a file)
  libsodium-dev                                    # keyed pseudonyms (raylab grade --anonymise)
  libcli11-dev nlohmann-json3-dev                  # command line, scene files (universe on Ubuntu)
  libtinyobjloader-dev                             # OBJ meshes (fur track; universe on Ubuntu)
)
if [ "$apt" -eq 1 ]; then
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}"
fi

cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAYLAB_WINDOW=OFF -DRAYLAB_BUILD_TESTS=OFF
[ "$configure_only" -eq 0 ] || { echo "setup.sh: configured $build"; exit 0; }
cmake --build "$build" -j "$(nproc)" --target raylab
echo "setup.sh: built $build/raylab (headless)"
