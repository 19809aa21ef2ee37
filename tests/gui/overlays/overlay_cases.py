"""The analysis overlays in the real FreeCAD GUI: zebra, isophotes and the curvature map on
two-patch surfaces that meet G1-not-G2 and G2, with screenshots, and assertions measured on
the screenshots.

Each test is a function of a Context (the document with the test surfaces, the view, the
screenshot folder). tests/gui/test_overlays.py turns them into unittest tests for
tests/gui/run_gui_tests.py. Raises unittest.SkipTest where the input is missing.
"""

import os
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
WIDTH, HEIGHT = 960, 600

# Limits of the kink measure (degrees), from the geometry: at the G1 joint the reflection
# lines turn by tens of degrees (60 measured), at the G2 joint they run on (a few degrees
# of fitting error remain; 0.2 for isophotes).
G1_KINK_AT_LEAST = 25.0
G2_KINK_AT_MOST = 10.0


class Context:
    def __init__(self, screenshot_dir):
        import FreeCAD
        import FreeCADGui

        import surfaces

        self.shots = screenshot_dir
        os.makedirs(screenshot_dir, exist_ok=True)
        self.doc = FreeCAD.newDocument("OverlayTest")
        self.objects = {}
        for continuity in ("G1", "G2"):
            obj = self.doc.addObject("Part::Feature", "Surface" + continuity)
            obj.Shape = surfaces.two_patch_face(continuity)
            self.objects[continuity] = obj
        self.doc.recompute()
        self.view = FreeCADGui.ActiveDocument.ActiveView
        self.view.setCameraType("Orthographic")
        self.plain = {}
        self.boxes = {}

    def show_only(self, continuity):
        for name, obj in self.objects.items():
            obj.ViewObject.Visibility = name == continuity
        self.view.viewTop()
        self.view.fitAll()

    def close(self):
        import FreeCAD

        import NurbsLODOverlays

        for obj in self.objects.values():
            NurbsLODOverlays.set_overlay(obj, None)
        FreeCAD.closeDocument(self.doc.Name)

    def shot(self, name):
        path = os.path.join(self.shots, name + ".png")
        self.view.saveImage(path, WIDTH, HEIGHT, "Current")
        return path


