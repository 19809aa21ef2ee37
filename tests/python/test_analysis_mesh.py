"""NurbsLOD.analysis_mesh: per-vertex exact normals and curvature for the analysis overlays."""

import unittest

import FreeCAD
import numpy as np
import Part

import NurbsLOD
from nurbslod_testing import bspline_face


class AnalysisMeshOfSphere(unittest.TestCase):
    """A sphere: every vertex on it, normals radial, curvature 1/R everywhere (convex: > 0)."""

    RADIUS = 7.0

    @classmethod
    def setUpClass(cls):
        cls.shape = Part.makeSphere(cls.RADIUS)
        cls.result = NurbsLOD.analysis_mesh(cls.shape, relative=1e-3)

    def test_arrays_fit_together(self):
        r = self.result
        n = len(r["points"])
        self.assertGreater(n, 100)
        self.assertEqual(r["points"].shape, (n, 3))
        self.assertEqual(r["normals"].shape, (n, 3))
        self.assertEqual(r["parameters"].shape, (n, 2))
        for key in ("gaussian", "mean", "minimum", "maximum"):
            self.assertEqual(r[key].shape, (n,), key)
            self.assertTrue(np.all(np.isfinite(r[key])), key)
        t = len(r["triangles"])
        self.assertEqual(r["triangles"].shape, (t, 3))
        self.assertEqual(r["face_ids"].shape, (t,))
        self.assertLess(int(r["triangles"].max()), n)
        self.assertEqual(r["summary"]["faces_failed"], [])
        self.assertEqual(r["summary"]["vertices"], n)

    def test_normals_are_exact_and_outward(self):
        points, normals = self.result["points"], self.result["normals"]
        radial = points / np.linalg.norm(points, axis=1)[:, None]
        self.assertLess(np.abs(np.linalg.norm(normals, axis=1) - 1).max(), 1e-12)
        # exact: the facet normal of a 1e-3 mesh would be off by degrees; at the poles the
        # normal is the limit from a step inside
        self.assertGreater(np.einsum("ij,ij->i", radial, normals).min(), 1 - 1e-8)

    def test_curvature_is_one_over_radius(self):
        r, k = self.result, 1 / self.RADIUS
        # the poles (singular vertices) take the limit from a small step inside: 1e-3
        self.assertGreater(r["summary"]["singular_vertices"], 0)
        for key in ("mean", "minimum", "maximum"):
            error = np.abs(r[key] - k)
            self.assertLess(error.max(), 1e-3 * k, key)
            self.assertLess(np.sort(error)[-r["summary"]["singular_vertices"] - 1], 1e-9 * k, key)
        self.assertLess(np.abs(r["gaussian"] - k * k).max(), 1e-3 * k * k)


class AnalysisMeshOfBSplineFace(unittest.TestCase):
    def test_parameters_give_the_points(self):
        face = bspline_face()
        surface = face.Surface
        r = NurbsLOD.analysis_mesh(face, relative=1e-3)
        edge_tolerance = max(max(e.Tolerance for e in face.Edges), 1e-9)
        for i in range(0, len(r["points"]), max(1, len(r["points"]) // 50)):
            u, v = r["parameters"][i]
            p = surface.value(u, v)
            # a point on the face's border lies on its edge's 3D curve, which may be off the
            # surface by the edge's tolerance
            self.assertLess((p - FreeCAD.Vector(*r["points"][i])).Length, edge_tolerance)
            # FreeCAD's own curvature (OpenCASCADE) at the same point, convex positive: the
            # face's normal here is du x dv, so the sign flips
            k_max, k_min = surface.curvature(u, v, "Max"), surface.curvature(u, v, "Min")
            self.assertAlmostEqual(r["maximum"][i], -k_min, delta=1e-9 * (1 + abs(k_min)))
            self.assertAlmostEqual(r["minimum"][i], -k_max, delta=1e-9 * (1 + abs(k_max)))


class AnalysisMeshSigns(unittest.TestCase):
    def test_cylinder_hole_is_concave(self):
        """A box with a hole: the hole's wall is concave (negative), min curvature -1/r."""
        box = Part.makeBox(20, 20, 10)
        hole = Part.makeCylinder(4, 10, FreeCAD.Vector(10, 10, 0))
        r = NurbsLOD.analysis_mesh(box.cut(hole), relative=1e-3)
        shape_faces = box.cut(hole).Faces
        wall = [i + 1 for i, f in enumerate(shape_faces) if "Cylinder" in f.Surface.TypeId]
        self.assertEqual(len(wall), 1)
        on_wall = np.unique(r["triangles"][r["face_ids"] == wall[0]])
        self.assertLess(np.abs(r["minimum"][on_wall] + 1 / 4).max(), 1e-9)
        self.assertLess(np.abs(r["maximum"][on_wall]).max(), 1e-9)
        self.assertLess(np.abs(r["gaussian"][on_wall]).max(), 1e-9)
        # a plane: all zero
        flat = np.unique(r["triangles"][r["face_ids"] != wall[0]])
        self.assertLess(np.abs(r["mean"][flat]).max(), 1e-12)


class AnalysisMeshBadInput(unittest.TestCase):
    def test_bad_tolerance(self):
        for bad in (0.0, -1.0, float("nan"), float("inf")):
            with self.assertRaises(ValueError):
                NurbsLOD.analysis_mesh(Part.makeBox(1, 1, 1), tolerance=bad)

    def test_not_a_shape(self):
        with self.assertRaises(TypeError):
            NurbsLOD.analysis_mesh(42)

    def test_no_faces(self):
        with self.assertRaises(ValueError):
            NurbsLOD.analysis_mesh(Part.makeLine((0, 0, 0), (1, 0, 0)))


if __name__ == "__main__":
    unittest.main()


class OverlayFaceReplacement(unittest.TestCase):
    """The pole editor's live overlay: one face of an analysis mesh replaced by the analysis
    mesh of its new version, every other face's vertices and triangles kept as they were."""

    def test_one_face_replaced_the_others_kept(self):
        import NurbsLODOverlays

        box = Part.makeBox(10, 20, 30)
        analysis = NurbsLOD.analysis_mesh(box, relative=1e-3)
        moved = box.Faces[2].copy()
        moved.translate(FreeCAD.Vector(0, 0, 5))
        replacement = NurbsLOD.analysis_mesh(moved, relative=1e-3)
        result = NurbsLODOverlays._with_face_replaced(analysis, 3, replacement)

        def face_triangles(mesh, face):
            return mesh["points"][mesh["triangles"][mesh["face_ids"] == face]]

        self.assertEqual(len(result["points"]), len(result["normals"]))
        self.assertEqual(len(result["triangles"]), len(result["face_ids"]))
        self.assertLess(int(result["triangles"].max()), len(result["points"]))
        for face in range(1, 7):
            with self.subTest(face=face):
                expected = replacement if face == 3 else analysis
                ids = 1 if face == 3 else face
                np.testing.assert_array_equal(
                    face_triangles(result, face), face_triangles(expected, ids))
        # no vertex left over from the old face
        used = np.unique(result["triangles"])
        self.assertEqual(len(used), len(result["points"]))
