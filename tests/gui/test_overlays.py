"""The analysis overlays (tests/gui/overlays/overlay_cases.py) as unittest tests, for a
runner that discovers tests/gui/test_*.py inside the FreeCAD GUI. Screenshots go to
$NURBSLOD_SCREENSHOT_DIR (default: out/gui-screenshots in the checkout)."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
OVERLAYS = os.path.join(HERE, "overlays")
if OVERLAYS not in sys.path:
    sys.path.insert(0, OVERLAYS)

import overlay_cases  # noqa: E402 (needs the path above)


class Overlays(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shots = os.environ.get("NURBSLOD_SCREENSHOT_DIR") or os.path.join(
            HERE, "..", "..", "out", "gui-screenshots"
        )
        cls.ctx = overlay_cases.Context(os.path.join(shots, "overlays"))

    @classmethod
    def tearDownClass(cls):
        cls.ctx.close()


def _method(case):
    def test(self):
        case(self.ctx)

    test.__doc__ = case.__doc__
    return test


for _case in overlay_cases.TESTS:
    setattr(Overlays, _case.__name__, _method(_case))
del _case
