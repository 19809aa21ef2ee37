"""Runs the GUI tests of NurbsLOD in the real FreeCAD GUI (under Xvfb on a headless machine):

    xvfb-run -a -s "-screen 0 1280x1024x24" freecad tests/gui/run_gui_tests.py

(scripts/test.sh runs it with the checkout installed as the only user workbench). Runs every
tests/gui/test_*.py with unittest from the Qt event loop, prints "N passed, N failed,
N skipped", writes the three numbers to $NURBSLOD_TEST_RESULTS when set and ends FreeCAD
with exit code 1 when a test failed. Screenshots go to $NURBSLOD_SCREENSHOT_DIR (default:
out/gui-screenshots in the checkout); $NURBSLOD_GUI_TESTS picks tests by name.

FreeCAD runs this file as a macro, with no __file__ and no __main__ guard.
"""

import os
import sys
import threading
import traceback
import unittest

from PySide import QtCore


def _here():
    # A macro has no __file__; FreeCAD passes the script's path on the command line.
    for argument in sys.argv:
        if argument.endswith("run_gui_tests.py"):
            return os.path.dirname(os.path.abspath(argument))
    return os.path.join(os.getcwd(), "tests", "gui")


HERE = _here()
# Ends a hung run: C++ cannot be interrupted, and FreeCAD would otherwise wait forever.
RUN_SECONDS = 240


def _report(passed, failed, skipped):
    print("{} passed, {} failed, {} skipped".format(passed, failed, skipped))
    sys.stdout.flush()
    path = os.environ.get("NURBSLOD_TEST_RESULTS")
    if path:
        with open(path, "w") as results:
            results.write("{} {} {}\n".format(passed, failed, skipped))


def _timeout():
    print("\nTIMEOUT: the GUI tests ran over {} s".format(RUN_SECONDS))
    _report(0, 1, 0)
    os._exit(1)


def _run():
    code = 1
    try:
        if HERE not in sys.path:
            sys.path.insert(0, HERE)
        loader = unittest.TestLoader()
        # NURBSLOD_GUI_TESTS="zoom selection": only the tests whose names contain one of these
        if os.environ.get("NURBSLOD_GUI_TESTS"):
            names = os.environ["NURBSLOD_GUI_TESTS"].split()
            loader.testNamePatterns = ["*{}*".format(name) for name in names]
        suite = loader.discover(HERE, pattern="test_*.py", top_level_dir=HERE)
        result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
        skipped = len(result.skipped)
        failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
        passed = result.testsRun - failed - skipped - len(result.expectedFailures)
        _report(passed, failed, skipped)
        code = 1 if failed else 0
    except Exception:
        traceback.print_exc()
        _report(0, 1, 0)
    sys.stdout.flush()
    os._exit(code)


_watchdog = threading.Timer(RUN_SECONDS, _timeout)
_watchdog.daemon = True
_watchdog.start()
QtCore.QTimer.singleShot(200, _run)
