#!/usr/bin/env bash
# Runs the analysis-overlay tests in the real FreeCAD GUI under Xvfb (tests/gui/overlays).
# Ends with "N passed, N failed, N skipped", writes those three numbers to
# $NURBSLOD_TEST_RESULTS when set (the format of scripts/test.sh's stages), and exits non-zero
# when a test failed. Without xvfb-run or freecad the tests count as skipped.
#
#   bash tests/gui/run_overlay_tests.sh [SCREENSHOT_DIR]
#
# SCREENSHOT_DIR (default: a temporary folder, removed at the end) keeps the screenshots;
# tests/gui/screenshots holds reference ones.
set -uo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
BUILD_DIR="${NURBSLOD_BUILD_DIR:-$ROOT/build}"
TEST_COUNT=12  # len(TESTS) in overlays/overlay_cases.py, for the skip count
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
SHOTS="${1:-$WORK/screenshots}"
mkdir -p "$SHOTS"
SHOTS=$(cd "$SHOTS" && pwd)

report() {
    echo "$1 passed, $2 failed, $3 skipped"
    if [ -n "${NURBSLOD_TEST_RESULTS:-}" ]; then
        echo "$1 $2 $3" >"$NURBSLOD_TEST_RESULTS"
    fi
}

for tool in xvfb-run freecad; do
    if ! command -v "$tool" >/dev/null; then
        echo "overlay GUI tests skipped: $tool is not installed"
        report 0 0 "$TEST_COUNT"
        exit 0
    fi
done

# A home of its own, where this checkout is the only user workbench (as in scripts/test.sh).
home="$WORK/home"
mkdir -p "$home/.local/share/FreeCAD/Mod"
ln -s "$ROOT" "$home/.local/share/FreeCAD/Mod/NurbsLOD"

(
    cd "$WORK" &&
        env -u XDG_DATA_HOME -u XDG_CONFIG_HOME -u XDG_CACHE_HOME HOME="$home" \
            NURBSLOD_BUILD_DIR="$BUILD_DIR" NURBSLOD_GUI_TEST_DIR="$ROOT/tests/gui/overlays" \
            NURBSLOD_SCREENSHOT_DIR="$SHOTS" NURBSLOD_TEST_RESULTS="$WORK/counts" \
            NURBSLOD_CORPUS_DIR="${NURBSLOD_CORPUS_DIR:-$ROOT/../shared/corpus}" \
            QTWEBENGINE_CHROMIUM_FLAGS="--no-sandbox --disable-gpu" \
            timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24" \
            freecad "$ROOT/tests/gui/overlays/overlay_gui_test.py" </dev/null 2>&1 |
        grep -v -e '^$' -e 'Addon Manager' -e '^ *#' -e ' passed, .* failed, .* skipped$'
)
if read -r passed failed skipped <"$WORK/counts" 2>/dev/null; then
    report "$passed" "$failed" "$skipped"
    [ "$failed" -eq 0 ]
    exit
fi
echo "overlay GUI tests: FreeCAD ended without a report (crash or time-out)" >&2
report 0 1 0
exit 1
