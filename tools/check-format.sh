#!/usr/bin/env bash
# Checks that every tracked C++ file (*.cpp, *.h) is formatted as .clang-format
# says; lists the files that are not and exits 1. Also ctest `format`.
#   tools/check-format.sh            check
#   clang-format -i FILE...          fix (or: git ls-files '*.cpp' '*.h' | xargs clang-format -i)
# There are no third-party sources in the tree; add exclusions here if any come.
set -uo pipefail
case "${1:-}" in
  -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
  "") ;;
  *) echo "check-format.sh: takes no arguments (try --help)" >&2; exit 2 ;;
esac
cd "$(dirname "$0")/.."
cf=${CLANG_FORMAT:-clang-format}
if ! command -v "$cf" >/dev/null 2>&1; then
  echo "FAIL: '$cf' not found: apt-get install clang-format (bash install.sh --test installs it)" >&2
  exit 1
fi
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "FAIL: $(pwd) is not a git work tree (the check formats tracked files)" >&2
  exit 1
fi
bad=()
while IFS= read -r -d '' f; do
  "$cf" --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(git ls-files -z -- '*.cpp' '*.h')
if [ ${#bad[@]} -gt 0 ]; then
  echo "Not formatted as .clang-format says (${#bad[@]} files; fix with clang-format -i):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "All tracked C++ files are formatted."
