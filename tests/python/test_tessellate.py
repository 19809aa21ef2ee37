"""NurbsLOD.tessellate: the arrays it returns, the error it promises, and bad input."""

import pathlib
import unittest

import FreeCAD
import numpy as np
import Part

import NurbsLOD
from nurbslod_testing import TempDirTestCase, bspline_face, corpus_file, edge_use_counts

DATA = pathlib.Path(__file__).resolve().parent.parent / "data"


class ArrayContract(unittest.TestCase):
    """What every result must satisfy, whatever the shape."""

    def check_result(self, result, shape, tolerance):
        points, triangles = result["points"], result["triangles"]
        normals, corner_normals = result["normals"], result["triangle_normals"]
        face_ids, summary = result["face_ids"], result["summary"]
        t = len(triangles)
        self.assertGreater(t, 0)
        self.assertEqual(points.dtype, np.float64)
        self.assertEqual(points.ndim, 2)
        self.assertEqual(points.shape[1], 3)
        self.assertEqual(normals.dtype, np.float64)
        self.assertEqual(normals.shape[1:], (3,))
        self.assertEqual(triangles.dtype, np.uint32)
        self.assertEqual(triangles.shape, (t, 3))
        self.assertEqual(corner_normals.dtype, np.uint32)
        self.assertEqual(corner_normals.shape, (t, 3))
        self.assertEqual(face_ids.dtype, np.int32)
        self.assertEqual(face_ids.shape, (t,))

        self.assertLess(int(triangles.max()), len(points))
        self.assertLess(int(corner_normals.max()), len(normals))
        self.assertTrue(np.all(np.isfinite(points)))
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-6)
        # no triangle repeats a corner or has zero area (its normal would be NaN)
        self.assertTrue(np.all((triangles[:, 0] != triangles[:, 1])
                               & (triangles[:, 1] != triangles[:, 2])
                               & (triangles[:, 2] != triangles[:, 0])))
        corners = points[triangles]
        cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        lengths = np.linalg.norm(cross, axis=1)
        self.assertEqual(int(np.count_nonzero(lengths <= 0)), 0, "zero-area triangles")
        geometric = cross / np.where(lengths > 0, lengths, 1.0)[:, None]  # counter-clockwise

        # every face of the shape is there, and no other
        faces = len(shape.Faces)
        self.assertEqual(sorted(set(face_ids.tolist())), list(range(1, faces + 1)))

        # corner normals point to the same side as the triangle's winding...
        for corner in range(3):
            dots = np.einsum("ij,ij->i", normals[corner_normals[:, corner]], geometric)
            self.assertEqual(int(np.count_nonzero(~(dots > 0))), 0,
                             "corner {} normals against the winding".format(corner))
        # ...and that side is the outside of the face (FreeCAD's normalAt knows a reversed
        # face); checked on a sample, as FreeCAD evaluates one point at a time
        step = max(1, len(triangles) // 300)
        against = []
        for i in range(0, len(triangles), step):
            face = shape.Faces[face_ids[i] - 1]
            u, v = face.Surface.parameter(FreeCAD.Vector(*corners[i].mean(axis=0)))
            if np.dot(np.array(face.normalAt(u, v)), geometric[i]) <= 0:
                against.append((i, int(face_ids[i])))
        self.assertEqual(against, [], "(triangle, face) wound against the face's normal")

        self.assertEqual(summary["faces"], faces)
        self.assertEqual(summary["triangles"], t)
        self.assertEqual(summary["vertices"], len(points))
        self.assertEqual(summary["faces_failed"], [])
        self.assertGreaterEqual(summary["seconds"], 0.0)
        self.assertGreaterEqual(summary["total_seconds"], summary["seconds"])
        # reading and importing come before the tessellation, all within the whole call
        self.assertGreater(summary["read_seconds"], 0.0)
        self.assertGreater(summary["import_seconds"], 0.0)
        self.assertLessEqual(
            summary["read_seconds"] + summary["import_seconds"] + summary["seconds"],
            summary["total_seconds"])
        if tolerance is not None:
            self.assertAlmostEqual(summary["tolerance"], tolerance)

    def check_closed(self, triangles):
        """A closed solid gives a closed, consistently oriented mesh: every edge is used once
        in each direction."""
        directed = {}
        for a, b, c in triangles.tolist():
            for u, v in ((a, b), (b, c), (c, a)):
                directed[(u, v)] = directed.get((u, v), 0) + 1
        twice = sum(1 for n in directed.values() if n > 1)
        self.assertEqual(twice, 0, "edges used twice in one direction (a face wound backwards)")
        uses = list(edge_use_counts(triangles).values())
        self.assertEqual(uses.count(1), 0, "open edges (cracks between or inside faces)")
        self.assertTrue(all(n == 2 for n in uses), "edges shared by more than two triangles")


class TessellateSolids(ArrayContract):
    def test_box(self):
        box = Part.makeBox(10, 20, 30)
        result = NurbsLOD.tessellate(box, tolerance=0.01)
        self.check_result(result, box, 0.01)
        self.check_closed(result["triangles"])
        points = result["points"]
        # every point lies on the box's surface
        self.assertTrue(np.all(points >= -1e-9) and np.all(points <= [10 + 1e-9, 20 + 1e-9,
                                                                         30 + 1e-9]))
        on_side = (np.isclose(points, 0, atol=1e-9) | np.isclose(points, [10, 20, 30],
                                                                 atol=1e-9))
        self.assertTrue(np.all(on_side.any(axis=1)))
        # a triangle lies on the face its id names: shape.Faces[id - 1]
        centroids = points[result["triangles"]].mean(axis=1)
        for centroid, face_id in zip(centroids, result["face_ids"]):
            face = box.Faces[face_id - 1]
            distance = face.distToShape(Part.Vertex(FreeCAD.Vector(*centroid)))[0]
            self.assertLess(distance, 1e-7, "face id {} is not the triangle's face".format(
                face_id))

    def test_sphere_within_tolerance(self):
        radius, tolerance = 10.0, 0.01
        sphere = Part.makeSphere(radius)
        result = NurbsLOD.tessellate(sphere, tolerance=tolerance)
        self.check_result(result, sphere, tolerance)
        self.check_closed(result["triangles"])
        points, triangles = result["points"], result["triangles"]
        np.testing.assert_allclose(np.linalg.norm(points, axis=1), radius, atol=tolerance)
        # the guarantee: no point of a triangle is farther than the tolerance from the sphere
        # (a chord's farthest points are its centroid and edge midpoints)
        corners = points[triangles]
        for inner in (corners.mean(axis=1), (corners[:, 0] + corners[:, 1]) / 2,
                      (corners[:, 1] + corners[:, 2]) / 2, (corners[:, 2] + corners[:, 0]) / 2):
            self.assertGreaterEqual(np.linalg.norm(inner, axis=1).min(), radius - tolerance)
        # corner normals are the sphere's normals there
        normals = result["normals"][result["triangle_normals"]]
        radial = corners / np.linalg.norm(corners, axis=2)[:, :, None]
        self.assertGreater(np.einsum("ijk,ijk->ij", normals, radial).min(), 0.999)

    def test_cylinder(self):
        cylinder = Part.makeCylinder(5, 12)
        result = NurbsLOD.tessellate(cylinder, tolerance=0.005)
        self.check_result(result, cylinder, 0.005)
        self.check_closed(result["triangles"])

    def test_tighter_tolerance_gives_more_triangles(self):
        sphere = Part.makeSphere(10.0)
        coarse = NurbsLOD.tessellate(sphere, tolerance=0.1)["summary"]["triangles"]
        fine = NurbsLOD.tessellate(sphere, tolerance=0.001)["summary"]["triangles"]
        self.assertGreater(fine, 2 * coarse)

    def test_approximate_mode_needs_no_more_triangles(self):
        sphere = Part.makeSphere(10.0)
        guaranteed = NurbsLOD.tessellate(sphere, tolerance=0.01)
        approximate = NurbsLOD.tessellate(sphere, tolerance=0.01, mode="approximate")
        self.assertEqual(approximate["summary"]["mode"], "approximate")
        self.assertEqual(guaranteed["summary"]["mode"], "guaranteed")
        self.check_result(approximate, sphere, 0.01)
        self.assertLessEqual(approximate["summary"]["triangles"],
                             guaranteed["summary"]["triangles"])

    def test_compact_keeps_the_guarantee_with_fewer_triangles(self):
        # tolerance 0.01 on a sphere of radius 10 is relative 2.9e-4 of its diagonal
        radius, tolerance = 10.0, 0.01
        sphere = Part.makeSphere(radius)
        plain = NurbsLOD.tessellate(sphere, tolerance=tolerance)
        compact = NurbsLOD.tessellate(sphere, tolerance=tolerance, compact=True)
        self.check_result(compact, sphere, tolerance)
        self.check_closed(compact["triangles"])
        # a sphere's plain mesh has few points to spare since its columns are tested on the rows
        # its kd-tree cuts (9,660 triangles, compact 9,636); FreeCAD's loft through a circle, an
        # ellipse and a tilted circle (tests/data/freecad_loft.brep) at relative 5e-4 has more:
        # 2,680 against 3,424
        self.assertLessEqual(compact["summary"]["triangles"], plain["summary"]["triangles"])
        loft = Part.read(str(DATA / "freecad_loft.brep"))
        loft_plain = NurbsLOD.tessellate(loft, relative=5e-4)
        loft_compact = NurbsLOD.tessellate(loft, relative=5e-4, compact=True)
        self.check_result(loft_compact, loft, loft_compact["summary"]["tolerance"])
        self.check_closed(loft_compact["triangles"])
        self.assertLess(loft_compact["summary"]["triangles"],
                        0.9 * loft_plain["summary"]["triangles"])
        # the guarantee, as for the plain mesh: no triangle's centroid or side middle is inside
        # the sphere by more than the tolerance (the corners are on it)
        points, triangles = compact["points"], compact["triangles"]
        np.testing.assert_allclose(np.linalg.norm(points, axis=1), radius, atol=1e-9)
        corners = points[triangles]
        for inner in (corners.mean(axis=1), (corners[:, 0] + corners[:, 1]) / 2,
                      (corners[:, 1] + corners[:, 2]) / 2, (corners[:, 2] + corners[:, 0]) / 2):
            self.assertGreaterEqual(np.linalg.norm(inner, axis=1).min(), radius - tolerance)
        # approximate mode has no such bound to keep: compact leaves it as it is
        self.assertEqual(
            NurbsLOD.tessellate(sphere, tolerance=tolerance, mode="approximate",
                                compact=True)["summary"]["triangles"],
            NurbsLOD.tessellate(sphere, tolerance=tolerance,
                                mode="approximate")["summary"]["triangles"])

    def test_thread_count_does_not_change_the_mesh(self):
        shape = Part.makeCylinder(5, 12).fuse(Part.makeSphere(6, FreeCAD.Vector(0, 0, 12)))
        one = NurbsLOD.tessellate(shape, tolerance=0.01, threads=1)
        many = NurbsLOD.tessellate(shape, tolerance=0.01, threads=4)
        np.testing.assert_array_equal(one["triangles"], many["triangles"])
        np.testing.assert_array_equal(one["points"], many["points"])


class TessellateFreeform(ArrayContract):
    def test_bspline_face_within_tolerance(self):
        face, tolerance = bspline_face(), 0.01
        result = NurbsLOD.tessellate(face, tolerance=tolerance)
        self.check_result(result, face, tolerance)
        self.assertTrue(np.all(result["face_ids"] == 1))
        # an open face: its border edges are used once, inner edges twice
        self.assertTrue(set(edge_use_counts(result["triangles"]).values()) <= {1, 2})
        points, triangles = result["points"], result["triangles"]
        step = max(1, len(triangles) // 200)
        for corners in points[triangles[::step]]:
            for sample in (corners.mean(axis=0), (corners[0] + corners[1]) / 2):
                distance = face.distToShape(Part.Vertex(FreeCAD.Vector(*sample)))[0]
                self.assertLessEqual(distance, tolerance * (1 + 1e-6))

    def test_trimmed_bspline_face(self):
        face = bspline_face().cut(Part.makeCylinder(4, 40, FreeCAD.Vector(15, 15, -20)))
        self.assertEqual(len(face.Faces[0].Wires), 2)
        result = NurbsLOD.tessellate(face, tolerance=0.01)
        self.check_result(result, face, 0.01)
        # nothing inside the hole
        centroids = result["points"][result["triangles"]].mean(axis=1)
        in_hole = np.hypot(centroids[:, 0] - 15, centroids[:, 1] - 15) < 4 - 0.05
        self.assertFalse(np.any(in_hole), "triangles inside the trimmed-away hole")


class ToleranceArguments(unittest.TestCase):
    box = Part.makeBox(10, 20, 30)

    def test_relative_is_a_fraction_of_the_diagonal(self):
        summary = NurbsLOD.tessellate(self.box, relative=1e-2)["summary"]
        diagonal = self.box.BoundBox.DiagonalLength
        self.assertAlmostEqual(summary["tolerance"] / (1e-2 * diagonal), 1.0, delta=0.01)

    def test_default_is_relative_1e_3(self):
        default = NurbsLOD.tessellate(self.box)["summary"]["tolerance"]
        explicit = NurbsLOD.tessellate(self.box, relative=1e-3)["summary"]["tolerance"]
        self.assertEqual(default, explicit)

    def test_bad_tolerances_raise_value_error(self):
        for bad in (0.0, -1.0, float("nan"), float("inf"), -0.0):
            with self.subTest(tolerance=bad):
                with self.assertRaisesRegex(ValueError, "tolerance"):
                    NurbsLOD.tessellate(self.box, tolerance=bad)
            with self.subTest(relative=bad):
                with self.assertRaisesRegex(ValueError, "relative"):
                    NurbsLOD.tessellate(self.box, relative=bad)

    def test_both_tolerances_raise_value_error(self):
        with self.assertRaisesRegex(ValueError, "not both"):
            NurbsLOD.tessellate(self.box, tolerance=0.1, relative=1e-3)

    def test_tolerance_must_be_a_number(self):
        with self.assertRaises(TypeError):
            NurbsLOD.tessellate(self.box, tolerance="abc")

    def test_exported_limits_are_the_ones_enforced(self):
        # a box just above the size floor is meshed, one just below is refused
        floor = NurbsLOD.SMALLEST_MODEL
        edge = floor / 3**0.5
        above = Part.makeBox(1.01 * edge, 1.01 * edge, 1.01 * edge)
        self.assertGreater(NurbsLOD.tessellate(above)["summary"]["triangles"], 0)
        below = Part.makeBox(0.99 * edge, 0.99 * edge, 0.99 * edge)
        with self.assertRaisesRegex(ValueError, "across"):
            NurbsLOD.tessellate(below)
        # the finest relative tolerance is taken, a finer one refused
        finest = NurbsLOD.FINEST_RELATIVE_TOLERANCE
        self.assertGreater(
            NurbsLOD.tessellate(self.box, relative=1.01 * finest)["summary"]["triangles"], 0
        )
        with self.assertRaisesRegex(ValueError, "finer than"):
            NurbsLOD.tessellate(self.box, relative=0.5 * finest)

    def test_bad_mode_and_threads_raise_value_error(self):
        with self.assertRaisesRegex(ValueError, "mode"):
            NurbsLOD.tessellate(self.box, tolerance=0.1, mode="exact")
        with self.assertRaisesRegex(ValueError, "threads"):
            NurbsLOD.tessellate(self.box, tolerance=0.1, threads=-1)


class ShapeArguments(TempDirTestCase):
    box = Part.makeBox(10, 20, 30)

    def test_document_object(self):
        doc = FreeCAD.newDocument("NurbsLODTest")
        self.addCleanup(FreeCAD.closeDocument, doc.Name)
        obj = doc.addObject("Part::Cylinder", "Cylinder")
        doc.recompute()
        result = NurbsLOD.tessellate(obj, tolerance=0.01)
        self.assertEqual(result["summary"]["faces"], 3)

    def test_file_paths(self):
        for name in ("box.brep", "box.step", "box.iges"):
            path = self.path(name)
            if name.endswith(".brep"):
                self.box.exportBrep(path)
            elif name.endswith(".step"):
                self.box.exportStep(path)
            else:
                self.box.exportIges(path)
            for given in (path, pathlib.Path(path)):
                with self.subTest(path=given):
                    result = NurbsLOD.tessellate(given, tolerance=0.01)
                    self.assertEqual(sorted(set(result["face_ids"].tolist())),
                                     list(range(1, 7)))

    def test_unreadable_files_raise_value_error(self):
        garbage = self.path("garbage.step")
        with open(garbage, "w") as out:
            out.write("ISO-10303-21;\nthis is not a STEP file\n")
        empty = self.path("empty.brep")
        open(empty, "w").close()
        for path in (self.path("missing.step"), garbage, empty, self.tmp):
            with self.subTest(path=path):
                with self.assertRaises(ValueError):
                    NurbsLOD.tessellate(path, tolerance=0.1)
        self.assertTrue(issubclass(NurbsLOD.ReadError, ValueError))

    def test_shapes_without_faces_raise_value_error(self):
        for shape in (Part.Shape(), Part.Vertex(1, 2, 3), Part.makeCircle(2.0)):
            with self.subTest(shape=shape.ShapeType if not shape.isNull() else "null"):
                with self.assertRaises(ValueError):
                    NurbsLOD.tessellate(shape, tolerance=0.1)

    def test_other_objects_raise_type_error(self):
        for thing in (42, None, [self.box]):
            with self.subTest(thing=thing):
                with self.assertRaises(TypeError):
                    NurbsLOD.tessellate(thing, tolerance=0.1)


class Corpus(ArrayContract):
    """Real CAD files (../shared/corpus); skipped where the corpus is absent."""

    def test_wing_brep(self):
        path = corpus_file("wing.brep")
        shape = Part.read(path)
        result = NurbsLOD.tessellate(path, relative=1e-3)
        self.check_result(result, shape, None)
        self.assertAlmostEqual(result["summary"]["tolerance"],
                               1e-3 * shape.BoundBox.DiagonalLength,
                               delta=1e-5 * shape.BoundBox.DiagonalLength)

    def test_bolt_step_same_as_from_shape(self):
        path = corpus_file("bug3883_xr2-ct-214_bolt.stp")
        shape = Part.read(path)
        from_file = NurbsLOD.tessellate(path, tolerance=0.05)
        from_shape = NurbsLOD.tessellate(shape, tolerance=0.05)
        self.check_result(from_file, shape, 0.05)
        self.assertEqual(from_file["summary"]["triangles"], from_shape["summary"]["triangles"])
