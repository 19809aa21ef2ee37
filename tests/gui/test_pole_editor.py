"""Live control-point editing: the net, live moves that touch only the node, one undoable
transaction on finish, cancel that leaves the document as it was."""

import unittest

import FreeCAD
import FreeCADGui

import gui_testing as gt
import NurbsLODGui
import NurbsLODPoleEditor


class PoleEditing(unittest.TestCase):
    placement = FreeCAD.Placement()

    def setUp(self):
        self.document, self.obj, self.view = gt.open_shape(
            gt.bicubic_face(20), "Poles", self.placement, undo=True
        )
        self.addCleanup(gt.close, self.document)
        NurbsLODGui.enable_adaptive_display(self.obj, normal_error_deg=0)  # the edit's cost only
        gt.settle(self.view, self.obj)
        self.original = self.obj.Shape.Faces[0].Surface.getPoles()  # document coordinates
        self.original_local = NurbsLODGui.local_shape(self.obj).Faces[0].Surface.getPoles()

    def lifted(self, i, j, height=30.0):
        return self.original[i - 1][j - 1] + FreeCAD.Vector(0, 0, height)

    def test_live_moves_change_the_node_and_finish_writes_one_transaction(self):
        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        graph = self.view.getSceneGraph()
        self.assertGreaterEqual(graph.findChild(editor.root), 0)
        before = NurbsLODGui.face_bounds(self.obj, 1)
        undo_count = self.document.UndoCount
        brep = self.obj.Shape.exportBrepToString()
        editor.move(10, 10, self.lifted(10, 10))
        editor.move(5, 15, self.lifted(5, 15, 20.0))
        gt.draw(self.view)
        self.assertGreater(NurbsLODGui.face_bounds(self.obj, 1)[1][2], before[1][2] + 5.0)
        # live moves leave the document alone
        self.assertEqual(self.obj.Shape.exportBrepToString(), brep)
        self.assertEqual(self.document.UndoCount, undo_count)
        gt.screenshot(self.view, "pole-editor-net")
        self.assertTrue(editor.finish())
        self.assertEqual(graph.findChild(editor.root), -1)
        self.assertEqual(self.document.UndoCount, undo_count + 1)
        self.assertEqual(self.document.UndoNames[0], "Edit control points")
        surface = self.obj.Shape.Faces[0].Surface
        self.assertLess((surface.getPole(10, 10) - self.lifted(10, 10)).Length, 1e-9)
        self.assertLess((surface.getPole(5, 15) - self.lifted(5, 15, 20.0)).Length, 1e-9)
        for kept, given in zip(self.obj.Placement.toMatrix().A, self.placement.toMatrix().A):
            self.assertAlmostEqual(kept, given, delta=1e-12)  # the placement is kept
        self.document.undo()
        self.assertEqual(
            NurbsLODGui.local_shape(self.obj).Faces[0].Surface.getPoles(), self.original_local)

    def test_cancel_puts_the_node_back_and_leaves_the_document(self):
        before = NurbsLODGui.face_bounds(self.obj, 1)
        undo_count = self.document.UndoCount
        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        editor.move(10, 10, self.lifted(10, 10))
        editor.cancel()
        gt.settle(self.view, self.obj)  # back at the level the view needs, as before
        after = NurbsLODGui.face_bounds(self.obj, 1)
        for k in range(3):
            self.assertAlmostEqual(after[0][k], before[0][k], delta=1e-6)
            self.assertAlmostEqual(after[1][k], before[1][k], delta=1e-6)
        self.assertEqual(self.document.UndoCount, undo_count)
        self.assertEqual(
            NurbsLODGui.local_shape(self.obj).Faces[0].Surface.getPoles(), self.original_local)
        self.assertEqual(self.view.getSceneGraph().findChild(editor.root), -1)

    def test_an_overlay_follows_live_moves_and_cancel(self):
        import NurbsLODOverlays

        NurbsLODOverlays.set_overlay(self.obj, "zebra", stripes=12)
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        overlay = NurbsLODOverlays._overlays[NurbsLODOverlays._key(self.obj)]
        top_before = float(overlay.analysis["points"][:, 2].max())
        brep = self.obj.Shape.exportBrepToString()
        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        timing = editor.move(10, 10, self.lifted(10, 10))
        self.assertIn("overlay_ms", timing)
        # the stripes' mesh is the moved face's, the document still the old one
        self.assertGreater(float(overlay.analysis["points"][:, 2].max()), top_before + 5.0)
        self.assertEqual(self.obj.Shape.exportBrepToString(), brep)
        self.assertEqual(NurbsLODOverlays.overlay_of(self.obj), "zebra")
        gt.draw(self.view)
        gt.screenshot(self.view, "pole-editor-zebra-live")
        editor.cancel()
        # the document's mesh, kept while the edit showed another: back at once, no worker
        self.assertFalse(NurbsLODOverlays.overlay_pending(self.obj))
        overlay = NurbsLODOverlays._overlays[NurbsLODOverlays._key(self.obj)]
        self.assertAlmostEqual(float(overlay.analysis["points"][:, 2].max()), top_before, delta=1e-9)

    def test_an_overlay_follows_a_drag_in_the_background(self):
        import time

        from PySide import QtGui

        import NurbsLODOverlays

        NurbsLODOverlays.set_overlay(self.obj, "zebra", stripes=12)
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        key = NurbsLODOverlays._key(self.obj)
        top_before = float(NurbsLODOverlays._overlays[key].analysis["points"][:, 2].max())
        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        self.addCleanup(editor.cancel)
        dragger = editor.grab(10, 10)
        for height in (10.0, 20.0, 30.0):  # three drag steps, coalesced while a worker runs
            local = self.placement.inverse().multVec(self.lifted(10, 10, height))
            dragger.translation.setValue(local.x, local.y, local.z)
        self.assertIsNotNone(editor.follower)
        deadline = time.monotonic() + 30.0
        while editor.follower.busy() and time.monotonic() < deadline:
            QtGui.QApplication.processEvents()
            time.sleep(0.01)
        self.assertFalse(editor.follower.busy())
        self.assertGreaterEqual(editor.follower.shown, 1)
        self.assertLessEqual(editor.follower.shown, 3)
        top = float(NurbsLODOverlays._overlays[key].analysis["points"][:, 2].max())
        self.assertGreater(top, top_before + 5.0)
        # the last step's face, not an earlier one's
        last = NurbsLODOverlays._analyse_face(
            editor._edited_face()[2],
            NurbsLODOverlays._live_tolerance(self.obj, NurbsLODOverlays.LIVE_COARSENING),
        )
        self.assertAlmostEqual(top, float(last["points"][:, 2].max()), delta=1e-9)

    def test_a_dragged_pole_moves_live(self):
        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        self.addCleanup(editor.cancel)
        # the pole under the mouse is found from its place on screen
        x, y = self.view.getPointOnScreen(self.original[6][7])
        self.assertEqual(editor.pole_at(x, y), (7, 8))
        dragger = editor.grab(7, 8)
        target = self.lifted(7, 8)
        local = self.placement.inverse().multVec(target)  # the dragger is under the net's
        dragger.translation.setValue(local.x, local.y, local.z)  # transform
        self.assertLess((editor.pole(7, 8) - target).Length, 1e-4)  # the dragger is float
        self.assertTrue(editor.timings)
        self.assertIn((7, 8), editor.moved)

    def test_bad_input(self):
        import Part

        editor = NurbsLODPoleEditor.PoleEditor(self.obj, 1, self.view)
        self.addCleanup(editor.cancel)
        for i, j, position in ((0, 1, (0, 0, 0)), (1, 21, (0, 0, 0)), (1, 1, (float("nan"), 0, 0))):
            with self.assertRaises(ValueError):
                editor.move(i, j, position)
        box = self.document.addObject("Part::Feature", "Box")
        box.Shape = Part.makeBox(1, 1, 1)
        with self.assertRaisesRegex(ValueError, "not a B-spline surface"):
            NurbsLODPoleEditor.PoleEditor(box, 1, self.view)
        with self.assertRaises(ValueError):
            NurbsLODPoleEditor.PoleEditor(self.obj, 2, self.view)

    def test_command_opens_and_closes_the_editor(self):
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.obj, "Face1")
        self.addCleanup(FreeCADGui.Selection.clearSelection)
        FreeCADGui.runCommand(NurbsLODPoleEditor.COMMAND_NAME)
        editor = NurbsLODPoleEditor._active
        self.assertIsNotNone(editor)
        editor.move(10, 10, self.lifted(10, 10))
        FreeCADGui.runCommand(NurbsLODPoleEditor.COMMAND_NAME)  # again: keep the edit
        self.assertIsNone(NurbsLODPoleEditor._active)
        moved = self.obj.Shape.Faces[0].Surface.getPole(10, 10)
        self.assertLess((moved - self.lifted(10, 10)).Length, 1e-9)



class PlacedPoleEditing(PoleEditing):
    """The same on an object with a placement: the nodes live in the shape's own coordinates,
    the net and the macro arguments in the document's."""

    placement = FreeCAD.Placement(
        FreeCAD.Vector(50, -20, 10), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))


if __name__ == "__main__":
    unittest.main()