def measure_box(ctx, continuity):
    import image_measures

    if continuity not in ctx.boxes:
        ctx.show_only(continuity)
        path = ctx.shot("plain_" + continuity)
        ctx.plain[continuity] = path
        top, bottom, left, right = image_measures.object_box(image_measures.read_rgb(path))
        # the face's border edge and the rows right next to it are not stripes
        ctx.boxes[continuity] = ((top + 8, bottom - 8, left, right), (left + right) // 2)
    return ctx.boxes[continuity]


def kink_of(ctx, continuity, kind, **options):
    import image_measures
    import NurbsLODOverlays

    box, joint = measure_box(ctx, continuity)
    ctx.show_only(continuity)
    start = time.perf_counter()
    result = NurbsLODOverlays.set_overlay(ctx.objects[continuity], kind, **options)
    seconds = time.perf_counter() - start
    path = ctx.shot("{}_{}".format(kind, continuity))
    NurbsLODOverlays.set_overlay(ctx.objects[continuity], None)
    kink, left, right = image_measures.joint_kink(image_measures.read_rgb(path), box, joint)
    print(
        "  {} on {}: kink {:.1f} deg (edge direction {:.1f} left, {:.1f} right of the joint); "
        "{} triangles, overlay built in {:.2f} s".format(
            kind, continuity, kink, left, right, result["triangles"], seconds
        )
    )
    return kink


def test_zebra_kinks_at_g1_joint_and_not_at_g2_joint(ctx):
    options = dict(count=36, width_ratio=0.5, direction=(1, -1, 0), lock="camera")
    g1 = kink_of(ctx, "G1", "zebra", **options)
    g2 = kink_of(ctx, "G2", "zebra", **options)
    assert g1 >= G1_KINK_AT_LEAST, "no stripe kink at the G1 joint: {:.1f} deg".format(g1)
    assert g2 <= G2_KINK_AT_MOST, "a stripe kink at the G2 joint: {:.1f} deg".format(g2)


def test_isophotes_kink_at_g1_joint_and_not_at_g2_joint(ctx):
    options = dict(count=24, line_width=2.0, direction=(0.3, 0.5, 1.0), lock="camera")
    g1 = kink_of(ctx, "G1", "isophotes", **options)
    g2 = kink_of(ctx, "G2", "isophotes", **options)
    assert g1 >= G1_KINK_AT_LEAST, "no isophote kink at the G1 joint: {:.1f} deg".format(g1)
    assert g2 <= G2_KINK_AT_MOST, "an isophote kink at the G2 joint: {:.1f} deg".format(g2)


def test_curvature_map_jumps_at_g1_joint_only_and_draws_its_legend(ctx):
    import image_measures
    import NurbsLODOverlays

    jumps = {}
    for continuity in ("G1", "G2"):
        box, joint = measure_box(ctx, continuity)
        ctx.show_only(continuity)
        obj = ctx.objects[continuity]
        # contour lines would count as colour changes: measure on the map without them
        result = NurbsLODOverlays.set_overlay(obj, "curvature", curvature="mean", levels=0)
        path = ctx.shot("curvature_mean_" + continuity)
        NurbsLODOverlays.set_overlay(obj, "curvature", curvature="mean")
        ctx.shot("curvature_mean_levels_" + continuity)
        NurbsLODOverlays.set_overlay(obj, None)
        rgb = image_measures.read_rgb(path)
        jumps[continuity] = image_measures.color_jump(rgb, box, joint)
        low, high = result["range"]
        print(
            "  curvature (mean) on {}: range {:.4g} .. {:.4g} 1/mm, colour change across the "
            "joint {:.3f}, {:.1f} times the change beside it".format(
                continuity, low, high, *jumps[continuity]
            )
        )
        # the legend: a colour bar at the left, red at its top, blue at its bottom
        column = int(0.04 * WIDTH)  # x = -0.92 in the legend's [-1, 1] frame
        top_row, bottom_row = int(0.5 * (1 - 0.66) * HEIGHT), int(0.5 * (1 + 0.66) * HEIGHT)
        top, bottom = rgb[top_row, column], rgb[bottom_row, column]
        assert top[0] > 0.8 and top[2] < 0.3, "legend top is not red: {}".format(top)
        assert bottom[2] > 0.8 and bottom[0] < 0.3, "legend bottom is not blue: {}".format(bottom)
    # the mean curvature jumps by c/400 at the G1 joint; at the G2 joint it is continuous
    across, ratio = jumps["G1"]
    assert across > 0.5 and ratio > 3, "no colour jump at the G1 joint: {}".format(jumps["G1"])
    across, ratio = jumps["G2"]
    assert ratio < 1.5, "a colour jump at the G2 joint: {}".format(jumps["G2"])


def test_removing_the_overlay_restores_freecads_display_exactly(ctx):
    import numpy as np

    import image_measures
    import NurbsLODOverlays

    measure_box(ctx, "G1")
    ctx.show_only("G1")
    obj = ctx.objects["G1"]
    switch_before = NurbsLODOverlays._view_provider_switch(obj)[1]
    children_before = switch_before.getNumChildren()
    which_before = switch_before.whichChild.getValue()
    for kind in ("zebra", "isophotes", "curvature"):
        NurbsLODOverlays.set_overlay(obj, kind)
        assert NurbsLODOverlays.overlay_of(obj) == kind
    NurbsLODOverlays.set_overlay(obj, None)
    assert NurbsLODOverlays.overlay_of(obj) is None
    assert switch_before.getNumChildren() == children_before, "an overlay node was left behind"
    assert switch_before.whichChild.getValue() == which_before, "the display mode changed"
    after = image_measures.read_rgb(ctx.shot("restored_G1"))
    before = image_measures.read_rgb(ctx.plain["G1"])
    difference = float(np.abs(after - before).max())
    assert difference == 0.0, "the display differs after the overlay: {}".format(difference)


def test_bad_input_is_refused_with_a_message(ctx):
    import NurbsLODOverlays

    obj = ctx.objects["G1"]
    cases = [
        (("rainbow",), {}),
        (("zebra",), {"count": 0}),
        (("zebra",), {"width_ratio": 1.5}),
        (("zebra",), {"direction": (0, 0, 0)}),
        (("zebra",), {"lock": "world"}),
        (("isophotes",), {"line_width": float("nan")}),
        (("curvature",), {"curvature": "torsion"}),
        (("curvature",), {"range": (1.0, -1.0)}),
        (("curvature",), {"relative": -1}),
        (("zebra",), {"stripe_count": 3}),
    ]
    for args, options in cases:
        try:
            NurbsLODOverlays.set_overlay(obj, *args, **options)
        except ValueError as error:
            assert "NurbsLOD" in str(error), str(error)
        else:
            raise AssertionError("accepted {} {}".format(args, options))
    assert NurbsLODOverlays.overlay_of(obj) is None, "a refused call left an overlay"
    empty = ctx.doc.addObject("Part::Feature", "Empty")
    try:
        NurbsLODOverlays.set_overlay(empty, "zebra")
    except ValueError as error:
        assert "no shape" in str(error) or "no faces" in str(error), str(error)
    else:
        raise AssertionError("an object without a shape got an overlay")
    ctx.doc.removeObject(empty.Name)


def test_preferences_give_the_defaults(ctx):
    import FreeCAD

    import NurbsLODOverlays

    group = FreeCAD.ParamGet(NurbsLODOverlays.PARAMETER_PATH)
    # as the preferences page writes them: spin boxes, a double spin box, a combo box index
    group.SetInt("ZebraStripeCount", 7)
    group.SetFloat("ZebraWidthRatio", 0.3)
    group.SetInt("CurvatureKind", 0)
    try:
        zebra = NurbsLODOverlays.options_for("zebra", {})
        assert (zebra["count"], zebra["width_ratio"]) == (7, 0.3), zebra
        assert NurbsLODOverlays.options_for("zebra", {"count": 9})["count"] == 9
        assert NurbsLODOverlays.options_for("zebra", {"stripes": 11})["count"] == 11
        assert NurbsLODOverlays.options_for("curvature", {})["curvature"] == "gaussian"
    finally:
        group.RemInt("ZebraStripeCount")
        group.RemFloat("ZebraWidthRatio")
        group.RemInt("CurvatureKind")
    assert NurbsLODOverlays.options_for("zebra", {})["count"] == 16


def test_stripes_come_from_exact_normals_not_facets(ctx):
    """The zebra of a coarse overlay mesh (20 times the tolerance, far fewer triangles)
    matches the fine one: the stripes follow the exact normals interpolated per pixel. Facet
    normals would turn every stripe into a staircase of flat triangles."""
    import numpy as np

    import image_measures
    import NurbsLODOverlays

    box, _ = measure_box(ctx, "G2")
    top, bottom, left, right = box
    ctx.show_only("G2")
    obj = ctx.objects["G2"]
    images, triangles = {}, {}
    # fine and coarse 20 times apart: about 7000 and 400 triangles since full kd-tree cells
    # take the whole budget (1e-4 and 2e-3 gave as many before it, 2e-4 and 4e-3 before the
    # tighter guaranteed cell bound)
    fine, coarse = 7e-5, 1.4e-3
    for relative in (fine, coarse):
        options = dict(count=36, direction=(1, -1, 0), relative=relative)
        triangles[relative] = NurbsLODOverlays.set_overlay(obj, "zebra", **options)["triangles"]
        path = ctx.shot("zebra_G2_relative_{:g}".format(relative))
        images[relative] = image_measures.read_rgb(path)[top:bottom, left + 2 : right - 2]
    # The measure's counter-check: the coarse mesh shaded with its facet normals (the
    # overlay's own scene, fed flat normals) is what a mesh-based zebra would show.
    overlay = NurbsLODOverlays._overlays[(obj.Document.Name, obj.Name)]
    exact = overlay.analysis
    corners = exact["triangles"].astype(np.int64)
    points = exact["points"][corners.ravel()]
    a, b, c = (exact["points"][corners[:, k]] for k in range(3))
    facet = np.cross(b - a, c - a)
    facet /= np.linalg.norm(facet, axis=1)[:, None]
    overlay.analysis = dict(
        exact,
        points=points,
        normals=np.repeat(facet, 3, axis=0),
        triangles=np.arange(len(points), dtype=np.uint32).reshape(-1, 3),
    )
    options = NurbsLODOverlays.options_for("zebra", dict(count=36, direction=(1, -1, 0)))
    overlay.show(overlay.build("zebra", options))
    facets = image_measures.read_rgb(ctx.shot("zebra_G2_facet_normals"))
    facets = facets[top:bottom, left + 2 : right - 2]
    overlay.analysis = exact
    NurbsLODOverlays.set_overlay(obj, None)

    def differing(image):
        return float((np.abs(images[fine] - image).max(axis=2) > 0.5).mean())

    print(
        "  zebra on G2 with {} triangles vs {}: {:.2%} of the pixels differ with exact "
        "normals, {:.2%} with facet normals".format(
            triangles[coarse], triangles[fine], differing(images[coarse]), differing(facets)
        )
    )
    assert triangles[coarse] * 10 < triangles[fine], triangles
    assert differing(images[coarse]) < 0.03, "coarse and fine stripes differ too much"
    assert differing(facets) > 0.1, "the measure cannot tell facet normals from exact ones"


def test_light_locked_to_object_turns_with_it_and_to_camera_does_not(ctx):
    """Isophotes with the light along +z, once fixed to the object and once to the camera:
    from the top the two frames agree and so must the pictures; from the front the object's
    z is the camera's y, so the pictures must differ."""
    import numpy as np

    import image_measures
    import NurbsLODOverlays

    obj = ctx.objects["G1"]
    pictures = {}
    for view in ("top", "front"):
        ctx.show_only("G1")
        (ctx.view.viewTop if view == "top" else ctx.view.viewFront)()
        ctx.view.fitAll()
        for lock in ("object", "camera"):
            NurbsLODOverlays.set_overlay(obj, "isophotes", direction=(0, 0, 1), lock=lock)
            pictures[view, lock] = image_measures.read_rgb(
                ctx.shot("isophotes_G1_{}_light_{}".format(view, lock))
            )
    NurbsLODOverlays.set_overlay(obj, None)

    def differing(view):
        a, b = pictures[view, "object"], pictures[view, "camera"]
        return float((np.abs(a - b).max(axis=2) > 0.1).mean())

    print("  pixels that differ between object and camera light: {:.2%} from the top, {:.2%} "
          "from the front".format(differing("top"), differing("front")))
    assert differing("top") < 0.001, "the frames agree from the top, the pictures do not"
    assert differing("front") > 0.01, "turning the view did not move the camera's light"


def test_faces_stay_pickable_under_the_overlay(ctx):
    """The overlay itself is not pickable; FreeCAD's faces, drawn invisible, still are: a
    click in the middle of the view finds Face1 of the object, as without the overlay."""
    import NurbsLODOverlays

    ctx.show_only("G1")
    obj = ctx.objects["G1"]
    width, height = ctx.view.getSize()
    middle = (width // 2, height // 2)
    before = ctx.view.getObjectInfo(middle)
    NurbsLODOverlays.set_overlay(obj, "zebra")
    try:
        during = ctx.view.getObjectInfo(middle)
    finally:
        NurbsLODOverlays.set_overlay(obj, None)
    print("  picked without the overlay: {}; with it: {}".format(before, during))
    assert before and before.get("Object") == obj.Name, before
    assert during and during.get("Object") == obj.Name, during
    assert during.get("Component") == before.get("Component") == "Face1", during


def test_commands_show_and_remove_overlays_on_the_selection(ctx):
    import FreeCADGui

    import NurbsLODOverlays

    names = NurbsLODOverlays.register_commands()
    assert NurbsLODOverlays.register_commands() == names  # a second call adds nothing
    obj = ctx.objects["G2"]
    empty = ctx.doc.addObject("Part::Feature", "EmptyForCommand")
    ctx.show_only("G2")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    FreeCADGui.Selection.addSelection(empty)  # refused with a message, the other still done
    try:
        for name, kind in (("NurbsLOD_Zebra", "zebra"), ("NurbsLOD_CurvatureMap", "curvature"),
                           ("NurbsLOD_Isophotes", "isophotes"), ("NurbsLOD_OverlayOff", None)):
            FreeCADGui.runCommand(name)
            shown = NurbsLODOverlays.overlay_of(obj)
            assert shown == kind, (name, shown)
            assert NurbsLODOverlays.overlay_of(empty) is None
    finally:
        FreeCADGui.Selection.clearSelection()
        NurbsLODOverlays.set_overlay(obj, None)
        ctx.doc.removeObject(empty.Name)


def test_overlay_follows_the_placement_and_object_locked_tubes_turn_with_it(ctx):
    """The object moved and turned 90 degrees about z, tubes fixed to the object: from the
    top the zebra is the unmoved one turned by 90 degrees, pixel for pixel."""
    import FreeCAD
    import numpy as np

    import image_measures
    import NurbsLODOverlays

    box, _ = measure_box(ctx, "G1")
    top, bottom, left, right = box
    obj = ctx.objects["G1"]
    options = dict(count=36, direction=(1, -1, 0), lock="object")
    ctx.show_only("G1")
    NurbsLODOverlays.set_overlay(obj, "zebra", **options)
    unmoved = image_measures.read_rgb(ctx.shot("zebra_G1_object_tubes"))
    NurbsLODOverlays.set_overlay(obj, None)
    obj.Placement = FreeCAD.Placement(
        FreeCAD.Vector(100, 50, 7), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 90)
    )
    ctx.doc.recompute()
    try:
        ctx.show_only("G1")
        NurbsLODOverlays.set_overlay(obj, "zebra", **options)
        moved = image_measures.read_rgb(ctx.shot("zebra_G1_object_tubes_turned"))
    finally:
        NurbsLODOverlays.set_overlay(obj, None)
        obj.Placement = FreeCAD.Placement()
        ctx.doc.recompute()
    # inside the face's border; the square face turns onto itself
    window = (slice(top - 5, bottom + 6), slice(left + 3, right - 2))
    expected = np.rot90(unmoved[window], 1)
    shown = moved[window]
    assert expected.shape == shown.shape, (expected.shape, shown.shape)
    differing = float((np.abs(expected - shown).max(axis=2) > 0.5).mean())
    print("  turned object: {:.3%} of the pixels differ from the turned picture".format(
        differing))
    assert differing < 0.005, "the overlay does not follow the placement"


def test_every_overlay_on_a_corpus_model(ctx):
    import numpy as np
    import Part

    import image_measures
    import NurbsLODOverlays

    corpus = os.environ.get(
        "NURBSLOD_CORPUS_DIR", os.path.join(HERE, "..", "..", "..", "..", "shared", "corpus")
    )
    path = os.path.join(corpus, "bottle.brep")
    if not os.path.isfile(path):
        raise unittest.SkipTest("corpus model not found: " + path)
    shape = Part.Shape()
    shape.read(path)
    obj = ctx.doc.addObject("Part::Feature", "Bottle")
    obj.Shape = shape
    ctx.doc.recompute()
    for other in ctx.objects.values():
        other.ViewObject.Visibility = False
    ctx.view.viewIsometric()
    ctx.view.fitAll()
    plain = image_measures.read_rgb(ctx.shot("plain_bottle"))
    try:
        for kind, options in (
            ("zebra", {}),
            ("isophotes", {}),
            ("curvature", {"curvature": "mean"}),
        ):
            start = time.perf_counter()
            result = NurbsLODOverlays.set_overlay(obj, kind, **options)
            seconds = time.perf_counter() - start
            assert result["faces_failed"] == [], result["faces_failed"]
            shown = image_measures.read_rgb(ctx.shot("{}_bottle".format(kind)))
            changed = float((np.abs(shown - plain).max(axis=2) > 0.1).mean())
            print("  {} on bottle.brep: {} triangles in {:.2f} s, {:.0%} of the pixels "
                  "changed".format(kind, result["triangles"], seconds, changed))
            assert changed > 0.05, "the {} overlay changed almost nothing".format(kind)
    finally:
        NurbsLODOverlays.set_overlay(obj, None)
        ctx.doc.removeObject(obj.Name)


TESTS = [
    test_zebra_kinks_at_g1_joint_and_not_at_g2_joint,
    test_isophotes_kink_at_g1_joint_and_not_at_g2_joint,
    test_curvature_map_jumps_at_g1_joint_only_and_draws_its_legend,
    test_stripes_come_from_exact_normals_not_facets,
    test_light_locked_to_object_turns_with_it_and_to_camera_does_not,
    test_removing_the_overlay_restores_freecads_display_exactly,
    test_faces_stay_pickable_under_the_overlay,
    test_overlay_follows_the_placement_and_object_locked_tubes_turn_with_it,
    test_commands_show_and_remove_overlays_on_the_selection,
    test_bad_input_is_refused_with_a_message,
    test_preferences_give_the_defaults,
    test_every_overlay_on_a_corpus_model,
]
