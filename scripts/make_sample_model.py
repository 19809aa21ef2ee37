"""Writes the sample model of scripts/setup.sh: a small STEP file that exercises what real
CAD models do to a tessellator.

  - a freeform B-spline patch with a hole cut into it (a trimmed face with an inner loop),
  - a box with every edge filleted (blends meeting at corners, many shared edges),
  - a sphere (degenerate edges at the poles, a seam).

Run with FreeCAD's Python: freecadcmd scripts/make_sample_model.py
The output path is $NURBSLOD_SAMPLE_OUT, default out/sample.step in the checkout.
"""

import os
import sys

import FreeCAD
import Part


def bspline_patch():
    """A 40 x 40 mm bicubic patch with a wavy height field, with a round hole through it."""
    n = 6
    def height(i, j):
        return 6.0 * ((i % 2) - 0.5) * ((j % 3) - 1)

    poles = [[FreeCAD.Vector(8.0 * i, 8.0 * j, height(i, j)) for j in range(n)] for i in range(n)]
    degree = 3
    knots = [0.0, 1.0, 2.0, 3.0]
    mults = [degree + 1, 1, 1, degree + 1]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(
        poles, mults, mults, knots, knots, False, False, degree, degree
    )
    face = Part.Face(surface)
    drill = Part.makeCylinder(6.0, 40.0, FreeCAD.Vector(20.0, 20.0, -20.0))
    return face.cut(drill)


def filleted_box():
    box = Part.makeBox(30.0, 20.0, 10.0, FreeCAD.Vector(60.0, 0.0, 0.0))
    return box.makeFillet(2.5, box.Edges)


def sphere():
    return Part.makeSphere(10.0, FreeCAD.Vector(110.0, 10.0, 0.0))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.environ.get("NURBSLOD_SAMPLE_OUT") or os.path.join(root, "out", "sample.step")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    model = Part.makeCompound([bspline_patch(), filleted_box(), sphere()])
    if not model.isValid():
        raise RuntimeError("the sample model is not a valid shape")
    model.exportStep(out)
    print("make_sample_model: wrote {} ({} faces)".format(out, len(model.Faces)))


try:
    main()
except Exception as error:  # freecadcmd would otherwise print the error and exit 0
    print("make_sample_model: {}".format(error), file=sys.stderr)
    sys.exit(1)
sys.exit(0)
