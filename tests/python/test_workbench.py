"""The workbench as FreeCAD loads it: Init.py's paths, InitGui.py, Resources/."""

import os
import py_compile
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import NurbsLOD
import NurbsLODPaths
from nurbslod_testing import BUILD_DIR, ROOT

PACKAGE_XML = os.path.join(ROOT, "package.xml")
NS = {"p": "https://wiki.freecad.org/Package_Metadata"}


class InitPaths(unittest.TestCase):
    """scripts/test.sh installs the checkout as the only user workbench, so these hold only
    if FreeCAD's start-up ran this checkout's Init.py."""

    def test_module_comes_from_this_build(self):
        module_dir = os.path.realpath(os.path.join(BUILD_DIR, "App", "python"))
        self.assertEqual(os.path.dirname(os.path.realpath(NurbsLOD.__file__)), module_dir)
        self.assertEqual(os.path.realpath(NurbsLODPaths.MODULE_DIR), module_dir)

    def test_workbench_folder_is_this_checkout(self):
        self.assertEqual(os.path.realpath(NurbsLODPaths.ROOT), os.path.realpath(ROOT))
        self.assertIn(NurbsLODPaths.MODULE_DIR, sys.path)

    def test_module_api(self):
        for name in ("tessellate", "export", "to_mesh", "ReadError"):
            self.assertTrue(hasattr(NurbsLOD, name), name)
        self.assertIn("face_ids", NurbsLOD.tessellate.__doc__)


class Resources(unittest.TestCase):
    def test_init_files_compile(self):
        for name in ("Init.py", "InitGui.py"):
            with self.subTest(file=name):
                with tempfile.TemporaryDirectory() as tmp:
                    py_compile.compile(os.path.join(ROOT, name),
                                       cfile=os.path.join(tmp, name + "c"), doraise=True)

    def test_package_xml_names_the_workbench_and_existing_icons(self):
        package = ET.parse(PACKAGE_XML).getroot()
        self.assertEqual(package.find("p:name", NS).text, "NurbsLOD")
        workbench = package.find("p:content/p:workbench", NS)
        self.assertEqual(workbench.find("p:classname", NS).text, "NurbsLODWorkbench")
        with open(os.path.join(ROOT, "InitGui.py")) as init_gui:
            self.assertIn("class NurbsLODWorkbench(", init_gui.read())
        for icon in package.iter("{%s}icon" % NS["p"]):
            with self.subTest(icon=icon.text):
                self.assertTrue(os.path.isfile(os.path.join(ROOT, icon.text)))

    def test_icon_is_svg(self):
        svg = ET.parse(NurbsLODPaths.icon("NurbsLOD.svg")).getroot()
        self.assertEqual(svg.tag, "{http://www.w3.org/2000/svg}svg")
