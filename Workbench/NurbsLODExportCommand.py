"""The command "Export certified mesh": the selected Part objects to OBJ, PLY, STL or OFF.

export_objects() does the work and needs no GUI, so it is tested headless; the command
class only adds the file dialog and the report view.
"""

import math
import os

import FreeCAD

from NurbsLODPaths import PARAMETER_PATH

COMMAND_NAME = "NurbsLOD_ExportCertifiedMesh"

# Edit > Preferences > NurbsLOD > Export certified mesh writes these.
DEFAULT_RELATIVE = 1e-3
MODES = ("guaranteed", "approximate")  # the preference's combo box index

FILE_FILTERS = ";;".join(
    ("Wavefront OBJ (*.obj)", "Stanford PLY (*.ply)", "STL (*.stl)", "Object File Format (*.off)")
)


def shapes_of(objects):
    """The non-empty shapes of the objects that have one (Part features, bodies, ...)."""
    return [obj.Shape for obj in objects if hasattr(obj, "Shape") and not obj.Shape.isNull()]


def export_settings():
    """The preferences' export tolerance (a fraction of the selection's size) and mode; the
    defaults where a value is missing or out of range."""
    import NurbsLOD

    group = FreeCAD.ParamGet(PARAMETER_PATH)
    relative = group.GetFloat("ExportRelative", DEFAULT_RELATIVE)
    # the finest the tessellator takes (the page's own minimum is the same)
    if not (math.isfinite(relative) and NurbsLOD.FINEST_RELATIVE_TOLERANCE <= relative <= 0.1):
        relative = DEFAULT_RELATIVE
    index = group.GetInt("ExportMode", 0)
    return relative, MODES[index] if 0 <= index < len(MODES) else MODES[0]


def export_objects(objects, path, relative=None, mode=None, progress=None):
    """Tessellates the objects' shapes together and writes one mesh file; returns the summary.

    Several objects become one compound, so face ids in the file count across all of them in
    selection order. relative and mode: the preferences' (export_settings) where None.
    progress: None or progress(stage, done, total), as NurbsLOD.export takes it. Raises
    ValueError when no object has a shape.
    """
    import Part

    import NurbsLOD

    shapes = shapes_of(objects)
    if not shapes:
        raise ValueError("NurbsLOD: select at least one object with a shape")
    shape = shapes[0] if len(shapes) == 1 else Part.makeCompound(shapes)
    preferred_relative, preferred_mode = export_settings()
    return NurbsLOD.export(shape, path,
                           relative=preferred_relative if relative is None else relative,
                           mode=preferred_mode if mode is None else mode, progress=progress)


def progress_text(stage, done, total):
    """The progress dialog's line for a stage of the export."""
    verb = "Importing" if stage == "import" else "Tessellating"
    return "{} faces: {} of {}".format(verb, done, total)


def progress_value(stage, done, total):
    """The progress bar's value out of 2 * total: the import is the first half."""
    return done + (total if stage == "tessellate" else 0)


def describe(summary):
    """The report view's line for a finished export."""
    return (
        "NurbsLOD: wrote {output}: {triangles} triangles, {vertices} vertices, {faces} faces "
        "within {tolerance:.4g} ({mode}) in {seconds:.2f} s\n".format(**summary)
    )


class ExportCertifiedMesh:
    def GetResources(self):
        import NurbsLODPaths

        return {
            "Pixmap": NurbsLODPaths.icon("NurbsLOD.svg"),
            "MenuText": "Export certified mesh",
            "ToolTip": "Write the selected objects as a mesh that deviates from them by at most "
            "the tolerance of the preferences (by default 1/1000 of their size)",
        }

    def IsActive(self):
        import FreeCADGui

        return bool(shapes_of(FreeCADGui.Selection.getSelection()))

    def Activated(self):
        import FreeCADGui
        from PySide import QtCore, QtGui

        objects = FreeCADGui.Selection.getSelection()
        path, chosen_filter = QtGui.QFileDialog.getSaveFileName(
            FreeCADGui.getMainWindow(), "Export certified mesh", "", FILE_FILTERS
        )
        if not path:
            return
        if not os.path.splitext(path)[1]:  # the writer picks the format by extension
            path += chosen_filter[chosen_filter.rfind("*") + 1 : -1] or ".obj"
        # A model of thousands of faces takes seconds to minutes: the faces done are shown as
        # they come (the module calls back in this thread, which keeps the window drawn). The
        # work cannot be stopped midway, so the dialog has no cancel button.
        dialog = QtGui.QProgressDialog(
            "Exporting certified mesh", None, 0, 1, FreeCADGui.getMainWindow())
        dialog.setWindowTitle("NurbsLOD")
        dialog.setWindowModality(QtCore.Qt.WindowModal)
        dialog.setMinimumDuration(500)

        def report(stage, done, total):
            dialog.setMaximum(max(1, 2 * total))
            dialog.setValue(progress_value(stage, done, total))
            dialog.setLabelText(progress_text(stage, done, total))
            QtGui.QApplication.processEvents()

        QtGui.QApplication.setOverrideCursor(QtGui.QCursor(QtCore.Qt.WaitCursor))
        try:
            summary = export_objects(objects, path, progress=report)
        except Exception as error:  # a command must not raise: tell the user instead
            FreeCAD.Console.PrintError("NurbsLOD: export failed: {}\n".format(error))
            return
        finally:
            QtGui.QApplication.restoreOverrideCursor()
            dialog.close()
        FreeCAD.Console.PrintMessage(describe(summary))
        for failure in summary["faces_failed"]:
            FreeCAD.Console.PrintWarning(
                "NurbsLOD: face {face} not tessellated: {reason}\n".format(**failure))


if FreeCAD.GuiUp:
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, ExportCertifiedMesh())
