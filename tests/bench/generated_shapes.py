#!/usr/bin/python3
"""generated_shapes: solids and faces as FreeCAD users build them, written as BREP files.

The corpus holds seven real files; a user's model is more often made in FreeCAD itself:
primitives cut to angles (BRepPrimAPI's partial tori and spheres start their circles at -pi),
booleans, fillets and chamfers, lofts (a twisted one too), revolutions, sweeps along a helix and
a space curve, a freeform patch with a hole and one thickened (an offset surface), a ruled face,
a tube drilled twelve times, a surface fitted through a grid of points (many small spans) and a
solid made of it, a solid 1e5 across and one 1e-3 across. Each shape is a function
here, so that the Python tests take a few and the benchmark takes all:

  /usr/bin/python3 tests/bench/generated_shapes.py OUT_DIR        (writes OUT_DIR/NAME.brep)
  tests/bench/model_benchmark.py --corpus OUT_DIR --md docs/benchmark-generated.md \
      --json docs/benchmark-generated.json

Run with /usr/bin/python3 (or freecadcmd), which finds FreeCAD's modules.
"""
import math
import os
import sys

sys.path.append("/usr/lib/freecad-python3/lib")

import FreeCAD  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector


def elbow():
    """A pipe elbow: the whole tube swept a quarter turn; its end discs are bounded by the
    tube's circles over [-pi, pi]."""
    return Part.makeTorus(10, 3, V(0, 0, 0), V(0, 0, 1), -180, 180, 90)


def torus_three_quarter_section():
    """The tube's section cut to 270 degrees and swept 200: planes bounded by an arc that
    starts at -pi/2."""
    return Part.makeTorus(10, 3, V(0, 0, 0), V(0, 0, 1), -90, 180, 200)


def torus():
    return Part.makeTorus(10, 3)


def spindle_torus():
    """A self-touching torus (minor radius above the major one)."""
    return Part.makeTorus(2, 3)


def sphere():
    return Part.makeSphere(7)


def sphere_segment():
    """A sphere cut to latitudes -30..60 and 270 degrees of longitude."""
    return Part.makeSphere(7, V(0, 0, 0), V(0, 0, 1), -30, 60, 270)


def ellipsoid():
    """A sphere scaled unevenly: a B-spline surface with poles."""
    return Part.makeSphere(5).transformGeometry(
        FreeCAD.Matrix(1.6, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.6, 0, 0, 0, 0, 1))


def cone_to_apex():
    return Part.makeCone(5, 0, 10)


def cone_frustum():
    return Part.makeCone(5, 2, 10)


def box_minus_cylinder():
    return Part.makeBox(20, 20, 20).cut(Part.makeCylinder(6, 40, V(10, 10, -10)))


def crossed_cylinders():
    """Two cylinders fused at right angles: their intersection is a B-spline edge."""
    return Part.makeCylinder(5, 30, V(0, 0, -15)).fuse(
        Part.makeCylinder(4, 30, V(-15, 0, 0), V(1, 0, 0)))


def sphere_minus_cylinder():
    return Part.makeSphere(10).cut(Part.makeCylinder(3, 40, V(2, 0, -20)))


def cone_with_sphere():
    return Part.makeCone(6, 0, 12).fuse(Part.makeSphere(4, V(0, 0, 12)))


def filleted_box():
    box = Part.makeBox(20, 20, 20)
    return box.makeFillet(3, box.Edges)


def chamfered_box():
    box = Part.makeBox(20, 20, 20)
    return box.makeChamfer(2, box.Edges)


def filleted_cylinder():
    cylinder = Part.makeCylinder(5, 10)
    return cylinder.makeFillet(1.5, cylinder.Edges)


def loft():
    """A solid loft through a circle, an ellipse and a tilted circle."""
    sections = [Part.Wire(Part.Circle(V(0, 0, 0), V(0, 0, 1), 5).toShape()),
                Part.Wire(Part.Ellipse(V(0, 0, 10), 8, 3).toShape()),
                Part.Wire(Part.Circle(V(1, 0, 20), V(0, 0.2, 1), 4).toShape())]
    return Part.makeLoft(sections, True)


def freeform_with_hole():
    """An interpolated B-spline patch with a round hole: one face, all its edges free."""
    surface = Part.BSplineSurface()
    surface.interpolate([[V(i * 5, j * 5, 3 * math.sin(i * 0.9) * math.cos(j * 0.7))
                          for j in range(6)] for i in range(6)])
    return surface.toShape().cut(Part.makeCylinder(4, 40, V(12, 12, -20)))


def revolved_profile():
    """A B-spline profile revolved a full turn: one face, open at both ends."""
    profile = Part.BSplineCurve()
    profile.interpolate([V(2, 0, 0), V(5, 0, 3), V(3, 0, 6), V(6, 0, 10), V(1, 0, 14)])
    return profile.toShape().revolve(V(0, 0, 0), V(0, 0, 1), 360)


