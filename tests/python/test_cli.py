"""The command-line tool build/App/nurbslod: bad input exits 2 with a message, good input
writes a mesh and ends its output with a JSON summary."""

import json
import os
import re
import shutil
import tempfile

import FreeCAD
import Part

import NurbsLOD
from nurbslod_testing import CLI, TempDirTestCase, nurbslod, tessellate_in_fresh_process

BAD_INPUT = 2
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "data")


class CommandLine(TempDirTestCase):
    @classmethod
    def setUpClass(cls):
        cls.models = tempfile.mkdtemp(prefix="nurbslod-cli-")
        cls.model = os.path.join(cls.models, "box.step")
        Part.makeBox(10, 20, 30).exportStep(cls.model)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.models, True)

    def setUp(self):
        super().setUp()
        self.assertTrue(os.access(CLI, os.X_OK), "the build has no " + CLI)

    def assertBadInput(self, args, message=None):
        run = nurbslod(*args)
        self.assertEqual(run.returncode, BAD_INPUT,
                         "nurbslod {}: {}{}".format(" ".join(args), run.stdout, run.stderr))
        self.assertTrue(run.stderr.strip(), "no message for nurbslod " + " ".join(args))
        if message:
            self.assertIn(message, run.stderr)

    def test_tessellate_writes_obj_and_summary(self):
        out = self.path("box.obj")
        run = nurbslod("tessellate", self.model, "-o", out, "--tolerance", "0.01")
        self.assertEqual(run.returncode, 0, run.stderr)
        summary = json.loads(run.stdout.strip().splitlines()[-1])
        self.assertGreater(summary["triangles"], 0)
        with open(out) as obj:
            facets = sum(1 for line in obj if line.startswith("f "))
        self.assertEqual(facets, summary["triangles"])
        # the Python module reports the same, under the same keys
        python = NurbsLOD.export(self.model, self.path("python.obj"), tolerance=0.01)
        self.assertEqual(sorted(python), sorted(summary))
        for key in ("faces", "triangles", "vertices", "tolerance", "mode", "faces_failed"):
            self.assertEqual(python[key], summary[key], key)

    def test_compact_flag_takes_fewer_triangles(self):
        # tests/data/freecad_loft.brep (FreeCAD's loft through a circle, an ellipse and a tilted
        # circle) at relative 5e-4: 2,680 triangles against 3,424. A sphere's plain mesh has few
        # points to spare since its columns are tested on the rows its kd-tree cuts.
        loft = os.path.join(DATA, "freecad_loft.brep")
        summaries = []
        for flags in ([], ["--compact"]):
            run = nurbslod("tessellate", loft, "-o", self.path("loft.obj"), "--relative", "5e-4",
                           *flags)
            self.assertEqual(run.returncode, 0, run.stderr)
            summaries.append(json.loads(run.stdout.strip().splitlines()[-1]))
        self.assertLess(summaries[1]["triangles"], 0.9 * summaries[0]["triangles"])
        run = nurbslod("verify", loft, self.path("loft.obj"), "--tolerance",
                       repr(summaries[1]["tolerance"]))
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)

    def test_hole_wound_like_outer_wire_is_meshed_and_reported(self):
        # tests/data/hole_wound_like_outer.brep: the top of a 10 x 10 x 1 box less a cylinder of
        # radius 2 about (5, 5), its hole's wire reversed in the file (OpenCASCADE's check:
        # BadOrientationOfSubshape)
        model = os.path.join(DATA, "hole_wound_like_outer.brep")
        out = self.path("hole.obj")
        run = nurbslod("tessellate", model, "-o", out, "--tolerance", "0.01")
        self.assertEqual(run.returncode, 0, run.stderr)
        summary = json.loads(run.stdout.strip().splitlines()[-1])
        self.assertEqual(summary["faces_failed"], [])
        self.assertEqual([entry["face"] for entry in summary["faces_warned"]], [1])
        self.assertIn("same way round", summary["faces_warned"][0]["reason"])
        self.assertGreater(summary["triangles"], 0)
        python = NurbsLOD.tessellate(model, tolerance=0.01)["summary"]
        self.assertEqual(python["faces_warned"], summary["faces_warned"])
        # the good model has no word on any face
        good = nurbslod("tessellate", self.model, "-o", self.path("box.obj"),
                             "--tolerance", "0.01")
        self.assertEqual(json.loads(good.stdout.strip().splitlines()[-1])["faces_warned"], [])

    def test_missing_model(self):
        missing = self.path("missing.step")
        self.assertBadInput(["tessellate", missing, "-o", self.path("out.obj")], "missing.step")

    def test_folder_as_model(self):
        self.assertBadInput(["tessellate", self.tmp, "-o", self.path("out.obj")])

    def test_malformed_step(self):
        garbage = self.path("garbage.step")
        with open(garbage, "w") as out:
            out.write("ISO-10303-21;\nHEADER;\nthis is not STEP at all\n")
        self.assertBadInput(["tessellate", garbage, "-o", self.path("out.obj")], "garbage.step")
        self.assertFalse(os.path.exists(self.path("out.obj")))

    def test_step_whose_translation_faults(self):
        # the box with the edge loop of one face bound deleted: OpenCASCADE's STEP translator
        # reads the bound through a null handle (it ended the process before SignalsAsFailures)
        with open(self.model) as step:
            text = step.read()
        loop = re.search(r"FACE_(?:OUTER_)?BOUND\('[^']*',(#\d+),", text).group(1)
        broken = self.path("no_loop.step")
        with open(broken, "w") as out:
            out.write("\n".join(line for line in text.split("\n")
                                if not re.match(re.escape(loop) + r"\s*=", line)))
        self.assertBadInput(["tessellate", broken, "-o", self.path("out.obj")],
                            "that OpenCASCADE could translate")
        self.assertFalse(os.path.exists(self.path("out.obj")))
        # the module raises the same, and the process it runs in goes on
        status, result = tessellate_in_fresh_process(broken, tolerance=0.1)
        self.assertEqual(status, 0)
        self.assertIn("OpenCASCADE could translate", result or "(the process died)")

    def test_opencascade_messages_go_to_stderr(self):
        # a face that names a missing loop: OpenCASCADE's STEP reader reports the unresolved
        # reference on its messenger, which printed it on stdout, before the summary
        with open(self.model) as step:
            text = step.read()
        broken = self.path("unresolved.step")
        with open(broken, "w") as out:
            out.write(re.sub(r"ADVANCED_FACE\('[^']*',\(#\d+\)",
                             "ADVANCED_FACE('',(#999999)", text, count=1))
        run = nurbslod("tessellate", broken, "-o", self.path("out.obj"), "--tolerance", "0.1")
        self.assertIn("Unresolved Reference", run.stderr)
        self.assertNotIn("\x1b[", run.stderr)  # no terminal colours in a log
        self.assertNotIn("StepReaderData", run.stdout)
        # what is left of the box: a mesh and its summary alone on stdout, or a message
        if run.returncode == 0:
            self.assertEqual(len(run.stdout.strip().splitlines()), 1, run.stdout)
        else:
            self.assertEqual(run.returncode, BAD_INPUT, run.stderr)
            self.assertEqual(run.stdout.strip(), "")

    def test_bad_tolerances(self):
        for option in ("--tolerance", "--relative"):
            for value in ("0", "-1", "nan", "inf", "abc"):
                with self.subTest(option=option, value=value):
                    self.assertBadInput(["tessellate", self.model, "-o", self.path("out.obj"),
                                         option, value])

    def test_tolerances_too_fine(self):
        # a tolerance far below the model's size would never end or exhaust the memory
        for option, value in (("--tolerance", "1e-20"), ("--relative", "1e-9")):
            with self.subTest(option=option, value=value):
                self.assertBadInput(["tessellate", self.model, "-o", self.path("out.obj"),
                                     option, value], "of the model's diagonal")
        # the module refuses it too
        with self.assertRaisesRegex(ValueError, "of the model's diagonal"):
            NurbsLOD.tessellate(Part.makeBox(10, 20, 30), tolerance=1e-12)
        # a box centred at x = 1e13 rounds its coordinates by up to 1e-3: 1e-3 cannot be kept
        far = os.path.join(self.models, "far_box.brep")
        Part.makeBox(10, 20, 30, FreeCAD.Vector(1e13, 0, 0)).exportBrep(far)
        self.assertBadInput(["tessellate", far, "-o", self.path("out.obj"), "--tolerance",
                             "1e-3"], "coordinates can hold")
        run = nurbslod("tessellate", far, "-o", self.path("far.obj"), "--tolerance", "0.05")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(json.loads(run.stdout.strip().splitlines()[-1])["faces_failed"], [])

    def test_both_tolerances(self):
        self.assertBadInput(["tessellate", self.model, "-o", self.path("out.obj"),
                             "--tolerance", "0.1", "--relative", "1e-3"])

    def test_bad_mode(self):
        self.assertBadInput(["tessellate", self.model, "-o", self.path("out.obj"),
                             "--tolerance", "0.1", "--mode", "exact"])

    def test_verify_bad_input(self):
        mesh = self.path("box.obj")
        with open(mesh, "w") as out:
            out.write("v 0 0 0\nv 1 0 0\nv 0 1 0\ng Face1\nf 1 2 3\n")
        self.assertBadInput(["verify", self.path("missing.step"), mesh, "--tolerance", "0.1"])
        self.assertBadInput(["verify", self.model, self.path("missing.obj"), "--tolerance", "0.1"])
        for value in ("0", "-1", "nan", "abc"):
            with self.subTest(tolerance=value):
                self.assertBadInput(["verify", self.model, mesh, "--tolerance", value])
