"""NurbsLOD.export and NurbsLOD.to_mesh, checked with FreeCAD's own Mesh module, and the
workbench's export command without its dialog."""

import os

import FreeCAD
import Mesh
import Part

import NurbsLOD
import NurbsLODExportCommand
from nurbslod_testing import TempDirTestCase


class Export(TempDirTestCase):
    shape = Part.makeBox(10, 20, 30).fuse(Part.makeSphere(8, FreeCAD.Vector(5, 10, 30)))

    def test_formats_read_back_by_freecad(self):
        expected = NurbsLOD.tessellate(self.shape, tolerance=0.02)["summary"]
        for extension in ("obj", "ply", "stl", "off"):
            with self.subTest(format=extension):
                path = self.path("mesh." + extension)
                summary = NurbsLOD.export(self.shape, path, tolerance=0.02)
                self.assertEqual(summary["output"], path)
                self.assertEqual(summary["triangles"], expected["triangles"])
                self.assertEqual(summary["faces"], len(self.shape.Faces))
                self.assertTrue(os.path.getsize(path) > 0)
                self.assertEqual(Mesh.Mesh(path).CountFacets, summary["triangles"])

    def test_obj_groups_name_the_faces(self):
        # The mesh judge (shared/tools/meshjudge.py) maps "g FaceN" to shape.Faces[N - 1].
        path = self.path("mesh.obj")
        summary = NurbsLOD.export(self.shape, path, tolerance=0.02)
        groups = []
        faces_per_group = {}
        with open(path) as obj:
            for line in obj:
                if line.startswith("g "):
                    groups.append(line.split()[1])
                elif line.startswith("f ") and groups:
                    faces_per_group[groups[-1]] = faces_per_group.get(groups[-1], 0) + 1
        names = ["Face{}".format(i) for i in range(1, len(self.shape.Faces) + 1)]
        self.assertEqual(sorted(set(groups)), sorted(names))
        self.assertEqual(sum(faces_per_group.values()), summary["triangles"])

    def test_bad_output_paths_raise(self):
        for path in (self.path("mesh.unknown"), self.path(os.path.join("missing", "mesh.obj"))):
            with self.subTest(path=path):
                with self.assertRaises((ValueError, RuntimeError, OSError)):
                    NurbsLOD.export(self.shape, path, tolerance=0.02)
                self.assertFalse(os.path.exists(path))

    def test_progress_runs_in_the_callers_thread(self):
        import threading
        caller = threading.get_ident()
        threads = set()
        calls = []

        def report(stage, done, total):
            threads.add(threading.get_ident())
            calls.append((stage, done, total))

        NurbsLOD.export(self.shape, self.path("mesh.obj"), tolerance=0.02, progress=report)
        self.assertEqual(threads, {caller})
        self.assertEqual(calls[-1][0], "tessellate")

    def test_progress_errors_are_raised_after_the_work(self):
        def broken(stage, done, total):
            raise KeyError("stopped by the callback")

        path = self.path("mesh.obj")
        with self.assertRaises(KeyError):
            NurbsLOD.export(self.shape, path, tolerance=0.02, progress=broken)
        with self.assertRaises(TypeError):
            NurbsLOD.export(self.shape, path, tolerance=0.02, progress=42)

    def test_bad_tolerance_writes_nothing(self):
        path = self.path("mesh.obj")
        with self.assertRaises(ValueError):
            NurbsLOD.export(self.shape, path, tolerance=0)
        self.assertFalse(os.path.exists(path))


class ToMesh(TempDirTestCase):
    def test_box_mesh(self):
        box = Part.makeBox(10, 20, 30)
        mesh = NurbsLOD.to_mesh(box, tolerance=0.01)
        self.assertIsInstance(mesh, Mesh.Mesh)
        summary = NurbsLOD.tessellate(box, tolerance=0.01)["summary"]
        self.assertEqual(mesh.CountFacets, summary["triangles"])
        # outward-facing and closed: the enclosed volume is the box's
        self.assertAlmostEqual(mesh.Volume, 6000.0, delta=1e-6)
        self.assertTrue(mesh.isSolid())

    def test_sphere_volume_within_tolerance(self):
        radius, tolerance = 10.0, 0.01
        mesh = NurbsLOD.to_mesh(Part.makeSphere(radius), tolerance=tolerance)
        volume = 4.0 / 3.0 * 3.141592653589793
        self.assertGreater(mesh.Volume, volume * (radius - tolerance) ** 3)
        self.assertLess(mesh.Volume, volume * (radius + tolerance) ** 3)

    def test_bad_tolerance_raises_value_error(self):
        with self.assertRaises(ValueError):
            NurbsLOD.to_mesh(Part.makeBox(1, 1, 1), tolerance=float("nan"))


