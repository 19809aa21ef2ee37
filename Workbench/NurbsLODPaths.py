"""Where the parts of the NurbsLOD workbench live.

FreeCAD runs a workbench's Init.py and InitGui.py without __file__, so they cannot find
the checkout by themselves; this module can, because it is imported normally.
"""

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The build folder of scripts/setup.sh; NURBSLOD_BUILD_DIR points elsewhere (another build).
BUILD_DIR = os.environ.get("NURBSLOD_BUILD_DIR") or os.path.join(ROOT, "build")

# Where CMake puts the compiled Python module NurbsLOD.
MODULE_DIR = os.path.join(BUILD_DIR, "App", "python")

# The workbench's parameter group: Edit > Preferences > NurbsLOD writes it
# (Resources/ui/NurbsLODPreferences.ui), the display, the overlays and the export read it.
PARAMETER_PATH = "User parameter:BaseApp/Preferences/Mod/NurbsLOD"


def icon(name):
    """Path of an icon in Resources/icons."""
    return os.path.join(ROOT, "Resources", "icons", name)


def add_module_dir():
    """Puts the compiled module's folder first on sys.path; returns False when it is not built.

    First, so that this checkout's build wins over a NurbsLOD installed elsewhere.
    """
    if not os.path.isdir(MODULE_DIR):
        return False
    if MODULE_DIR in sys.path:
        sys.path.remove(MODULE_DIR)
    sys.path.insert(0, MODULE_DIR)
    return True
