"""Malformed STEP files, made by breaking a good one in fixed random ways: entities deleted,
numbers replaced by absurd ones (1e300, 0, NaN-like), references pointed elsewhere. Whatever
OpenCASCADE makes of them, the command line ends with a mesh and a summary (exit 0) or a message
(exit 2), never by a signal; the module returns or raises, and its process goes on. Before
occ::SignalsAsFailures, 59 of 150 such copies of the corpus bolt ended the process with SIGSEGV
inside OpenCASCADE's STEP translator or its NURBS conversion."""

import json
import os
import random
import re

from nurbslod_testing import TempDirTestCase, nurbslod, tessellate_in_fresh_process

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "data")

BAD_INPUT = 2
# Fixed so that the same files are made on every run. Some mutations make OpenCASCADE's
# readers loop (a curve trimmed at 1e300 steps through its period): this seed makes none.
SEED = 7
COPIES = 40
ABSURD = ["1.E300", "-1.E300", "0.", "1.E-300", "-1.", "3.4"]
NUMBER = re.compile(r"(?<![#\w])-?\d+\.\d*(?:E[-+]?\d+)?")


def mutated(text, rng):
    """One copy of the STEP text with one to five of its DATA lines broken."""
    lines = text.split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("DATA"))
    for _ in range(rng.randint(1, 5)):
        i = rng.randrange(start + 1, len(lines) - 2)
        kind = rng.random()
        if kind < 0.45:
            numbers = list(NUMBER.finditer(lines[i]))
            if numbers:
                m = rng.choice(numbers)
                lines[i] = lines[i][:m.start()] + rng.choice(ABSURD) + lines[i][m.end():]
        elif kind < 0.7:
            lines[i] = ""  # the entity is gone; whoever refers to it reads a null handle
        else:
            references = re.findall(r"#\d+", lines[i])
            if references:
                lines[i] = lines[i].replace(rng.choice(references),
                                            "#{}".format(rng.randint(1, 400)), 1)
    return "\n".join(lines)


class MutatedModels(TempDirTestCase):
    # tests/data/box_hole_sphere.step: a 10 x 20 x 30 box less a cylinder of radius 4, with a
    # sphere of radius 3 on top, as FreeCAD 0.20 writes it. A file in the checkout, so that every
    # run breaks the same text (FreeCAD's writer names the product with a count of the shapes
    # the process has written).
    good = os.path.join(DATA, "box_hole_sphere.step")

    def tessellate(self, path):
        return nurbslod("tessellate", path, "-o", self.path("out.obj"), "--relative", "1e-3",
                        "--threads", "1", timeout=120)

    def test_no_copy_ends_the_process(self):
        good = self.tessellate(self.good)
        self.assertEqual(good.returncode, 0, good.stderr)
        good = json.loads(good.stdout.strip().splitlines()[-1])
        with open(self.good) as step:
            text = step.read()
        rng = random.Random(SEED)
        changed = 0  # copies refused, or meshed otherwise than the good file
        for k in range(COPIES):
            path = self.path("copy{}.step".format(k))
            with open(path, "w") as out:
                out.write(mutated(text, rng))
            with self.subTest(copy=k):
                run = self.tessellate(path)
                self.assertIn(run.returncode, (0, BAD_INPUT),
                              "copy {}: {}".format(k, run.stderr[-500:]))
                if run.returncode == 0:
                    summary = json.loads(run.stdout.strip().splitlines()[-1])
                    self.assertGreater(summary["faces"], 0)
                    # every face is meshed or listed with its reason
                    self.assertTrue(summary["triangles"] > 0 or summary["faces_failed"])
                    changed += (summary["faces"], summary["triangles"], summary["faces_failed"]) \
                        != (good["faces"], good["triangles"], good["faces_failed"])
                else:
                    self.assertTrue(run.stderr.strip())
                    changed += 1
                # the module, as a macro calls it: a result or an exception, never a signal
                status, result = tessellate_in_fresh_process(path, relative=1e-3)
                self.assertEqual((status, result is None), (0, False),
                                 "copy {}: the module's process died".format(k))
        # the copies break the model, or they no longer test anything (with SEED, 11 of the 40
        # ended the process with SIGSEGV before SignalsAsFailures)
        self.assertGreaterEqual(changed, COPIES // 4)
