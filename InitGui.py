# FreeCAD runs this at GUI start-up, after Init.py has put Workbench/ on sys.path. Keep it
# light: the command module is imported only when the user opens the workbench.


class NurbsLODWorkbench(Workbench):  # noqa: F821 (FreeCAD provides Workbench here)
    import NurbsLODPaths

    MenuText = "NurbsLOD"
    ToolTip = "Tessellate trimmed NURBS models with a guaranteed error"
    Icon = NurbsLODPaths.icon("NurbsLOD.svg")
    del NurbsLODPaths

    def Initialize(self):
        import NurbsLODAdaptiveCommand
        import NurbsLODExportCommand
        import NurbsLODOverlays
        import NurbsLODPoleEditor

        commands = [
            NurbsLODAdaptiveCommand.COMMAND_NAME,
            NurbsLODPoleEditor.COMMAND_NAME,
            NurbsLODExportCommand.COMMAND_NAME,
        ]
        self.appendToolbar("NurbsLOD", commands)
        self.appendMenu("NurbsLOD", commands)
        overlays = NurbsLODOverlays.register_commands()
        self.appendToolbar("NurbsLOD analysis", overlays)
        self.appendMenu(["NurbsLOD", "Surface analysis"], overlays)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


def _nurbslod_preferences():
    # Edit > Preferences > NurbsLOD: the .ui's Gui::Pref* widgets read and write
    # User parameter:BaseApp/Preferences/Mod/NurbsLOD themselves.
    import os

    import NurbsLODPaths

    page = os.path.join(NurbsLODPaths.ROOT, "Resources", "ui", "NurbsLODPreferences.ui")
    Gui.addPreferencePage(page, "NurbsLOD")  # noqa: F821
    Gui.addIconPath(os.path.join(NurbsLODPaths.ROOT, "Resources", "icons"))  # noqa: F821


def _nurbslod_restore_on_open():
    # Documents saved with adaptive display or overlays get them back when opened, also
    # before the workbench is opened (the observer imports the display modules when needed).
    import NurbsLODRestore

    NurbsLODRestore.install()


Gui.addWorkbench(NurbsLODWorkbench())  # noqa: F821 (FreeCAD provides Gui here)
_nurbslod_preferences()
_nurbslod_restore_on_open()
del _nurbslod_preferences, _nurbslod_restore_on_open
