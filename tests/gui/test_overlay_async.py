"""Overlays never hold up the GUI: their meshes are made in a worker thread, a newer request
replaces an older one, closing the document or deleting the object while a worker runs is
harmless. Adaptive display re-reads a changed shape in a thread too."""

import time
import unittest

import FreeCAD
import FreeCADGui
from PySide import QtGui

import gui_testing as gt
import NurbsLODGui
import NurbsLODOverlays


def _pump(seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtGui.QApplication.processEvents()
        time.sleep(0.01)


class OverlayInTheBackground(unittest.TestCase):
    def setUp(self):
        # a 20 x 20 bicubic face: its overlay mesh takes about a second to make
        self.document, self.obj, self.view = gt.open_shape(gt.bicubic_face(20), "Async")
        self.addCleanup(_close_if_open, self.document.Name)

    def switch(self):
        return NurbsLODOverlays._view_provider_switch(self.obj)[1]

    def test_set_overlay_returns_at_once_and_shows_the_overlay_when_ready(self):
        shown_before = self.switch().whichChild.getValue()
        answer = NurbsLODOverlays.set_overlay(self.obj, "zebra", wait=False)
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        self.assertEqual(answer["kind"], "zebra")
        self.assertTrue(answer["pending"])
        self.assertTrue(NurbsLODOverlays.overlay_pending(self.obj))
        self.assertEqual(NurbsLODOverlays.overlay_of(self.obj), "zebra")
        # FreeCAD's display stays until the mesh is there
        self.assertEqual(self.switch().whichChild.getValue(), shown_before)
        result = NurbsLODGui.wait_for_overlay(self.obj, 120)
        self.assertFalse(NurbsLODOverlays.overlay_pending(self.obj))
        self.assertEqual(result["kind"], "zebra")
        self.assertGreater(result["triangles"], 1000)
        self.assertNotEqual(self.switch().whichChild.getValue(), shown_before)
        self.assertEqual(
            self.switch().getChild(self.switch().whichChild.getValue()).getName().getString(),
            NurbsLODOverlays.NODE_NAME,
        )
        # another kind on the same mesh needs no worker
        answer = NurbsLODOverlays.set_overlay(self.obj, "isophotes", wait=False)
        self.assertNotIn("pending", answer)
        self.assertEqual(answer["triangles"], result["triangles"])
        gt.draw(self.view)
        gt.screenshot(self.view, "overlay-async-isophotes")

    def test_the_command_returns_before_the_overlay_is_ready(self):
        NurbsLODOverlays.register_commands()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.obj)
        self.addCleanup(FreeCADGui.Selection.clearSelection)
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        FreeCADGui.runCommand("NurbsLOD_Zebra")
        self.assertTrue(NurbsLODOverlays.overlay_pending(self.obj))
        self.assertEqual(NurbsLODOverlays.wait_for_overlay(self.obj, 120)["kind"], "zebra")
        FreeCADGui.runCommand("NurbsLOD_OverlayOff")
        self.assertIsNone(NurbsLODOverlays.overlay_of(self.obj))

    def test_a_newer_request_replaces_an_older_one(self):
        NurbsLODOverlays.set_overlay(self.obj, "zebra", wait=False, relative=2e-4)
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        self.assertTrue(NurbsLODOverlays.overlay_pending(self.obj))
        NurbsLODOverlays.set_overlay(self.obj, "curvature", wait=False, relative=1e-3)
        result = NurbsLODOverlays.wait_for_overlay(self.obj, 120)
        self.assertEqual(result["kind"], "curvature")
        self.assertEqual(result["options"]["relative"], 1e-3)
        overlay = NurbsLODOverlays._overlays[NurbsLODOverlays._key(self.obj)]
        self.assertEqual(overlay.kind, "curvature")
        self.assertEqual(len(overlay.analysis["triangles"]), result["triangles"])
        # the coarser request's mesh, not the finer older one's: a quarter of the triangles
        fine = NurbsLODOverlays.set_overlay(self.obj, "curvature", relative=2e-4)
        self.assertGreater(fine["triangles"], 2 * result["triangles"])

    def test_closing_the_document_while_a_worker_runs(self):
        NurbsLODOverlays.set_overlay(self.obj, "zebra", wait=False)
        self.assertTrue(NurbsLODOverlays.overlay_pending(self.obj))
        key = NurbsLODOverlays._key(self.obj)
        overlay = NurbsLODOverlays._overlays[key]
        thread = overlay.worker.thread
        FreeCAD.closeDocument(self.document.Name)
        self.assertNotIn(key, NurbsLODOverlays._overlays)
        thread.join(120)  # the worker ends by itself; its result goes nowhere
        _pump(0.2)
        self.assertNotIn(key, NurbsLODOverlays._overlays)
        self.assertIsNone(overlay.group)

    def test_deleting_the_object_while_a_worker_runs(self):
        NurbsLODOverlays.set_overlay(self.obj, "curvature", wait=False)
        key = NurbsLODOverlays._key(self.obj)
        thread = NurbsLODOverlays._overlays[key].worker.thread
        self.assertIsNotNone(thread)
        self.document.removeObject(self.obj.Name)
        self.assertNotIn(key, NurbsLODOverlays._overlays)
        thread.join(120)
        _pump(0.2)
        self.assertNotIn(key, NurbsLODOverlays._overlays)
        self.assertEqual(len(self.document.Objects), 0)

    def test_the_overlay_follows_a_shape_change_in_the_background(self):
        NurbsLODOverlays.set_overlay(self.obj, "zebra")
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        overlay = NurbsLODOverlays._overlays[NurbsLODOverlays._key(self.obj)]
        old_group = overlay.group
        self.obj.Shape = gt.bicubic_face(12)
        # the old overlay stays on while the new shape's mesh is made
        self.assertTrue(NurbsLODOverlays.overlay_pending(self.obj))
        self.assertIs(overlay.group, old_group)
        result = NurbsLODOverlays.wait_for_overlay(self.obj, 120)
        self.assertEqual(result["kind"], "zebra")
        self.assertIsNot(overlay.group, old_group)

    def test_a_shape_without_faces_removes_the_overlay(self):
        import Part

        NurbsLODOverlays.set_overlay(self.obj, "zebra")
        self.addCleanup(NurbsLODOverlays.set_overlay, self.obj, None)
        shown_before = NurbsLODOverlays._overlays[NurbsLODOverlays._key(self.obj)].saved_child
        # the observer refuses the new shape at once and gives FreeCAD's display back
        self.obj.Shape = Part.Vertex(FreeCAD.Vector(0, 0, 0))
        self.assertIsNone(NurbsLODOverlays.overlay_of(self.obj))
        self.assertEqual(self.switch().whichChild.getValue(), shown_before)
        with self.assertRaises(ValueError):
            NurbsLODOverlays.set_overlay(self.obj, "zebra")
        self.assertIsNone(NurbsLODOverlays.overlay_of(self.obj))


