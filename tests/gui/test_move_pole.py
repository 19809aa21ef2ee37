"""Control-point editing: move_pole changes one face, the node shows the new face at once,
and undo restores the document's shape exactly."""

import unittest

import FreeCAD

import gui_testing as gt
import NurbsLODGui


class MovePole(unittest.TestCase):
    placement = FreeCAD.Placement()

    def setUp(self):
        self.document, self.obj, self.view = gt.open_shape(
            gt.bicubic_face(20), "Edit", self.placement, undo=True
        )
        self.addCleanup(gt.close, self.document)
        NurbsLODGui.enable_adaptive_display(self.obj, normal_error_deg=0)  # the edit's cost only
        gt.settle(self.view, self.obj)

    def test_move_changes_the_face_and_undo_restores_it_exactly(self):
        # compared without the placement (kept apart, as FreeCAD's undo keeps it): the
        # shape's own numbers
        original_placement = self.obj.Placement.toMatrix().A
        original_shape = NurbsLODGui.local_shape(self.obj)
        original_surface = original_shape.Faces[0].Surface
        original_poles = original_surface.getPoles()
        global_pole = self.obj.Shape.Faces[0].Surface.getPole(10, 10)
        before = NurbsLODGui.face_bounds(self.obj, 1)
        gt.screenshot(self.view, "move-pole-before")
        target = global_pole + FreeCAD.Vector(0, 0, 40)
        timing = NurbsLODGui.move_pole(self.obj, 1, 10, 10, target)

        self.assertLess((self.obj.Shape.Faces[0].Surface.getPole(10, 10) - target).Length, 1e-9)
        for kept, given in zip(self.obj.Placement.toMatrix().A, self.placement.toMatrix().A):
            self.assertAlmostEqual(kept, given, delta=1e-12)  # the placement is kept
        self.assertIsNotNone(timing["display_ms"])
        after = NurbsLODGui.face_bounds(self.obj, 1)
        # the node's mesh of the face follows: the bump raises its top by several units
        self.assertGreater(after[1][2], before[1][2] + 5.0)
        gt.settle(self.view, self.obj)
        self.assertLessEqual(NurbsLODGui.stats(self.obj)["max_screen_error_px"], 0.5)
        gt.screenshot(self.view, "move-pole-after")
        self.assertEqual(self.document.UndoNames[0], "Move pole")

        self.document.undo()
        self.assertTrue(NurbsLODGui.wait_until_ready(self.obj))  # re-read in a thread
        restored_shape = NurbsLODGui.local_shape(self.obj)
        # FreeCAD's undo restores a deep copy, whose BREP text differs from the original by
        # an identity location; the geometry must be the very same numbers
        # Part::Feature derives Placement from the restored shape's location, which rounds
        # the rotation through OpenCASCADE's matrix by an ulp: any shape assignment does that
        for restored, original in zip(self.obj.Placement.toMatrix().A, original_placement):
            self.assertAlmostEqual(restored, original, delta=1e-12)
        restored_surface = restored_shape.Faces[0].Surface
        self.assertEqual(restored_surface.getPoles(), original_poles)
        self.assertEqual(restored_surface.getWeights(), original_surface.getWeights())
        self.assertEqual(restored_surface.getUKnots(), original_surface.getUKnots())
        self.assertEqual(restored_surface.getVKnots(), original_surface.getVKnots())
        for name in ("getUMultiplicities", "getVMultiplicities"):
            self.assertEqual(getattr(restored_surface, name)(), getattr(original_surface, name)())
        # vertices and edge curves carry the undo copy's composite location (the placement
        # and its inverse), which can move them by an ulp; the face's surface above is exact
        self.assertEqual(len(restored_shape.Vertexes), len(original_shape.Vertexes))
        for restored_vertex, original_vertex in zip(restored_shape.Vertexes,
                                                    original_shape.Vertexes):
            self.assertLess((restored_vertex.Point - original_vertex.Point).Length, 1e-9)
        for restored_edge, original_edge in zip(restored_shape.Edges, original_shape.Edges):
            self.assertEqual(restored_edge.ParameterRange, original_edge.ParameterRange)
            for restored_pole, original_pole in zip(restored_edge.Curve.getPoles(),
                                                    original_edge.Curve.getPoles()):
                self.assertLess((restored_pole - original_pole).Length, 1e-9)
        self.assertEqual(len(restored_shape.Edges), len(original_shape.Edges))
        gt.settle(self.view, self.obj)
        restored = NurbsLODGui.face_bounds(self.obj, 1)
        self.assertAlmostEqual(restored[1][2], before[1][2], delta=0.5)

    def test_bad_edits_raise_and_change_nothing(self):
        import Part

        original = self.obj.Shape.exportBrepToString()
        undo_count = self.document.UndoCount
        bad_calls = [
            (0, 1, 1, (0, 0, 0)),  # no face 0
            (2, 1, 1, (0, 0, 0)),  # one face only
            (1, 0, 1, (0, 0, 0)),  # poles count from 1
            (1, 21, 1, (0, 0, 0)),
            (1, 1, 1, (float("nan"), 0, 0)),
            (1, 1, 1, "up"),
        ]
        for arguments in bad_calls:
            with self.subTest(arguments=arguments):
                with self.assertRaises(ValueError):
                    NurbsLODGui.move_pole(self.obj, *arguments)
        box = self.document.addObject("Part::Feature", "Box")
        box.Shape = Part.makeBox(1, 1, 1)
        with self.assertRaisesRegex(ValueError, "face 1 is a Plane"):
            NurbsLODGui.move_pole(box, 1, 1, 1, (0, 0, 0))
        self.assertEqual(self.obj.Shape.exportBrepToString(), original)
        self.assertEqual(self.document.UndoCount, undo_count)