def helical_sweep():
    """A circle swept along a helix (a spring): a B-spline surface with a helical seam."""
    helix = Part.Wire(Part.makeHelix(4, 12, 10))
    section = Part.Wire(Part.Circle(V(10, 0, 0), V(0, 1, 0), 1.2).toShape())
    return helix.makePipeShell([section], True, True)


def hollow_sphere():
    return Part.makeSphere(6).cut(Part.makeSphere(5))


def box_with_slanted_cut():
    return Part.makeBox(10, 10, 10).cut(Part.makeBox(10, 10, 10, V(5, 0, 5), V(1, 0, 1)))


def huge_box_minus_cylinder():
    """1e5 across: coordinates far from 1."""
    return Part.makeBox(1e5, 1e5, 1e5).cut(Part.makeCylinder(2e4, 3e5, V(5e4, 5e4, -1e5)))


def tiny_box():
    """1e-3 across: a tolerance near OpenCASCADE's confusion distance."""
    return Part.makeBox(1e-3, 2e-3, 3e-3)


def sliver_and_cylinder():
    """A 0.01 thick plate fused with a cylinder: faces far thinner than long."""
    return Part.makeBox(50, 0.01, 10).fuse(Part.makeCylinder(3, 10, V(25, 0, 0)))


def twisted_loft():
    """A solid loft through four squares, each turned 30 degrees from the one below: ruled
    sides whose straight lines turn as they rise (their cells' bound is mostly twist)."""
    sections = []
    for k in range(4):
        square = Part.makePolygon([V(-5, -5, 0), V(5, -5, 0), V(5, 5, 0), V(-5, 5, 0),
                                   V(-5, -5, 0)])
        square.rotate(V(0, 0, 0), V(0, 0, 1), 30 * k)
        square.translate(V(0, 0, 10 * k))
        sections.append(square)
    return Part.makeLoft(sections, True, False)


def ruled_circle_ellipse():
    """One ruled face between a circle and an ellipse above it, its two rims free edges."""
    return Part.makeRuledSurface(Part.Wire(Part.makeCircle(5)),
                                 Part.Wire(Part.Ellipse(V(0, 0, 10), 8, 3).toShape()))


def perforated_tube():
    """A tube with twelve radial holes along a spiral: small cylinders meeting large ones."""
    tube = Part.makeCylinder(10, 40).cut(Part.makeCylinder(9, 40))
    for k in range(12):
        angle = math.radians(30 * k)
        tube = tube.cut(Part.makeCylinder(1, 30, V(0, 0, 5 + 2.5 * k),
                                          V(math.cos(angle), math.sin(angle), 0)))
    return tube


def thickened_freeform():
    """An interpolated B-spline patch thickened by 1 into a solid: its far side an offset
    surface, which the importer converts with BRepBuilderAPI_NurbsConvert."""
    surface = Part.BSplineSurface()
    surface.interpolate([[V(i * 10, j * 10, 3 * math.sin(i) * math.cos(j)) for j in range(5)]
                         for i in range(5)])
    return surface.toShape().makeOffsetShape(1.0, 1e-6, fill=True)


def pipe_along_spline():
    """A circle swept along an interpolated space curve (a bent pipe)."""
    path = Part.BSplineCurve()
    path.interpolate([V(0, 0, 0), V(10, 5, 5), V(20, -5, 10), V(30, 0, 20)])
    section = Part.Wire(Part.makeCircle(2, V(0, 0, 0), path.tangent(path.FirstParameter)[0]))
    return Part.Wire(path.toShape()).makePipeShell([section], True, True)


def fitted_surface():
    """A B-spline surface interpolated through a 60 x 60 grid of heights, as a surface fitted
    to measured points comes: 57 x 57 bicubic spans, far smaller than the surface bends, one
    face, all its edges free."""
    surface = Part.BSplineSurface()
    surface.interpolate([[V(i, j, 3 * math.sin(i / 12) * math.cos(j / 15) +
                            math.sin(i * j / 400)) for j in range(60)] for i in range(60)])
    return surface.toShape()


def fitted_block():
    """The fitted surface extruded down into a solid: its sides extrusions of 37-span curves."""
    return fitted_surface().extrude(V(0, 0, -10))


SHAPES = [elbow, torus_three_quarter_section, torus, spindle_torus, sphere, sphere_segment,
          ellipsoid, cone_to_apex, cone_frustum, box_minus_cylinder, crossed_cylinders,
          sphere_minus_cylinder, cone_with_sphere, filleted_box, chamfered_box,
          filleted_cylinder, loft, freeform_with_hole, revolved_profile, helical_sweep,
          hollow_sphere, box_with_slanted_cut, huge_box_minus_cylinder, tiny_box,
          sliver_and_cylinder, twisted_loft, ruled_circle_ellipse, perforated_tube,
          thickened_freeform, pipe_along_spline, fitted_surface, fitted_block]


def write(folder, shapes=SHAPES):
    """Writes folder/NAME.brep for each shape function; returns the paths."""
    os.makedirs(folder, exist_ok=True)
    paths = []
    for make in shapes:
        path = os.path.join(folder, make.__name__ + ".brep")
        make().exportBrep(path)
        paths.append(path)
    return paths


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    for written in write(sys.argv[1]):
        print(written)