class AdaptiveDisplayInTheBackground(unittest.TestCase):
    def test_a_shape_change_is_read_in_a_thread_while_the_old_node_draws(self):
        document, obj, view = gt.open_shape(gt.bicubic_face(12), "AsyncNode")
        self.addCleanup(_close_if_open, document.Name)
        NurbsLODGui.enable_adaptive_display(obj, pixel_error=0.8)
        old_node = NurbsLODGui.node_of(obj)
        gt.settle(view, obj)
        self.assertLess(NurbsLODGui.face_bounds(obj, 1)[1][0], 101.0)
        obj.Shape = gt.bicubic_face(12, size=300.0)  # three times as large
        self.assertTrue(NurbsLODGui.is_pending(obj))
        self.assertIs(NurbsLODGui.node_of(obj), old_node)  # still drawing the old shape
        self.assertTrue(NurbsLODGui.wait_until_ready(obj))
        node = NurbsLODGui.node_of(obj)
        self.assertIsNot(node, old_node)
        self.assertAlmostEqual(node.pixelError.getValue(), 0.8, places=6)  # its options kept
        view.fitAll()
        gt.settle(view, obj)
        self.assertGreater(NurbsLODGui.face_bounds(obj, 1)[1][0], 250.0)
        # deleted while a new shape is read: the thread's result goes nowhere
        obj.Shape = gt.bicubic_face(12)
        self.assertTrue(NurbsLODGui.is_pending(obj))
        thread = NurbsLODGui._pending[NurbsLODGui._key(obj)].thread
        key = NurbsLODGui._key(obj)
        document.removeObject(obj.Name)
        thread.join(60)
        _pump(0.2)
        self.assertNotIn(key, NurbsLODGui._displays)
        self.assertNotIn(key, NurbsLODGui._pending)


def _close_if_open(name):
    try:
        FreeCAD.getDocument(name)
    except NameError:
        return
    FreeCAD.closeDocument(name)
    FreeCADGui.updateGui()


if __name__ == "__main__":
    unittest.main()
