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
import threading
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))

# A test that runs this long hangs. C++ code cannot be interrupted, so the watchdog ends the
# whole run, counting the test as failed: the others still get reported, CI still ends.
TEST_SECONDS = 300


def counts(result, hung=0):
    skipped = len(result.skipped)
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses) + hung
    passed = result.testsRun - failed - skipped - len(result.expectedFailures)
    return passed, failed, skipped


def report(passed, failed, skipped):
    print("{} passed, {} failed, {} skipped".format(passed, failed, skipped))
    sys.stdout.flush()
    results_path = os.environ.get("NURBSLOD_TEST_RESULTS")
    if results_path:
        with open(results_path, "w") as results:
            results.write("{} {} {}\n".format(passed, failed, skipped))


class WatchedResult(unittest.TextTestResult):
    """Ends the run when one test takes longer than TEST_SECONDS."""

    def startTest(self, test):
        super().startTest(test)
        self._watchdog = threading.Timer(TEST_SECONDS, self._hung, (test,))
        self._watchdog.daemon = True
        self._watchdog.start()

    def stopTest(self, test):
        self._watchdog.cancel()
        super().stopTest(test)

    def _hung(self, test):
        print("\nTIMEOUT: {} ran over {} s; the tests after it did not run".format(
            test.id(), TEST_SECONDS))
        report(*counts(self, hung=1))
        os._exit(1)


def run():
    if HERE not in sys.path:
        sys.path.insert(0, HERE)
    suite = unittest.defaultTestLoader.discover(HERE, pattern="test_*.py", top_level_dir=HERE)
    runner = unittest.TextTestRunner(stream=sys.stdout, verbosity=2, resultclass=WatchedResult)
    passed, failed, skipped = counts(runner.run(suite))
    report(passed, failed, skipped)
    return failed


# sys.exit: freecadcmd would otherwise wait on its console, and report success.
sys.exit(1 if run() else 0)
