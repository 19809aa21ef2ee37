"""The workbench in the GUI: its command toggles adaptive display and Edit > Undo swaps back;
the preferences page loads and its parameters reach the node."""

import os
import unittest

import FreeCAD
import FreeCADGui

import gui_testing as gt
import NurbsLODGui


class AdaptiveDisplayCommand(unittest.TestCase):
    def setUp(self):
        import Part

        FreeCADGui.activateWorkbench("NurbsLODWorkbench")
        self.document = FreeCAD.newDocument("Command")
        self.addCleanup(gt.close, self.document)
        self.document.UndoMode = 1
        self.obj = self.document.addObject("Part::Feature", "Sphere")
        self.obj.Shape = Part.makeSphere(5)
        self.document.recompute()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(self.obj)
        self.addCleanup(FreeCADGui.Selection.clearSelection)

    def test_command_is_in_the_workbench(self):
        import NurbsLODAdaptiveCommand

        self.assertIn(NurbsLODAdaptiveCommand.COMMAND_NAME, FreeCADGui.listCommands())
        self.assertTrue(
            os.path.isfile(FreeCADGui.Command.get(NurbsLODAdaptiveCommand.COMMAND_NAME)
                           .getInfo()["pixmap"]))

    def test_toggle_and_undo_swap_the_display(self):
        import NurbsLODAdaptiveCommand

        FreeCADGui.runCommand(NurbsLODAdaptiveCommand.COMMAND_NAME)
        # the command imports in a thread: FreeCAD's display stays until the swap
        self.assertTrue(NurbsLODGui.is_pending(self.obj) or NurbsLODGui.is_enabled(self.obj))
        self.assertTrue(NurbsLODGui.wait_until_ready(self.obj))
        self.assertIn("Adaptive display on", self.document.UndoNames)
        self.document.undo()
        self.assertFalse(NurbsLODGui.is_enabled(self.obj))
        self.assertFalse(NurbsLODGui.is_pending(self.obj))
        self.document.redo()
        self.assertTrue(NurbsLODGui.wait_until_ready(self.obj))
        FreeCADGui.runCommand(NurbsLODAdaptiveCommand.COMMAND_NAME)
        self.assertFalse(NurbsLODGui.is_enabled(self.obj))
        self.document.undo()
        self.assertTrue(NurbsLODGui.wait_until_ready(self.obj))
        # undone before the import finished: the display never swaps
        self.document.undo()
        self.document.redo()
        self.document.undo()
        self.assertFalse(NurbsLODGui.wait_until_ready(self.obj))
        self.assertFalse(NurbsLODGui.is_enabled(self.obj))
        NurbsLODGui.disable_adaptive_display(self.obj)


class Preferences(unittest.TestCase):
    def test_page_loads_with_its_parameter_widgets(self):
        from PySide import QtGui

        page = os.path.join(gt.ROOT, "Resources", "ui", "NurbsLODPreferences.ui")
        widget = FreeCADGui.PySideUic.loadUi(page)
        for name in ("pixelError", "frameBudget", "normalError", "zebraWidth", "exportRelative"):
            self.assertIsNotNone(widget.findChild(QtGui.QDoubleSpinBox, name), name)
        for name in ("isophoteCount", "zebraStripes"):
            self.assertIsNotNone(widget.findChild(QtGui.QSpinBox, name), name)
        self.assertEqual(widget.findChild(QtGui.QComboBox, "exportMode").count(), 2)

    def test_parameters_reach_the_node(self):
        import Part

        parameters = NurbsLODGui.parameters()
        parameters.SetFloat("PixelError", 0.8)
        parameters.SetFloat("FrameBudgetMs", 12.0)
        self.addCleanup(parameters.RemFloat, "PixelError")
        self.addCleanup(parameters.RemFloat, "FrameBudgetMs")
        document = FreeCAD.newDocument("Preferences")
        self.addCleanup(gt.close, document)
        obj = document.addObject("Part::Feature", "Box")
        obj.Shape = Part.makeBox(1, 2, 3)
        document.recompute()
        NurbsLODGui.enable_adaptive_display(obj)
        stats = NurbsLODGui.stats(obj)
        self.assertAlmostEqual(stats["pixel_error"], 0.8, places=6)
        self.assertAlmostEqual(stats["frame_budget_ms"], 12.0, places=6)
        # a macro's argument wins over the preference
        NurbsLODGui.enable_adaptive_display(obj, pixel_error=0.25)
        self.assertAlmostEqual(NurbsLODGui.stats(obj)["pixel_error"], 0.25, places=6)



