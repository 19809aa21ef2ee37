"""Appearance-preserving display in the real FreeCAD GUI (paper appearance, section 4.1): with
the normal error bound (1 degree, the default) every drawn face's normals, interpolated across
its triangles as the viewer shades them, stay within the bound of the exact normals, measured
on the drawn levels (max_normal_error_deg, face_normal_error_deg); without it the screen-space
error alone leaves larger normal errors on the sample model.

The measure samples each triangle on a barycentric grid (InterpolatedNormalError); against a
grid three times denser it reads up to 1.22 times low on the corpus, so "within the bound"
means within it at those samples.
"""

import math
import shutil
import tempfile
import unittest

import FreeCAD

import gui_testing as gt
import NurbsLODGui

BOUND_DEG = 1.0
# What the bound may cost over the screen-space error alone, in triangles, at the fitted view.
# The tighter guaranteed cell bound and trimming-chord bound more than halved the screen-space
# mesh of the sample model at 2 px (4342 -> 2020 triangles) while the bounded one grew (8374 ->
# 11041): 5.5 times now, 1.9 before.
COST_LIMIT = 6.0


class NormalErrorCase:
    model_name = None
    pixel_error = 0.5
    # whether the screen-space error alone leaves more than the bound (the bound then has
    # something to do in the fitted view)
    unbounded_exceeds = True
    # faces known to stay over the bound (a known limit, not a pass): the test fails if any
    # other face is over it, or if one of these comes within it (then take it off the list)
    known_over = ()

    def model_path(self):
        raise NotImplementedError

    def setUp(self):
        self.document, self.obj, self.view = gt.open_model(self.model_path(), self.model_name)
        self.addCleanup(gt.close, self.document)

    def settled(self, normal_error_deg, name):
        NurbsLODGui.enable_adaptive_display(
            self.obj, pixel_error=self.pixel_error, normal_error_deg=normal_error_deg)
        self.view.fitAll()
        stats, _, frames = gt.settle(self.view, self.obj)
        gt.screenshot(self.view, name)
        faces = stats["face_normal_error_deg"]
        worst = max(range(len(faces)), key=lambda k: faces[k])
        FreeCAD.Console.PrintMessage(
            "NurbsLOD GUI test normal error {} {}: {} triangles, measured max normal error "
            "{:.3f} deg (face {}), {} faces made finer by the bound, {} over it, {:.3f} px, "
            "{} frames, {:.0f} ms in workers; triangles of the faces over it: {}\n".format(
                self.model_name, normal_error_deg, stats["triangles"],
                stats["max_normal_error_deg"], worst + 1, stats["faces_shading_limited"],
                stats["faces_normal_error_over"], stats["max_screen_error_px"], frames,
                stats["background_tessellation_ms"],
                {k + 1: stats["face_triangles"][k] for k in range(len(faces))
                 if stats["normal_error_deg"] > 0 and faces[k] > stats["normal_error_deg"]}))
        return stats

    def test_the_default_bound_is_met_on_every_face(self):
        off = self.settled(0, "normal-error-{}-off".format(self.model_name))
        NurbsLODGui.disable_adaptive_display(self.obj)
        on = self.settled(None, "normal-error-{}-1deg".format(self.model_name))
        self.assertEqual(off["normal_error_deg"], 0)
        self.assertEqual(on["normal_error_deg"], BOUND_DEG)  # the default
        drawn = [k for k, count in enumerate(on["face_triangles"]) if count > 0]
        self.assertEqual(len(drawn), on["faces_visible"])
        self.assertGreater(len(drawn), 0)
        # the bound, on every drawn face
        over = [k + 1 for k in drawn if on["face_normal_error_deg"][k] > BOUND_DEG]
        self.assertEqual(over, [k for k in self.known_over if k - 1 in drawn])
        self.assertEqual(on["faces_normal_error_over"], len(over))
        self.assertLessEqual(
            max(on["face_normal_error_deg"][k] for k in drawn if k + 1 not in over), BOUND_DEG)
        self.assertLessEqual(on["max_screen_error_px"], self.pixel_error)
        self.assertEqual(on["last_error"], "")
        # what it costs
        self.assertGreaterEqual(on["triangles"], off["triangles"])
        self.assertLessEqual(on["triangles"], COST_LIMIT * off["triangles"])
        if self.unbounded_exceeds:
            self.assertGreater(off["max_normal_error_deg"], BOUND_DEG)
            self.assertGreater(on["faces_shading_limited"], 0)


class SampleModelNormalError(NormalErrorCase, unittest.TestCase):
    model_name = "sample"
    # At the default 0.5 px the screen-space error alone keeps the sample model within 1 degree
    # in the fitted view (0.95 measured, 16,698 triangles with and without the bound): 2 px
    # gives the bound work to do.
    pixel_error = 2.0

    def model_path(self):
        directory = tempfile.mkdtemp(prefix="nurbslod-gui-")
        self.addCleanup(shutil.rmtree, directory, True)
        return gt.sample_model(directory)

    def test_the_preference_is_the_default_and_bad_bounds_are_refused(self):
        parameters = NurbsLODGui.parameters()
        parameters.SetFloat("NormalErrorDeg", 2.5)
        self.addCleanup(parameters.RemFloat, "NormalErrorDeg")
        NurbsLODGui.enable_adaptive_display(self.obj)
        self.assertEqual(NurbsLODGui.stats(self.obj)["normal_error_deg"], 2.5)
        NurbsLODGui.disable_adaptive_display(self.obj)
        for bad in (-1, math.nan, math.inf, 90, "x"):
            with self.assertRaises(ValueError):
                NurbsLODGui.enable_adaptive_display(self.obj, normal_error_deg=bad)
        self.assertFalse(NurbsLODGui.is_enabled(self.obj))


class CorpusModelNormalError(NormalErrorCase, unittest.TestCase):
    model_name = "trj7"
    # Faces 170 and 174 end in a degenerated edge whose surface row is spread over 0.0013 mm
    # instead of collapsed: their normals are taken on the surface with that row collapsed, the
    # pole the B-rep declares (CollapsedPoleRows); on the file's surface they turned by 88
    # degrees over the last tenth of a millimetre and face 170 stayed 17.8 degrees over.

    def model_path(self):
        return gt.corpus_file("trj7_b1-ec-214.stp")


if __name__ == "__main__":
    unittest.main()