class ExportCommand(TempDirTestCase):
    """The work behind the workbench command "Export certified mesh"."""

    def test_selected_objects_become_one_file(self):
        doc = FreeCAD.newDocument("NurbsLODExportCommand")
        self.addCleanup(FreeCAD.closeDocument, doc.Name)
        box = doc.addObject("Part::Box", "Box")
        sphere = doc.addObject("Part::Sphere", "Sphere")
        sketchless = doc.addObject("App::DocumentObjectGroup", "Group")
        doc.recompute()
        path = self.path("selection.obj")
        summary = NurbsLODExportCommand.export_objects([box, sketchless, sphere], path)
        self.assertEqual(summary["faces"], len(box.Shape.Faces) + len(sphere.Shape.Faces))
        self.assertEqual(Mesh.Mesh(path).CountFacets, summary["triangles"])
        self.assertIn("triangles", NurbsLODExportCommand.describe(summary))

    def test_progress_reaches_every_face_of_both_stages(self):
        doc = FreeCAD.newDocument("NurbsLODExportProgress")
        self.addCleanup(FreeCAD.closeDocument, doc.Name)
        box = doc.addObject("Part::Box", "Box")
        doc.recompute()
        calls = []
        summary = NurbsLODExportCommand.export_objects(
            [box], self.path("box.obj"), progress=lambda *call: calls.append(call))
        faces = summary["faces"]
        # each stage ends with all faces done, even one faster than the reports
        self.assertEqual(calls[-1], ("tessellate", faces, faces))
        self.assertIn(("import", faces, faces), calls)
        stages = [stage for stage, _, _ in calls]
        self.assertEqual(stages, sorted(stages, key=["import", "tessellate"].index))
        for stage, done, total in calls:
            self.assertEqual(total, faces)
            self.assertLessEqual(done, total)
        values = [NurbsLODExportCommand.progress_value(*call) for call in calls]
        self.assertEqual(values, sorted(values))
        self.assertEqual(values[-1], 2 * faces)
        self.assertEqual(NurbsLODExportCommand.progress_text("import", 3, 6),
                         "Importing faces: 3 of 6")

    def test_preferences_set_the_tolerance_and_mode(self):
        group = FreeCAD.ParamGet(NurbsLODExportCommand.PARAMETER_PATH)
        self.addCleanup(group.RemFloat, "ExportRelative")
        self.addCleanup(group.RemInt, "ExportMode")
        self.assertEqual(NurbsLODExportCommand.export_settings(), (1e-3, "guaranteed"))
        group.SetFloat("ExportRelative", 1e-2)
        group.SetInt("ExportMode", 1)
        self.assertEqual(NurbsLODExportCommand.export_settings(), (1e-2, "approximate"))
        doc = FreeCAD.newDocument("NurbsLODExportPreferences")
        self.addCleanup(FreeCAD.closeDocument, doc.Name)
        sphere = doc.addObject("Part::Sphere", "Sphere")
        doc.recompute()
        summary = NurbsLODExportCommand.export_objects([sphere], self.path("sphere.obj"))
        self.assertEqual(summary["mode"], "approximate")
        self.assertAlmostEqual(summary["tolerance"], 1e-2 * sphere.Shape.BoundBox.DiagonalLength,
                               delta=1e-3 * summary["tolerance"])
        # values the page cannot hold fall back to the defaults
        group.SetFloat("ExportRelative", -1.0)
        group.SetInt("ExportMode", 7)
        self.assertEqual(NurbsLODExportCommand.export_settings(), (1e-3, "guaranteed"))

    def test_nothing_with_a_shape_raises_value_error(self):
        with self.assertRaisesRegex(ValueError, "select"):
            NurbsLODExportCommand.export_objects([], self.path("nothing.obj"))
