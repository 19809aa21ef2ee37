"""The main job of scripts/setup.sh, end to end: make the sample model, tessellate it with
the command-line tool at --relative 1e-3, and check the mesh with `nurbslod verify` and with
the independent judge (../shared/tools/meshjudge.py, skipped where absent)."""

import json
import os
import shutil
import subprocess
import tempfile
import unittest

import Part

from nurbslod_testing import CLI, ROOT

JUDGE = os.path.join(os.path.dirname(ROOT), "shared", "tools", "meshjudge.py")
# Each step takes seconds on this small model; far longer means it hangs, and CI
# has no time to wait for it.
STEP_SECONDS = 180


class SampleModel(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="nurbslod-sample-")
        cls.model = os.path.join(cls.tmp, "sample.step")
        cls.mesh = os.path.join(cls.tmp, "sample.obj")
        make = subprocess.run(
            ["freecadcmd", os.path.join(ROOT, "scripts", "make_sample_model.py")],
            env=dict(os.environ, NURBSLOD_SAMPLE_OUT=cls.model), cwd=cls.tmp,
            stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=300)
        cls.make_output = make.stdout + make.stderr
        cls.tessellate = None
        if make.returncode == 0 and os.path.isfile(cls.model):
            cls.tessellate = subprocess.run(
                [CLI, "tessellate", cls.model, "-o", cls.mesh, "--relative", "1e-3"],
                stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=STEP_SECONDS)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, True)

    def summary(self):
        self.assertIsNotNone(self.tessellate, "make_sample_model failed:\n" + self.make_output)
        self.assertEqual(self.tessellate.returncode, 0, self.tessellate.stderr)
        return json.loads(self.tessellate.stdout.strip().splitlines()[-1])

    def test_sample_has_the_promised_features(self):
        self.summary()
        shape = Part.read(self.model)
        kinds = {type(face.Surface).__name__ for face in shape.Faces}
        self.assertTrue({"BSplineSurface", "Sphere", "Cylinder", "Plane"} <= kinds, kinds)
        trimmed = [face for face in shape.Faces
                   if type(face.Surface).__name__ == "BSplineSurface" and len(face.Wires) > 1]
        self.assertEqual(len(trimmed), 1, "the B-spline patch has lost its hole")

    def test_main_job_meshes_every_face(self):
        summary = self.summary()
        shape = Part.read(self.model)
        self.assertEqual(summary["faces"], len(shape.Faces))
        self.assertEqual(summary["faces_failed"], [])
        self.assertAlmostEqual(summary["tolerance"], 1e-3 * shape.BoundBox.DiagonalLength,
                               delta=1e-5 * shape.BoundBox.DiagonalLength)

    def test_verify_passes(self):
        summary = self.summary()
        verify = subprocess.run(
            [CLI, "verify", self.model, self.mesh, "--tolerance", repr(summary["tolerance"])],
            stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=STEP_SECONDS)
        self.assertEqual(verify.returncode, 0, verify.stdout + verify.stderr)

    def test_independent_judge_passes(self):
        if not os.path.isfile(JUDGE):
            self.skipTest("the mesh judge {} is absent".format(JUDGE))
        summary = self.summary()
        judge = subprocess.run(
            ["/usr/bin/python3", JUDGE, self.model, self.mesh, "--tol",
             repr(summary["tolerance"])],
            stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=STEP_SECONDS)
        self.assertEqual(judge.returncode, 0, judge.stdout + judge.stderr)
