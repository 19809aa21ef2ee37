"""What the Python tests share: where things are, and small checks on meshes."""

import os
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD_DIR = os.environ.get("NURBSLOD_BUILD_DIR") or os.path.join(ROOT, "build")
CLI = os.path.join(BUILD_DIR, "App", "nurbslod")
# Real CAD models beside the checkout (../shared/corpus); absent on some machines.
CORPUS_DIR = os.path.join(os.path.dirname(ROOT), "shared", "corpus")


def bspline_face():
    """A 30 x 30 bicubic patch with a bump: a freeform face, as FreeCAD users make them."""
    import FreeCAD
    import Part

    heights = [[0, 0, 0, 0], [0, 5, 3, 0], [0, 2, 6, 0], [0, 0, 0, 0]]
    poles = [[FreeCAD.Vector(10.0 * i, 10.0 * j, heights[i][j]) for j in range(4)]
             for i in range(4)]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(poles, [4, 4], [4, 4], [0.0, 1.0], [0.0, 1.0],
                                     False, False, 3, 3)
    return Part.Face(surface)


def nurbslod(*args, timeout=300):
    """The command line with these arguments, its output captured (subprocess.CompletedProcess)."""
    return subprocess.run([CLI, *args], stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=timeout)


def tessellate_in_fresh_process(path, **options):
    """NurbsLOD.tessellate(path, **options) in a new freecadcmd process, as a macro would call it:
    its exit status and "ok", or the message of the exception it raised (None where it printed
    neither: it died). For files that make OpenCASCADE fault: the module recovers from the fault
    (occ::SignalsAsFailures), but the longjmp leaves OpenCASCADE's state as the fault found it,
    and one process that read such a file again and again looped inside OpenCASCADE's STEP
    parser after about ten reads. One read per process keeps the other tests apart from that."""
    code = ("import NurbsLOD\n"
            "try:\n"
            "    NurbsLOD.tessellate({!r}, **{!r})\n"
            "    print('RESULT ok')\n"
            "except Exception as error:\n"
            "    print('RESULT', error)\n").format(path, options)
    run = subprocess.run([shutil.which("freecadcmd") or "freecadcmd", "-c", code],
                         stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=300)
    results = [line[len("RESULT "):] for line in run.stdout.splitlines()
               if line.startswith("RESULT ")]
    return run.returncode, results[-1] if results else None


def corpus_file(name):
    """Path of a corpus model; skips the test when the corpus is absent."""
    path = os.path.join(CORPUS_DIR, name)
    if not os.path.isfile(path):
        raise unittest.SkipTest("corpus model {} absent".format(path))
    return path


class TempDirTestCase(unittest.TestCase):
    """A test case with a fresh folder self.tmp, removed afterwards."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="nurbslod-test-")
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def path(self, name):
        return os.path.join(self.tmp, name)


def edge_use_counts(triangles):
    """How many triangles use each undirected edge, keyed by (low, high) vertex index."""
    counts = {}
    for a, b, c in triangles.tolist():
        for u, v in ((a, b), (b, c), (c, a)):
            key = (u, v) if u < v else (v, u)
            counts[key] = counts.get(key, 0) + 1
    return counts