class PlacedMovePole(MovePole):
    """The same on an object with a placement (the node works without it)."""

    placement = FreeCAD.Placement(
        FreeCAD.Vector(50, -20, 10), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))


if __name__ == "__main__":
    unittest.main()


class MovePoleUnderOverlay(unittest.TestCase):
    """A scripted edit with an analysis overlay on: the overlay follows the new surface, and
    undo."""

    def setUp(self):
        self.document, self.obj, _ = gt.open_shape(gt.bicubic_face(8), "EditOverlay", undo=True)
        self.addCleanup(gt.close, self.document)

    def test_the_overlay_follows_the_edit(self):
        import NurbsLODOverlays

        NurbsLODGui.set_overlay(self.obj, "zebra")
        self.addCleanup(NurbsLODGui.set_overlay, self.obj, None)
        overlay = NurbsLODOverlays._overlays[(self.document.Name, self.obj.Name)]
        before = overlay.analysis["points"].copy()
        pole = self.obj.Shape.Faces[0].Surface.getPole(4, 4)
        NurbsLODGui.move_pole(self.obj, 1, 4, 4, pole + FreeCAD.Vector(0, 0, 5))
        self.assertEqual(NurbsLODOverlays.overlay_of(self.obj), "zebra")
        # the overlay of the new shape is made in a worker thread
        self.assertEqual(NurbsLODOverlays.wait_for_overlay(self.obj)["kind"], "zebra")
        after = NurbsLODOverlays._overlays[(self.document.Name, self.obj.Name)].analysis["points"]
        # the overlay's mesh rises where the pole was lifted

        def height_near_pole(points):
            squared = (points[:, 0] - pole.x) ** 2 + (points[:, 1] - pole.y) ** 2
            return points[squared.argmin(), 2]

        self.assertGreater(height_near_pole(after), height_near_pole(before) + 0.5)
        # and back with undo
        self.document.undo()
        NurbsLODOverlays.wait_for_overlay(self.obj)
        undone = NurbsLODOverlays._overlays[(self.document.Name, self.obj.Name)].analysis["points"]
        self.assertAlmostEqual(height_near_pole(undone), height_near_pole(before), places=9)
