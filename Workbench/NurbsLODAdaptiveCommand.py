"""The command "Adaptive display": toggles view-dependent display of the selected objects.

It sets the view property AdaptiveDisplay (group NurbsLOD) of each selected object in one
document transaction; NurbsLODGui swaps the display when the property changes, so Edit >
Undo swaps back (FreeCAD records view properties in its transactions).
"""

import FreeCAD

COMMAND_NAME = "NurbsLOD_AdaptiveDisplay"


def candidates(objects):
    """The objects that can be shown adaptively: a non-empty shape with faces, a view."""
    return [
        obj
        for obj in objects
        if hasattr(obj, "Shape")
        and not obj.Shape.isNull()
        and obj.Shape.Faces
        and getattr(obj, "ViewObject", None) is not None
    ]


class AdaptiveDisplay:
    def GetResources(self):
        import NurbsLODPaths

        return {
            "Pixmap": NurbsLODPaths.icon("NurbsLODAdaptive.svg"),
            "MenuText": "Adaptive display",
            "ToolTip": "Draw the selected objects view-dependently: every face within half a "
            "pixel on screen, refined as you zoom (again: FreeCAD's own display)",
        }

    def IsActive(self):
        import FreeCADGui

        return bool(candidates(FreeCADGui.Selection.getSelection()))

    def Activated(self):
        import FreeCADGui

        import NurbsLODGui

        objects = candidates(FreeCADGui.Selection.getSelection())
        # all on, unless all are on already: then all off
        enable = not all(NurbsLODGui.is_enabled(obj) for obj in objects)
        try:
            NurbsLODGui.set_adaptive_display(objects, enable)
        except Exception as error:  # a command must not raise: tell the user instead
            FreeCAD.Console.PrintError("NurbsLOD: adaptive display failed: {}\n".format(error))


if FreeCAD.GuiUp:
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, AdaptiveDisplay())
