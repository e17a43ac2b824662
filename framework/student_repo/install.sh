#!/usr/bin/env bash
# Sets up this RayLab repository on Debian 12 / Ubuntu 22.04+ (also under
# WSL on Windows): installs the packages it needs with apt, then builds
# build/raylab. Safe to run twice: the second time it only rebuilds.
set -euo pipefail
cd "$(dirname "$0")"

case "${1:-}" in
  "") ;;
  -h|--help) sed -n '2,4p' "$0"; exit 0 ;;
  *) echo "install.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
esac

packages=(
  build-essential cmake pkg-config                 # compiler and build
  libsdl2-dev libsdl2-image-dev                    # window, input, PNG files
  libglew-dev libglm-dev libgl1-mesa-dev           # OpenGL and its maths
  libegl-dev libegl1-mesa-dev libgl1-mesa-dri      # drawing without a window (checks)
  libosmesa6-dev                                   # a second way to draw without a window
  libcli11-dev nlohmann-json3-dev                  # command line, scene files
  libtinyobjloader-dev                             # OBJ meshes (fur track)
  libimgui-dev                                     # the window's overlay
)
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
echo "install.sh: built build/raylab (try: build/raylab stages)"
