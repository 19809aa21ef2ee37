"""A saved document gets its adaptive display and overlay back when it is opened again
(NurbsLODRestore, installed by InitGui.py)."""

import os
import shutil
import tempfile
import time
import unittest

import FreeCAD
import FreeCADGui

import gui_testing as gt
import NurbsLODGui
import NurbsLODOverlays
from test_overlay_async import _close_if_open, _pump


class RestoreOnOpen(unittest.TestCase):
    def test_adaptive_display_and_zebra_come_back_when_the_document_is_opened(self):
        directory = tempfile.mkdtemp(prefix="nurbslod-restore-")
        self.addCleanup(shutil.rmtree, directory, True)
        document, obj, view = gt.open_shape(gt.bicubic_face(8), "Saved")
        self.addCleanup(_close_if_open, document.Name)
        NurbsLODGui.enable_adaptive_display(obj)
        NurbsLODGui.set_overlay(obj, "zebra", stripes=12)
        self.assertTrue(obj.ViewObject.AdaptiveDisplay)
        self.assertEqual(obj.ViewObject.Overlay, "zebra")
        path = os.path.join(directory, "saved.FCStd")
        document.saveAs(path)
        name = obj.Name
        gt.close(document)

        document = FreeCAD.openDocument(path)
        self.addCleanup(_close_if_open, document.Name)
        obj = document.getObject(name)
        view = FreeCADGui.getDocument(document.Name).activeView()
        deadline = time.monotonic() + 60
        while not NurbsLODGui.is_enabled(obj) and time.monotonic() < deadline:
            _pump(0.05)  # the observer looks at the document from the event loop
        self.assertTrue(NurbsLODGui.wait_until_ready(obj))
        result = NurbsLODGui.wait_for_overlay(obj, 120)
        self.assertIsNotNone(result)
        self.assertEqual(result["kind"], "zebra")
        self.assertEqual(result["options"]["count"], 12)
        view.viewIsometric()
        view.fitAll()
        gt.draw(view)
        gt.screenshot(view, "restored-adaptive-zebra")
        # the overlay draws instead of the faces; without it the node draws them
        NurbsLODGui.set_overlay(obj, None)
        stats, _, _ = gt.settle(view, obj)
        self.assertGreater(stats["triangles"], 0)
        self.assertLessEqual(stats["max_screen_error_px"], 0.5 + 1e-9)
        # turned off and saved again: it stays off when opened
        NurbsLODGui.disable_adaptive_display(obj)
        self.assertFalse(obj.ViewObject.AdaptiveDisplay)
        self.assertEqual(obj.ViewObject.Overlay, "")
        document.save()
        gt.close(document)
        document = FreeCAD.openDocument(path)
        self.addCleanup(_close_if_open, document.Name)
        obj = document.getObject(name)
        _pump(0.5)
        self.assertFalse(NurbsLODGui.is_enabled(obj) or NurbsLODGui.is_pending(obj))
        self.assertIsNone(NurbsLODOverlays.overlay_of(obj))


if __name__ == "__main__":
    unittest.main()
