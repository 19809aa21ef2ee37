"""What the GUI tests share: documents, the camera, waiting for the view to settle, pictures."""

import os
import time
import unittest

import FreeCAD
import FreeCADGui

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS_DIR = os.path.join(os.path.dirname(ROOT), "shared", "corpus")
SCREENSHOT_DIR = os.environ.get("NURBSLOD_SCREENSHOT_DIR") or os.path.join(
    ROOT, "out", "gui-screenshots"
)
# Small pictures: the reference copies live in the repository.
IMAGE_SIZE = (480, 360)


def corpus_file(name):
    path = os.path.join(CORPUS_DIR, name)
    if not os.path.isfile(path):
        raise unittest.SkipTest("corpus model {} absent".format(path))
    return path


def sample_model(directory):
    """The project's sample model (scripts/make_sample_model.py), written into directory."""
    import runpy

    path = os.path.join(directory, "sample.step")
    os.environ["NURBSLOD_SAMPLE_OUT"] = path
    try:
        runpy.run_path(os.path.join(ROOT, "scripts", "make_sample_model.py"), run_name="__main__")
    except SystemExit:
        pass
    if not os.path.isfile(path):
        raise RuntimeError("make_sample_model.py wrote no " + path)
    return path


def open_model(path, name="Model"):
    """A new document with one Part::Feature holding the file's shape, shown fitted."""
    import Part

    return open_shape(Part.read(path), name)


def open_shape(shape, name, placement=None, undo=False):
    """A new document with one Part::Feature holding shape at placement, shown fitted:
    (document, obj, view). undo: the document records undo steps (for edits)."""
    document = FreeCAD.newDocument(name)
    if undo:
        document.UndoMode = 1
    obj = document.addObject("Part::Feature", name)
    obj.Shape = shape
    if placement is not None:
        obj.Placement = placement
    document.recompute()
    view = FreeCADGui.getDocument(document.Name).activeView()
    view.viewIsometric()
    view.fitAll()
    FreeCADGui.updateGui()
    return document, obj, view


def close(document):
    FreeCAD.closeDocument(document.Name)
    FreeCADGui.updateGui()


def draw(view):
    view.redraw()
    FreeCADGui.updateGui()


def settle(view, obj, seconds=60.0):
    """Redraws until every visible face shows the level it wants (no job pending, none drawn
    coarser than wanted). Returns (stats of the settled frame, the largest
    last_frame_tessellation_ms of the frames on the way, frames drawn); the stats also hold
    worst_cpu_ms, the largest last_frame_tessellation_cpu_ms on the way."""
    import NurbsLODGui

    end = time.time() + seconds
    frames = 0
    worst_frame_ms = 0.0
    worst_cpu_ms = 0.0
    while True:
        before = NurbsLODGui.stats(obj)["frames"]
        draw(view)
        stats = NurbsLODGui.stats(obj)
        if stats["frames"] > before:
            frames += stats["frames"] - before
            worst_cpu_ms = max(worst_cpu_ms, stats["last_frame_tessellation_cpu_ms"])
            worst_frame_ms = max(worst_frame_ms, stats["last_frame_tessellation_ms"])
        if stats["pending_jobs"] == 0 and stats["faces_waiting"] == 0 and stats["frames"] > before:
            stats["worst_cpu_ms"] = worst_cpu_ms
            return stats, worst_frame_ms, frames
        if time.time() > end:
            raise AssertionError("the view did not settle in {} s: {}".format(seconds, stats))
        time.sleep(0.02)


def zoom_on(view, point, factor):
    """Centres the view on point (a FreeCAD.Vector) and zooms in by factor."""
    from pivy import coin

    camera = view.getCameraNode()
    direction = camera.orientation.getValue().multVec(coin.SbVec3f(0, 0, -1))
    distance = camera.focalDistance.getValue()
    target = coin.SbVec3f(point.x, point.y, point.z)
    camera.position.setValue(target - direction * distance)
    if camera.getTypeId().getName().getString() == "OrthographicCamera":
        camera.height.setValue(camera.height.getValue() / factor)
    else:  # perspective: move the eye factor times closer
        camera.position.setValue(target - direction * (distance / factor))
        camera.focalDistance.setValue(distance / factor)
    FreeCADGui.updateGui()


def face_point(face):
    """A point on the face, inside its trimming loops: the surface point nearest to the
    centre of mass."""
    u, v = face.Surface.parameter(face.CenterOfMass)
    point = face.valueAt(u, v)
    if face.isInside(point, 1e-6 * max(face.BoundBox.DiagonalLength, 1.0), True):
        return point
    return face.Vertexes[0].Point


def screenshot(view, name):
    os.makedirs(SCREENSHOT_DIR, exist_ok=True)
    path = os.path.join(SCREENSHOT_DIR, name + ".png")
    view.saveImage(path, IMAGE_SIZE[0], IMAGE_SIZE[1], "Current")
    return path


def shaded_pixels(path):
    """How many pixels of the picture are grey shading: neither FreeCAD's blue background
    nor the black edge lines."""
    from PySide import QtGui

    image = QtGui.QImage(path)
    count = 0
    for y in range(0, image.height(), 2):
        for x in range(0, image.width(), 2):
            color = QtGui.QColor(image.pixel(x, y))
            r, g, b = color.red(), color.green(), color.blue()
            if max(r, g, b) > 50 and max(r, g, b) - min(r, g, b) < 12:
                count += 1
    return count


def coloured_pixels(path, channel):
    """How many pixels are strongly one colour: channel "green" (FreeCAD's selection) or
    "yellow" (its pre-selection)."""
    from PySide import QtGui

    image = QtGui.QImage(path)
    count = 0
    for y in range(0, image.height(), 2):
        for x in range(0, image.width(), 2):
            color = QtGui.QColor(image.pixel(x, y))
            r, g, b = color.red(), color.green(), color.blue()
            if channel == "green" and g > r + 40 and g > b + 40:
                count += 1
            elif channel == "yellow" and r > b + 60 and g > b + 60:
                count += 1
    return count


def bicubic_face(count=20, size=100.0):
    """A count x count bicubic B-spline face over a size x size square, gently waved."""
    import math

    import Part

    poles = [
        [
            FreeCAD.Vector(size * i / (count - 1), size * j / (count - 1),
                           3.0 * math.sin(i * 0.7) * math.cos(j * 0.5))
            for j in range(count)
        ]
        for i in range(count)
    ]
    spans = count - 3
    knots = [float(k) for k in range(spans + 1)]
    mults = [4] + [1] * (spans - 1) + [4]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(poles, mults, mults, knots, knots, False, False, 3, 3)
    return surface.toShape()
