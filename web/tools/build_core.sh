#!/usr/bin/env bash
# Builds the page's core: the C++ CPU modules compiled to WebAssembly by
# Debian's emscripten from the project's own CMake files, into
# build-wasm/ (beside build/), and copies raylab_core.js into web/dist/core/.
# Run by `npm run build` (so by install.sh and the web tests).
#   web/tools/build_core.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/build-wasm}
if ! command -v emcmake >/dev/null; then
  echo "build_core.sh: emscripten is missing: run 'bash install.sh' (Debian's emscripten package)" >&2
  exit 1
fi
# emscripten's optimiser needs Debian's acorn when node is not Debian's own.
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs
if [ ! -f "$out/CMakeCache.txt" ]; then
  emcmake cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$out" --target raylab_web_core -j "$(nproc)" -- --no-print-directory >/dev/null
# A folder of its own, marked CommonJS (web/ is an ES-module package; the
# core is a classic script the page loads with <script> and node with require).
dist=$root/web/dist/core
mkdir -p "$dist"
echo '{ "type": "commonjs" }' > "$dist/package.json"
cp "$out/raylab_core.js" "$dist/raylab_core.js.tmp"
mv "$dist/raylab_core.js.tmp" "$dist/raylab_core.js"
echo "web: built dist/core/raylab_core.js ($(( $(stat -c %s "$dist/raylab_core.js") / 1024 )) KB)"
