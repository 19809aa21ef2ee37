"""Runs the overlay GUI tests (overlay_cases.py) as a FreeCAD macro: started by
tests/gui/run_overlay_tests.sh under Xvfb.

FreeCAD runs this file as a macro (no __file__): NURBSLOD_GUI_TEST_DIR names this folder,
NURBSLOD_SCREENSHOT_DIR where the screenshots go, NURBSLOD_TEST_RESULTS where the counts
"passed failed skipped" go. The work runs from a QTimer once the main window is up, and the
script ends FreeCAD with os._exit (the exit code says whether every test passed).
"""

import os
import sys
import traceback
import unittest

from PySide import QtCore

HERE = os.environ.get("NURBSLOD_GUI_TEST_DIR", "")
SHOTS = os.environ.get("NURBSLOD_SCREENSHOT_DIR", "")
RESULTS = os.environ.get("NURBSLOD_TEST_RESULTS", "")


def run():
    passed = failed = skipped = 0
    try:
        sys.path.insert(0, HERE)
        import overlay_cases

        tests = overlay_cases.TESTS
        ctx = overlay_cases.Context(SHOTS)
    except Exception:
        traceback.print_exc()
        tests, ctx = [], None
        failed += 1
    for test in tests:
        print("overlay GUI test: " + test.__name__)
        try:
            test(ctx)
        except unittest.SkipTest as reason:
            print("skipped: {}: {}".format(test.__name__, reason))
            skipped += 1
        except Exception:
            traceback.print_exc()
            print("FAIL: " + test.__name__)
            failed += 1
        else:
            print("ok: " + test.__name__)
            passed += 1
    print("{} passed, {} failed, {} skipped".format(passed, failed, skipped))
    sys.stdout.flush()
    if RESULTS:
        with open(RESULTS, "w") as results:
            results.write("{} {} {}\n".format(passed, failed, skipped))
    os._exit(1 if failed else 0)


QtCore.QTimer.singleShot(500, run)
