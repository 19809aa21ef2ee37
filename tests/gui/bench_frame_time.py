"""Benchmark (not a test): frame time with adaptive display against FreeCAD's own display,
five corpus models open, in one run.

    xvfb-run -a -s "-screen 0 1280x1024x24" freecad tests/gui/bench_frame_time.py

The five models stand side by side in one document. A camera path (fit, then a turn and a
zoom in towards one model) is drawn with FreeCAD's own display, then twice with adaptive
display on every model: the first pass refines as it goes (workers making levels), the second
finds the levels cached. A frame is timed from the redraw request to the end of the paint.
Software GL (llvmpipe) under Xvfb: the times say how the two compare, not what a GPU does.
"""

import os
import statistics
import sys
import time
import traceback

from PySide import QtCore

MODELS = [
    "trj7_b1-ec-214.stp",
    "bottle.brep",
    "wing.brep",
    "hammer.iges",
    "bug3883_xr2-ct-214_bolt.stp",
]
STEPS = 24


def _here():
    for argument in sys.argv:
        if argument.endswith("bench_frame_time.py"):
            return os.path.dirname(os.path.abspath(argument))
    return os.path.join(os.getcwd(), "tests", "gui")


def _camera_path(view, target, steps):
    """Yields after setting the camera for each frame: a quarter turn about the vertical
    while zooming in 8x on target."""
    from pivy import coin

    camera = view.getCameraNode()
    start_orientation = camera.orientation.getValue()
    start_height = camera.height.getValue()
    for k in range(steps):
        t = k / (steps - 1)
        turn = coin.SbRotation(coin.SbVec3f(0, 0, 1), 0.5 * 3.14159 * t)
        orientation = start_orientation * turn
        camera.orientation.setValue(orientation)
        direction = orientation.multVec(coin.SbVec3f(0, 0, -1))
        focal = camera.focalDistance.getValue()
        center = coin.SbVec3f(*target)
        camera.position.setValue(center - direction * focal)
        camera.height.setValue(start_height / (1.0 + 7.0 * t))
        yield


def _frame_times(view, target, steps):
    import FreeCADGui

    times = []
    for _ in _camera_path(view, target, steps):
        start = time.perf_counter()
        view.redraw()
        FreeCADGui.updateGui()
        times.append((time.perf_counter() - start) * 1000.0)
    return times


def _row(name, times, extra=""):
    return "| {:<40} | {:>8.1f} | {:>8.1f} | {:>8.1f} | {:<28} |".format(
        name, statistics.mean(times), statistics.median(times), max(times), extra)


def _run():
    code = 0
    try:
        sys.path.insert(0, _here())
        import FreeCAD
        import FreeCADGui
        import Part

        import gui_testing as gt
        import NurbsLODGui

        paths = [os.path.join(gt.CORPUS_DIR, name) for name in MODELS]
        missing = [path for path in paths if not os.path.isfile(path)]
        if missing:
            print("bench_frame_time: corpus models absent: {}".format(", ".join(missing)))
            os._exit(0)
        document = FreeCAD.newDocument("Frames")
        objects = []
        x = 0.0
        for path in paths:
            shape = Part.read(path)
            box = shape.BoundBox
            shape.translate(FreeCAD.Vector(x - box.XMin, -box.Center.y, -box.Center.z))
            x += box.XLength * 1.1
            name = os.path.splitext(os.path.basename(path))[0].replace("-", "_")
            obj = document.addObject("Part::Feature", name)
            obj.Shape = shape
            objects.append(obj)
        document.recompute()
        view = FreeCADGui.getDocument(document.Name).activeView()
        view.viewIsometric()
        view.fitAll()
        FreeCADGui.updateGui()
        first = objects[0].Shape.BoundBox.Center
        target = (first.x, first.y, first.z)

        def reset():
            view.viewIsometric()
            view.fitAll()
            FreeCADGui.updateGui()

        reset()
        own = _frame_times(view, target, STEPS)
        reset()
        start = time.perf_counter()
        failed = 0
        for obj in objects:
            failed += len(NurbsLODGui.enable_adaptive_display(obj)["faces_failed"])
        enable_s = time.perf_counter() - start
        reset()
        cold = _frame_times(view, target, STEPS)
        triangles_cold = sum(NurbsLODGui.stats(obj)["triangles"] for obj in objects)
        reset()
        warm = _frame_times(view, target, STEPS)
        stats = [NurbsLODGui.stats(obj) for obj in objects]
        triangles = sum(s["triangles"] for s in stats)
        error = max(s["max_screen_error_px"] for s in stats)
        lod_ms = max(s["last_frame_tessellation_ms"] for s in stats)

        faces = sum(len(obj.Shape.Faces) for obj in objects)
        print("\nframe time, {} models ({} faces), view {} px high, {} frames along the path; "
              "enabling adaptive display took {:.1f} s, {} faces left to FreeCAD".format(
                  len(objects), faces, view.getSize()[1], STEPS, enable_s, failed))
        print("| {:<40} | {:>8} | {:>8} | {:>8} | {:<28} |".format(
            "milliseconds per frame", "mean", "median", "max", "last frame"))
        print("|" + "|".join("-" * width for width in (42, 10, 10, 10, 30)) + "|")
        print(_row("FreeCAD's own display", own))
        print(_row("adaptive display, first pass (refining)", cold,
                   "{} triangles".format(triangles_cold)))
        print(_row("adaptive display, second pass (cached)", warm,
                   "{} triangles, {:.2f} px".format(triangles, error)))
        print("ratio adaptive (cached) / FreeCAD's own, means: {:.2f}; largest LOD work in the "
              "last frame: {:.2f} ms".format(statistics.mean(warm) / statistics.mean(own), lod_ms))
    except Exception:
        traceback.print_exc()
        code = 1
    sys.stdout.flush()
    os._exit(code)


QtCore.QTimer.singleShot(200, _run)
