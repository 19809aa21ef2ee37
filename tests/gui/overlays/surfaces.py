"""Test surfaces for the continuity overlays: one B-spline surface made of two patches.

z = f(x) + a y^2 over [-20, 20]^2 mm. On the left (x < 0) f = 0, a flat profile; on the right
f = c (x/20)^2 (two patches that meet G1 but not G2: the curvature in x jumps from 0 to
2c/400 at x = 0; a cubic with a double knot) or f = c (x/20)^3 (they meet G2: a cubic with a
simple knot, second derivative 0 on both sides). Degree 3 in x, 2 in y (y^2 is exact).
"""

import FreeCAD
import Part

HALF = 20.0  # mm
HEIGHT = 8.0  # c: f(20) on the right
BOWL = 4.0  # a y^2 reaches this at y = +-20


def _poles_and_knots(continuity):
    # Bezier extraction of the profile f on [-1, 0] (zero) and [0, 1] (c x^2 or c x^3):
    # with unit spans, C1 (double knot) poles sit at the left Bezier's first three and the
    # right Bezier's last three; C2 (simple knot) poles follow from the blossoms.
    if continuity == "G1":
        xs = [-1.0, -2.0 / 3.0, -1.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
        zs = [0.0, 0.0, 0.0, 0.0, HEIGHT / 3.0, HEIGHT]  # c x^2 = cubic Bezier (0, 0, c/3, c)
        mults = [4, 2, 4]
    elif continuity == "G2":
        xs = [-1.0, -2.0 / 3.0, 0.0, 2.0 / 3.0, 1.0]
        zs = [0.0, 0.0, 0.0, 0.0, HEIGHT]  # c x^3 = cubic Bezier (0, 0, 0, c)
        mults = [4, 1, 4]
    else:
        raise ValueError(continuity)
    return xs, zs, mults


def two_patch_surface(continuity):
    """The Part.BSplineSurface: continuity "G1" (G1 but not G2 at x = 0) or "G2"."""
    xs, zs, mults_u = _poles_and_knots(continuity)
    ys, bowl = [-1.0, 0.0, 1.0], [BOWL, -BOWL, BOWL]  # a y^2: quadratic Bezier (a, -a, a)
    poles = [[FreeCAD.Vector(HALF * x, HALF * y, z + b) for y, b in zip(ys, bowl)]
             for x, z in zip(xs, zs)]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(poles, mults_u, [3, 3], [-1.0, 0.0, 1.0], [-1.0, 1.0],
                                     False, False, 3, 2)
    return surface


def two_patch_face(continuity):
    return Part.Face(two_patch_surface(continuity))
