"""Runs the Python tests of NurbsLOD inside FreeCAD, headless:

    freecadcmd tests/python/run_tests.py

(scripts/test.sh runs it with the checkout installed as the only user workbench). Runs every
tests/python/test_*.py with unittest, prints "N passed, N failed, N skipped", writes the
three numbers to $NURBSLOD_TEST_RESULTS when set, and exits 1 when a test failed.

freecadcmd imports this file as a module instead of running it as __main__, so there is no
`if __name__ == "__main__"` guard.
"""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def run():
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    suite = unittest.defaultTestLoader.discover(HERE, pattern="test_*.py", top_level_dir=HERE)
    result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
    skipped = len(result.skipped)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    passed = result.testsRun - failed - skipped - len(result.expectedFailures)
    print("{} passed, {} failed, {} skipped".format(passed, failed, skipped))
    results_path = os.environ.get("NURBSLOD_TEST_RESULTS")
    if results_path:
        with open(results_path, "w") as results:
            results.write("{} {} {}\n".format(passed, failed, skipped))
    return failed


# sys.exit: freecadcmd would otherwise wait on its console, and report success.
sys.stdout.flush()
sys.exit(1 if run() else 0)