class ExportCommandInTheGui(unittest.TestCase):
    """The command "Export certified mesh" as a user runs it: the file dialog (answered here),
    then a progress dialog that the export fills in as the faces are done."""

    def test_export_writes_the_file_and_fills_the_progress_dialog(self):
        import shutil
        import tempfile

        import Part
        from PySide import QtGui

        import NurbsLODExportCommand

        FreeCADGui.activateWorkbench("NurbsLODWorkbench")
        document = FreeCAD.newDocument("ExportCommand")
        self.addCleanup(gt.close, document)
        obj = document.addObject("Part::Feature", "Bracket")
        obj.Shape = Part.makeBox(20, 10, 5).cut(Part.makeCylinder(3, 5, FreeCAD.Vector(10, 5, 0)))
        document.recompute()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)
        self.addCleanup(FreeCADGui.Selection.clearSelection)
        folder = tempfile.mkdtemp(prefix="nurbslod-export-")
        self.addCleanup(shutil.rmtree, folder, True)
        path = os.path.join(folder, "bracket")  # no extension: the chosen filter's is added

        dialogs = []

        class RecordingProgressDialog(QtGui.QProgressDialog):
            def __init__(self, *args):
                super().__init__(*args)
                self.values = []
                dialogs.append(self)

            def setValue(self, value):
                self.values.append((value, self.maximum()))
                super().setValue(value)

        saved = (QtGui.QFileDialog.getSaveFileName, QtGui.QProgressDialog)
        QtGui.QFileDialog.getSaveFileName = staticmethod(
            lambda *args, **kwargs: (path, "Stanford PLY (*.ply)"))
        QtGui.QProgressDialog = RecordingProgressDialog
        try:
            FreeCADGui.runCommand(NurbsLODExportCommand.COMMAND_NAME)
        finally:
            QtGui.QFileDialog.getSaveFileName, QtGui.QProgressDialog = saved
        self.assertTrue(os.path.getsize(path + ".ply") > 0)
        self.assertEqual(len(dialogs), 1)
        values = dialogs[0].values
        self.assertTrue(values, "the progress dialog got no value")
        # the bar ends full: both stages reported every face
        self.assertEqual(values[-1][0], values[-1][1])
        self.assertEqual(values[-1][1], 2 * len(obj.Shape.Faces))
        self.assertEqual([value for value, _ in values], sorted(value for value, _ in values))


class ShapeBelowTheConfusionDistance(unittest.TestCase):
    """A sphere of radius 5e-8: the tessellator refuses it, and the fallback to FreeCAD's own
    mesher, which ran for ever on it in the GUI thread, is not tried."""

    def test_adaptive_display_returns_and_names_the_face(self):
        import time

        import Part

        document = FreeCAD.newDocument("Tiny")
        self.addCleanup(gt.close, document)
        obj = document.addObject("Part::Feature", "Tiny")
        obj.Shape = Part.makeSphere(5e-8)
        document.recompute()
        start = time.time()
        NurbsLODGui.enable_adaptive_display(obj, wait=False)
        self.assertTrue(NurbsLODGui.wait_until_ready(obj, 30))
        self.assertLess(time.time() - start, 30)
        self.addCleanup(NurbsLODGui.disable_adaptive_display, obj)
        FreeCADGui.updateGui()
        self.assertEqual(NurbsLODGui.stats(obj)["faces_failed"], 1)


if __name__ == "__main__":
    unittest.main()
