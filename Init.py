# FreeCAD runs this at start-up, in freecad and freecadcmd alike, with the workbench folder
# on sys.path but without __file__: find the folder by its Workbench/NurbsLODPaths.py, then
# put Workbench/ and the compiled module NurbsLOD on sys.path so `import NurbsLOD` works.


def _nurbslod_init():
    import os
    import sys

    import FreeCAD

    for entry in list(sys.path):
        workbench_dir = os.path.join(entry, "Workbench")
        if os.path.isfile(os.path.join(workbench_dir, "NurbsLODPaths.py")):
            break
    else:
        FreeCAD.Console.PrintWarning("NurbsLOD: cannot find the workbench folder on sys.path\n")
        return
    if workbench_dir not in sys.path:
        sys.path.append(workbench_dir)
    import NurbsLODPaths

    if not NurbsLODPaths.add_module_dir():
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: the module is not built; run scripts/setup.sh (looked in {})\n".format(
                NurbsLODPaths.MODULE_DIR
            )
        )


_nurbslod_init()
del _nurbslod_init
