# FreeCAD runs this at GUI start-up, after Init.py has put Workbench/ on sys.path. Keep it
# light: the command module is imported only when the user opens the workbench.


class NurbsLODWorkbench(Workbench):  # noqa: F821 (FreeCAD provides Workbench here)
    import NurbsLODPaths

    MenuText = "NurbsLOD"
    ToolTip = "Tessellate trimmed NURBS models with a guaranteed error"
    Icon = NurbsLODPaths.icon("NurbsLOD.svg")
    del NurbsLODPaths

    def Initialize(self):
        import NurbsLODExportCommand

        commands = [NurbsLODExportCommand.COMMAND_NAME]
        self.appendToolbar("NurbsLOD", commands)
        self.appendMenu("NurbsLOD", commands)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(NurbsLODWorkbench())  # noqa: F821 (FreeCAD provides Gui here)
