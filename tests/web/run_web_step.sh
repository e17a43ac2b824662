#!/usr/bin/env bash
# One step of the web build's tests (ctest label `web`), run from the project
# root: build (tsc, the catalog, the core in WebAssembly), unit (node's test
# runner), browser (the pages in Debian's Chromium against the native renders,
# then the page driven through its own controls, then its editor with the
# work kept in the browser, then a students' bundle
# served statically, then a submission downloaded from the page and graded,
# then a grading report read as an instructor reads it), parity (the page's Check
# against native's verdicts: every stage, every catalogued mistake in
# Chromium, a different sixth of them in Firefox and in WebKit; ctest labels
# web and web-parity). RAYLAB_BROWSER=firefox: in Firefox ESR instead
# of Chromium (ctest's web_browser_firefox, web_parity_firefox); webkit: in
# WebKitGTK, under an X display (web_parity_webkit).
# editor: the editor test alone (WebKitGTK runs it: web_editor_webkit).
#   run_web_step.sh build|unit|browser|parity|editor RAYLAB_EXE OUT_DIR LABGEN_EXE
set -euo pipefail
step=$1 raylab=$2 out=$3 labgen=${4:-}
cd "$(dirname "$0")/../.."
if ! command -v node >/dev/null || [ ! -d web/node_modules/typescript ]; then
  echo "web tests: node or web/node_modules is missing: run 'bash install.sh' (it runs 'npm ci' in web/)" >&2
  exit 1
fi
case "$step" in
  build) npm --prefix web run --silent build ;;
  unit) node --test web/tests/unit/ ;;
  browser|parity|editor)
    if [ "${RAYLAB_BROWSER:-}" = webkit ]; then
      command -v WebKitWebDriver >/dev/null ||
        { echo "web tests: WebKitWebDriver is missing: run 'bash install.sh --test' (webkit2gtk-driver)" >&2; exit 1; }
    elif [ "${RAYLAB_BROWSER:-}" = firefox ]; then
      [ -x /usr/bin/firefox-esr ] || [ -n "${RAYLAB_FIREFOX:-}" ] ||
        { echo "web tests: /usr/bin/firefox-esr is missing: run 'bash install.sh --test'" >&2; exit 1; }
    else
      [ -x /usr/bin/chromium ] || [ -n "${RAYLAB_CHROMIUM:-}" ] ||
        { echo "web tests: /usr/bin/chromium is missing: run 'bash install.sh --test'" >&2; exit 1; }
    fi ;;
esac
case "$step" in
  build|unit) ;;
  editor)
    # The editor alone (WebKitGTK's run: web_editor_webkit).
    node web/tests/browser/editor.mjs --raylab "$raylab" --labgen "$labgen" ;;
  browser)
    node web/tests/browser/render_views.mjs --raylab "$raylab" --out "$out"
    node web/tests/browser/page_ui.mjs
    # The grading report as an instructor reads it: the class table sorted
    # by keyboard, a student's page with its pictures and their alt text.
    node web/tests/browser/grade_report.mjs --raylab "$raylab" --labgen "$labgen"
    # The editor in the page, the work kept in the browser, driven by keys
    # and clicks only (no test API, as in a students' bundle).
    node web/tests/browser/editor.mjs --raylab "$raylab" --labgen "$labgen"
    # The bundle served statically and the downloaded submission graded
    # natively test the server, the bundle and native grading more than the
    # engine: Chromium runs them, the second engine the pages and the page.
    if [ "${RAYLAB_BROWSER:-}" != firefox ]; then
      node web/tests/browser/bundle.mjs --raylab "$raylab"
      # Folder mode through the folder input (Firefox's WebDriver cannot
      # hand an input a folder): a file saved on disk after it was read.
      node web/tests/browser/folder_mode.mjs
      node web/tests/browser/submission.mjs --raylab "$raylab" --labgen "$labgen"
    fi ;;
  parity)
    # Chromium checks every mistake; Firefox and WebKit each a different sixth.
    case "${RAYLAB_BROWSER:-}" in
      firefox) share=(--every 6 --offset 0) ;;
      webkit) share=(--every 6 --offset 3) ;;
      *) share=(--all) ;;
    esac
    node web/tests/browser/check_parity.mjs "${share[@]}" --labgen "$labgen" ;;
  *) echo "run_web_step.sh: unknown step '$step'" >&2; exit 2 ;;
esac
