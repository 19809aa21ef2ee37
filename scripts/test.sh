#!/usr/bin/env bash
# Runs every test of NurbsLOD: builds build/ if needed (incrementally), then the GoogleTest
# unit tests (ctest), the Python tests (tests/python, in freecadcmd, headless; they
# include the command-line bad-input checks) and the GUI tests (tests/gui, the real
# FreeCAD GUI under Xvfb; skipped, and counted so, without xvfb-run). Ends with the line
# "N passed, N failed, N skipped" and exits non-zero when anything failed.
set -uo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD_DIR="$ROOT/build"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

passed=0
failed=0
skipped=0

say() { printf '\n== test: %s\n' "$*"; }

# Adds "passed failed skipped" (one line, from a stage's result file) to the totals.
add_counts() {
    local p f s
    read -r p f s <"$1" || return 1
    passed=$((passed + p))
    failed=$((failed + f))
    skipped=$((skipped + s))
}

finish() {
    echo
    echo "$passed passed, $failed failed, $skipped skipped"
    [ "$failed" -eq 0 ]
    exit
}

say "building $BUILD_DIR"
if ! command -v cmake >/dev/null || ! command -v ninja >/dev/null; then
    echo "test: cmake or ninja missing: run bash scripts/setup.sh first" >&2
    failed=$((failed + 1))
    finish
fi
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
    cmake -S "$ROOT" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_COMPILER_LAUNCHER=ccache || {
        failed=$((failed + 1))
        finish
    }
fi
if ! ninja -C "$BUILD_DIR" -j"$(nproc)"; then
    echo "test: the build failed" >&2
    failed=$((failed + 1))
    finish
fi

# A runaway allocation must fail its test, not wake the OOM killer, which may kill some
# other process on a shared machine: cap each test process at half the memory.
ulimit -v $(($(awk '/^MemTotal:/ { print $2 }' /proc/meminfo) / 2))

say "unit tests (ctest)"
# The JUnit report says which tests ran, failed or were skipped (GTEST_SKIP, missing corpus).
# A test that runs for ten minutes hangs: fail it rather than let it eat CI's 90 minutes.
ctest --test-dir "$BUILD_DIR" --output-on-failure --timeout 600 \
    --output-junit "$WORK/ctest.xml"
if [ -f "$WORK/ctest.xml" ]; then
    /usr/bin/python3 - "$WORK/ctest.xml" >"$WORK/ctest.counts" <<'EOF'
import sys
import xml.etree.ElementTree as ET

counts = {"run": 0, "fail": 0, "skip": 0}
for case in ET.parse(sys.argv[1]).getroot().iter("testcase"):
    status = case.get("status", "run")
    if case.find("failure") is not None or status == "fail":
        counts["fail"] += 1
    elif case.find("skipped") is not None or status in ("notrun", "disabled"):
        counts["skip"] += 1
    else:
        counts["run"] += 1
print(counts["run"], counts["fail"], counts["skip"])
EOF
fi
add_counts "$WORK/ctest.counts" 2>/dev/null || {
    echo "test: ctest left no report" >&2
    failed=$((failed + 1))
}

say "Python tests (freecadcmd, headless)"
# A home of its own, where the checkout is the only user workbench: FreeCAD runs this
# checkout's Init.py exactly as it would for a user, and a NurbsLOD installed elsewhere
# cannot shadow the module under test.
home="$WORK/home"
mkdir -p "$home/.local/share/FreeCAD/Mod"
ln -s "$ROOT" "$home/.local/share/FreeCAD/Mod/NurbsLOD"
(
    cd "$WORK" &&
        env -u XDG_DATA_HOME -u XDG_CONFIG_HOME -u XDG_CACHE_HOME HOME="$home" \
            NURBSLOD_BUILD_DIR="$BUILD_DIR" NURBSLOD_TEST_RESULTS="$WORK/python.counts" \
            timeout 1800 freecadcmd "$ROOT/tests/python/run_tests.py" </dev/null
)
add_counts "$WORK/python.counts" 2>/dev/null || {
    echo "test: the Python tests ended without a report (crash or time-out)" >&2
    failed=$((failed + 1))
}

say "GUI tests (FreeCAD GUI under Xvfb)"
# The real GUI: adaptive display, picking through it, screenshots in out/gui-screenshots.
# Software GL (llvmpipe) is slow: the scenes are small and the whole stage takes about a
# minute. Without xvfb-run or the freecad program it is one skipped test, not a failure.
if ! command -v xvfb-run >/dev/null || ! command -v freecad >/dev/null; then
    echo "test: GUI tests skipped: xvfb-run or freecad is not installed"
    skipped=$((skipped + 1))
else
    (
        cd "$WORK" &&
            env -u XDG_DATA_HOME -u XDG_CONFIG_HOME -u XDG_CACHE_HOME HOME="$home" \
                NURBSLOD_BUILD_DIR="$BUILD_DIR" NURBSLOD_TEST_RESULTS="$WORK/gui.counts" \
                NURBSLOD_SCREENSHOT_DIR="$ROOT/out/gui-screenshots" \
                QTWEBENGINE_CHROMIUM_FLAGS="--no-sandbox --disable-gpu" \
                timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24" \
                freecad "$ROOT/tests/gui/run_gui_tests.py" </dev/null
    ) | grep -v -E '^ *(#|$)'
    if [ -f "$WORK/gui.counts" ]; then
        add_counts "$WORK/gui.counts"
    elif [ -z "${DISPLAY:-}" ] && ! xvfb-run -a true 2>/dev/null; then
        echo "test: GUI tests skipped: xvfb-run cannot start a display"
        skipped=$((skipped + 1))
    else
        echo "test: the GUI tests ended without a report (crash or time-out)" >&2
        failed=$((failed + 1))
    fi
fi

finish
