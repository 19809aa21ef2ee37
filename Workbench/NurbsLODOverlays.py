"""Surface-analysis overlays on Part objects: isophotes, reflection lines (zebra), curvature.

    set_overlay(obj, "zebra", count=16, width_ratio=0.5, direction=(0, 1, 0), lock="camera")
    set_overlay(obj, "isophotes", count=32, line_width=2, direction=(0.3, 0.5, 1), lock="camera")
    set_overlay(obj, "curvature", curvature="mean", range=None, percentiles=(2, 98), levels=10)
    set_overlay(obj, None)        # FreeCAD's own display again, exactly as it was
    set_overlay(obj, "zebra", wait=False); wait_for_overlay(obj)

The overlay's mesh is made in a worker thread (BackgroundWorker), so the GUI keeps drawing
while it is made: only the Coin nodes are built on the GUI thread. set_overlay waits by
default, processing GUI events meanwhile; commands and observers do not wait. The kind and
the options given are kept in the object's view properties Overlay and OverlayOptions, which
the document saves: NurbsLODRestore shows the overlay again when it is opened.

The overlay is a mesh of the object at a fine tolerance from NurbsLOD.analysis_mesh: every
vertex carries the exact surface normal and curvature, interpolated across the triangles, so
the stripes show the surface's continuity and not the mesh's facets (appearance.txt,
sections 5 and 6.3). GLSL shaders (Resources/shaders) draw it, attached through Coin's
shader nodes. It is inserted into the object's view provider as one more child of its
display-mode switch and shown instead of the shaded faces; the object's edges stay visible
and its faces stay pickable (drawn invisible), so selection keeps working.

Options common to every kind:
  relative / tolerance   fineness of the overlay mesh (fraction of the bounding box
                         diagonal, or absolute); default relative 2e-4
  lock                   "camera" (light or tubes fixed to the viewer) or "object" (they turn
                         with the object)
Isophotes: count (lines over the intensity range), line_width (pixels), direction (towards
  the light).
Zebra: count or stripes (black stripes around a full turn of the reflected direction), width_ratio
  (black fraction of each period), direction (axis of the light tubes).
Curvature: curvature ("gaussian", "mean", "minimum", "maximum"), range ((low, high) overrides
  the automatic range), percentiles (the automatic range: these percentiles of the vertex
  values), levels (contour lines; 0 for none), legend (draw the colour bar).

Defaults come from the parameter group User parameter:BaseApp/Preferences/Mod/NurbsLOD when
set there (see PREFERENCES), else from DEFAULTS.
"""

import math
import os

import FreeCAD

from NurbsLODPaths import PARAMETER_PATH

KINDS = ("isophotes", "zebra", "curvature")
CURVATURE_KINDS = {
    "gaussian": "gaussian",
    "mean": "mean",
    "minimum": "minimum",
    "min": "minimum",
    "maximum": "maximum",
    "max": "maximum",
}
CURVATURE_TITLES = {
    "gaussian": "Gaussian curvature",
    "mean": "Mean curvature",
    "minimum": "Minimum curvature",
    "maximum": "Maximum curvature",
}

DEFAULTS = {
    "common": {"relative": 2e-4, "tolerance": None},
    "isophotes": {"count": 32, "line_width": 2.0, "direction": (0.3, 0.5, 1.0), "lock": "camera"},
    "zebra": {"count": 16, "width_ratio": 0.5, "direction": (0.0, 1.0, 0.0), "lock": "camera"},
    "curvature": {
        "curvature": "mean",
        "range": None,
        "percentiles": (2.0, 98.0),
        "levels": 10,
        "legend": True,
    },
}

# The order of the curvature kinds in the preferences page's combo box, which stores the
# index (Gui::PrefComboBox).
CURVATURE_KIND_ORDER = ("gaussian", "mean", "minimum", "maximum")

# option -> (parameter name, type) in PARAMETER_PATH; a parameter that is set wins over
# DEFAULTS, an option given to set_overlay wins over both. The names of the preferences page
# (Resources/ui/NurbsLODPreferences.ui) where it has the option.
PREFERENCES = {
    "common": {"relative": ("OverlayRelativeTolerance", "Float")},
    "isophotes": {
        "count": ("IsophoteCount", "Int"),
        "line_width": ("IsophoteLineWidth", "Float"),
        "lock": ("IsophoteLock", "String"),
    },
    "zebra": {
        "count": ("ZebraStripeCount", "Int"),
        "width_ratio": ("ZebraWidthRatio", "Float"),
        "lock": ("ZebraLock", "String"),
    },
    "curvature": {
        "curvature": ("CurvatureKind", "Int"),  # index into CURVATURE_KIND_ORDER
        "levels": ("CurvatureLevels", "Int"),
    },
}

# Other names an option answers to: zebra stripes=12 is count=12.
ALIASES = {"zebra": {"stripes": "count"}, "isophotes": {"lines": "count"}}

SHADER_DIR = os.path.join(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Resources", "shaders"
)
FRAGMENT_SHADERS = {
    "isophotes": "isophotes.frag",
    "zebra": "zebra.frag",
    "curvature": "curvature.frag",
}
NODE_NAME = "NurbsLODOverlay"

# Blue (minimum) - cyan - green - yellow - red (maximum): the ramp of the map and its legend.
RAMP_STOPS = (
    (0.0, (0.0, 0.0, 1.0)),
    (0.25, (0.0, 1.0, 1.0)),
    (0.5, (0.0, 0.85, 0.0)),
    (0.75, (1.0, 1.0, 0.0)),
    (1.0, (1.0, 0.0, 0.0)),
)

# The overlays that are on or being made: (document name, object name) -> _Overlay
_overlays = {}
# Why the newest request of an object failed, for wait_for_overlay: key -> ValueError
_failures = {}


def ramp_color(t):
    """The curvature ramp's colour at t in [0, 1] (clamped), as an (r, g, b) tuple."""
    t = min(max(float(t), 0.0), 1.0)
    for (t0, c0), (t1, c1) in zip(RAMP_STOPS, RAMP_STOPS[1:]):
        if t <= t1:
            s = (t - t0) / (t1 - t0)
            return tuple(a + s * (b - a) for a, b in zip(c0, c1))
    return RAMP_STOPS[-1][1]


def options_for(kind, options):
    """The options set_overlay uses: DEFAULTS, overridden by the preferences that are set,
    overridden by `options`. Raises ValueError naming an option the kind does not have."""
    merged = dict(DEFAULTS["common"])
    merged.update(DEFAULTS[kind])
    try:
        group = FreeCAD.ParamGet(PARAMETER_PATH)
        set_names = {
            "Float": set(group.GetFloats()),
            "Int": set(group.GetInts()),
            "String": set(group.GetStrings()),
        }
        for section in ("common", kind):
            for option, (name, type_name) in PREFERENCES[section].items():
                if name in set_names[type_name]:
                    value = getattr(group, "Get" + type_name)(name)
                    if option == "curvature":
                        value = CURVATURE_KIND_ORDER[value % len(CURVATURE_KIND_ORDER)]
                    merged[option] = value
    except Exception as error:  # preferences are a convenience: never fail for them
        FreeCAD.Console.PrintWarning("NurbsLOD: overlay preferences not read: {}\n".format(error))
    aliases = ALIASES.get(kind, {})
    options = {aliases.get(name, name): value for name, value in options.items()}
    unknown = set(options) - set(merged)
    if unknown:
        raise ValueError(
            "NurbsLOD: set_overlay({!r}) has no option {}; it has {}".format(
                kind, ", ".join(sorted(unknown)), ", ".join(sorted(merged))
            )
        )
    merged.update(options)
    if "tolerance" in options and options["tolerance"] is not None and "relative" not in options:
        merged["relative"] = None
    return _validated(kind, merged)


def _positive(options, name, integer=False):
    value = options[name]
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError("NurbsLOD: {} must be a number, got {!r}".format(name, value)) from None
    if not (math.isfinite(number) and number > 0):
        raise ValueError("NurbsLOD: {} must be positive and finite, got {!r}".format(name, value))
    options[name] = int(round(number)) if integer else number


def _direction(options):
    value = options["direction"]
    try:
        x, y, z = (float(c) for c in value)
    except (TypeError, ValueError):
        raise ValueError(
            "NurbsLOD: direction must be three numbers, got {!r}".format(value)
        ) from None
    length = math.sqrt(x * x + y * y + z * z)
    if not (math.isfinite(length) and length > 0):
        raise ValueError("NurbsLOD: direction must be a non-zero vector, got {!r}".format(value))
    options["direction"] = (x / length, y / length, z / length)


def _validated(kind, options):
    if options.get("tolerance") is not None:
        _positive(options, "tolerance")
        options["relative"] = None
    else:
        _positive(options, "relative")
    if kind in ("isophotes", "zebra"):
        _positive(options, "count", integer=True)
        _direction(options)
        if options["lock"] not in ("camera", "object"):
            raise ValueError(
                'NurbsLOD: lock must be "camera" or "object", got {!r}'.format(options["lock"])
            )
    if kind == "isophotes":
        _positive(options, "line_width")
    if kind == "zebra":
        _positive(options, "width_ratio")
        if not options["width_ratio"] < 1:
            raise ValueError(
                "NurbsLOD: width_ratio must be in (0, 1), got {!r}".format(options["width_ratio"])
            )
    if kind == "curvature":
        name = str(options["curvature"]).lower()
        if name not in CURVATURE_KINDS:
            raise ValueError(
                "NurbsLOD: curvature must be one of {}, got {!r}".format(
                    ", ".join(sorted(set(CURVATURE_KINDS.values()))), options["curvature"]
                )
            )
        options["curvature"] = CURVATURE_KINDS[name]
        low, high = (float(p) for p in options["percentiles"])
        if not (0 <= low < high <= 100):
            raise ValueError(
                "NurbsLOD: percentiles must be 0 <= low < high <= 100, got {!r}".format(
                    options["percentiles"]
                )
            )
        options["percentiles"] = (low, high)
        if options["range"] is not None:
            low, high = (float(v) for v in options["range"])
            if not (math.isfinite(low) and math.isfinite(high) and low < high):
                raise ValueError(
                    "NurbsLOD: range must be (low, high) with low < high, got {!r}".format(
                        options["range"]
                    )
                )
            options["range"] = (low, high)
        levels = int(options["levels"])
        if levels < 0:
            raise ValueError("NurbsLOD: levels must be >= 0, got {!r}".format(options["levels"]))
        options["levels"] = levels
        options["legend"] = bool(options["legend"])
    return options


def curvature_range(values, percentiles=(2.0, 98.0), weights=None):
    """The automatic range of a curvature map: the given percentiles of the vertex values,
    weighted by `weights` (the area around each vertex: an adaptive mesh crowds its vertices
    where the surface bends, which would skew plain percentiles), widened to a non-empty
    interval (a plane or a cylinder's Gaussian curvature is constant)."""
    import numpy as np

    values = np.asarray(values, dtype=float)
    weights = np.ones_like(values) if weights is None else np.asarray(weights, dtype=float)
    keep = np.isfinite(values) & np.isfinite(weights) & (weights >= 0)
    values, weights = values[keep], weights[keep]
    if values.size == 0 or not weights.sum() > 0:
        return (-1.0, 1.0)
    order = np.argsort(values)
    values, cumulative = values[order], np.cumsum(weights[order])
    cumulative /= cumulative[-1]
    low, high = (
        float(values[min(np.searchsorted(cumulative, p / 100.0), values.size - 1)])
        for p in percentiles
    )
    if not high > low:
        pad = max(abs(low) * 1e-3, 1e-12)
        low, high = low - pad, high + pad
    return (low, high)


def vertex_areas(analysis):
    """A third of the area of the triangles around each vertex of an analysis mesh."""
    import numpy as np

    points, triangles = analysis["points"], analysis["triangles"].astype(np.int64)
    a, b, c = (points[triangles[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    areas = np.zeros(len(points))
    for k in range(3):
        np.add.at(areas, triangles[:, k], area / 3.0)
    return areas


def _view_provider_switch(obj):
    """The display-mode switch of the object's view provider (FreeCAD's ModeSwitch)."""
    from pivy import coin

    view = getattr(obj, "ViewObject", None)
    if view is None:
        raise ValueError(
            "NurbsLOD: {} has no view provider (run in the FreeCAD GUI)".format(obj.Name)
        )
    root = view.RootNode
    for i in range(root.getNumChildren()):
        child = root.getChild(i)
        if child.isOfType(coin.SoSwitch.getClassTypeId()):
            return root, child
    raise ValueError("NurbsLOD: {}'s view provider has no display-mode switch".format(obj.Name))


def _document_shape(obj):
    """The object's shape as the document holds it (not copied: FreeCAD hands it out
    read-only); ValueError when it has no faces."""
    shape = getattr(obj, "Shape", None)
    if shape is None or shape.isNull():
        raise ValueError("NurbsLOD: {} has no shape to analyse".format(obj.Name))
    if shape.countElement("Face") == 0:
        raise ValueError("NurbsLOD: {} has no faces to analyse".format(obj.Name))
    return shape


def _in_view_coordinates(shape, placement):
    """shape in the coordinates of the object's view provider, whose Transform node applies
    the object's placement: shape itself when both placements are the identity (an object
    that was never moved), else a copy (tens of milliseconds for a large part: call it in
    the worker)."""
    if placement is None:
        return shape
    local = placement.inverse().multiply(shape.Placement)
    if local.isIdentity() and shape.Placement.isIdentity():
        return shape
    copy = shape.copy()
    copy.Placement = local
    return copy


def _local_shape(obj):
    """The object's shape in the coordinates of its view provider."""
    return _in_view_coordinates(_document_shape(obj), getattr(obj, "Placement", None))


def _same_mesh_source(a, b):
    """Whether two (shape, tolerance, relative) keys ask for the same mesh: the same
    tolerances and the same document shape (OpenCASCADE's isSame: the same shared topology
    at the same place; every change of a document's shape makes a new one)."""
    return a is not None and b is not None and a[1:] == b[1:] and a[0].isSame(b[0])


def _contains_face_set(node):
    from pivy import coin

    search = coin.SoSearchAction()
    search.setType(coin.SoIndexedFaceSet.getClassTypeId())
    search.setInterest(coin.SoSearchAction.FIRST)
    search.apply(node)
    return search.getPath() is not None


def _analysis_mesh(shape, options):
    """The overlay's mesh of shape at the options' fineness (may run in a worker thread:
    analysis_mesh releases the GIL while it tessellates)."""
    import NurbsLOD

    if options.get("tolerance") is not None:
        return NurbsLOD.analysis_mesh(shape, tolerance=options["tolerance"])
    return NurbsLOD.analysis_mesh(shape, relative=options["relative"])


def _shown_range(analysis, options):
    """The values at the ends of a curvature map's colour ramp."""
    if options["range"] is not None:
        return options["range"]
    values = analysis[options["curvature"]]
    return curvature_range(values, options["percentiles"], vertex_areas(analysis))


class BackgroundWorker:
    """Runs jobs in a worker thread, one at a time, and hands their results to the GUI
    thread, so that the GUI goes on drawing while a mesh is made: a QTimer polls the thread
    every POLL_MS and calls deliver(result) or fail(error) there (Coin nodes are built on the
    GUI thread only). Jobs that come while one runs are coalesced: only the newest waits.
    With supersede, a newer job also drops the result of the one running (an overlay
    request: only the newest counts); without it that result is shown too (a drag: every
    step shown brings the stripes closer to the mouse)."""

    POLL_MS = 15

    def __init__(self, name, deliver, fail, supersede=False):
        from PySide import QtCore

        self.name = name
        self.deliver, self.fail = deliver, fail
        self.supersede = supersede
        self.pending = None
        self.thread = None
        self.outcome = None  # the running job's box: {"result": ...} or {"error": ...}
        self.superseded = False
        self.timer = QtCore.QTimer()
        self.timer.setInterval(self.POLL_MS)
        self.timer.timeout.connect(self._poll)

    def submit(self, job):
        """Asks for job() to run in the worker; returns at once."""
        self.pending = job
        if self.thread is None:
            self._start()
        elif self.supersede:
            self.superseded = True

    def busy(self):
        return self.thread is not None or self.pending is not None

    def _start(self):
        import threading

        job, self.pending = self.pending, None
        if job is None:
            self.timer.stop()
            return
        box = {}  # the thread's own: a dropped thread that ends late cannot touch a newer one

        def work():
            try:
                box["result"] = job()
            except Exception as error:  # reported on the GUI thread
                box["error"] = error

        self.outcome = box
        self.superseded = False
        self.thread = threading.Thread(target=work, name=self.name, daemon=True)
        self.thread.start()
        self.timer.start()

    def _poll(self):
        if self.thread is None:
            self.timer.stop()
            return
        if self.thread.is_alive():
            return
        box, dropped = self.outcome, self.superseded
        self.thread, self.outcome = None, None
        if not dropped:
            try:
                if "error" in box:
                    self.fail(box["error"])
                else:
                    self.deliver(box.get("result"))
            except Exception as error:  # a timer must not raise into FreeCAD
                FreeCAD.Console.PrintError("NurbsLOD: {}: {}\n".format(self.name, error))
        if self.pending is not None:
            self._start()
        else:
            self.timer.stop()

    def wait(self, seconds):
        """Processes GUI events until every job is done and delivered, at most seconds;
        True when idle. The GUI keeps drawing meanwhile: a script can wait without freezing
        it."""
        import time

        from PySide import QtGui

        end = time.monotonic() + seconds
        while self.busy():
            if time.monotonic() > end:
                return False
            QtGui.QApplication.processEvents()
            self._poll()
            if self.busy():
                time.sleep(0.005)
        return True

    def stop(self):
        """Drops what is pending and waits for a running job (its result is dropped)."""
        self.pending = None
        self.timer.stop()
        if self.thread is not None:
            self.thread.join()
        self.thread, self.outcome = None, None

    def abandon(self):
        """Drops what is pending and the running job's result without waiting for it (the
        object or its document went away: the job holds copies only and ends by itself)."""
        self.pending = None
        self.timer.stop()
        self.thread, self.outcome = None, None


class _Overlay:
    """One object's overlay: its nodes, the analysis mesh they show, and how to undo them."""

    def __init__(self, obj):
        self.document = obj.Document.Name
        self.name = obj.Name
        self.root, self.switch = _view_provider_switch(obj)
        self.saved_child = self.switch.whichChild.getValue()
        self.label = obj.Label
        self.analysis = None
        self.analysis_key = None
        # the document's mesh while a live edit shows another one (cancel goes back to it)
        self.document_analysis = None
        self.group = None
        self.kind = None  # what the nodes show
        self.options = None
        self.requested = None  # (kind, options) of the newest request, shown or not yet
        self.given = {}  # the options set_overlay was given for it
        self.result = None  # set_overlay's dict for what is shown
        self.error = None  # why the newest request failed
        self.worker = BackgroundWorker(
            "NurbsLOD overlay", self._mesh_ready, self._mesh_failed, supersede=True
        )

    # the mesh -----------------------------------------------------------------------------
    def request(self, obj, kind, options):
        """Shows kind with options: at once when the overlay has the mesh of the object's
        shape at that fineness already (another kind, other stripes), else when a worker
        thread has made it; until then the nodes show what they showed (an older overlay,
        or FreeCAD's own display). A newer request drops an older one still running."""
        # the GUI thread only takes the shape (shared, read-only) and its placement: copying
        # or exporting a large part takes tens of milliseconds, left to the worker
        shape = _document_shape(obj)
        placement = getattr(obj, "Placement", None)
        key = (shape, options.get("tolerance"), options.get("relative"))
        self.label = obj.Label
        self.requested = (kind, options)
        self.error = None
        cached = None
        if self.analysis is not None and _same_mesh_source(key, self.analysis_key):
            cached = self.analysis
        elif self.document_analysis is not None and _same_mesh_source(
            key, self.document_analysis[0]
        ):
            cached = self.document_analysis[1]  # a live edit cancelled: the document's face
        if cached is not None:
            self.worker.abandon()  # an older request's mesh is not wanted any more
            self.analysis, self.analysis_key = cached, key
            self.document_analysis = None
            self.apply(kind, options)
            return

        def job():  # in the worker: analysis_mesh releases the GIL while it tessellates
            analysis = _analysis_mesh(_in_view_coordinates(shape, placement), options)
            shown_range = None
            if kind == "curvature" and len(analysis["triangles"]):
                shown_range = _shown_range(analysis, options)
            return key, kind, options, analysis, shown_range

        self.worker.submit(job)

    def _mesh_ready(self, made):
        """The worker's mesh, on the GUI thread."""
        key, kind, options, analysis, shown_range = made
        if _overlays.get((self.document, self.name)) is not self:
            return  # removed meanwhile (set_overlay None, object or document gone)
        if len(analysis["triangles"]) == 0:
            failed = analysis["summary"]["faces_failed"]
            reasons = "; ".join("Face{}: {}".format(f["face"], f["reason"]) for f in failed)
            self._mesh_failed(
                ValueError(
                    "NurbsLOD: no face of {} could be tessellated{}".format(
                        self.label, ": " + reasons if reasons else ""
                    )
                )
            )
            return
        failed = analysis["summary"]["faces_failed"]
        if failed:
            FreeCAD.Console.PrintWarning(
                "NurbsLOD: the overlay of {} leaves out {} face(s): {}\n".format(
                    self.label,
                    len(failed),
                    "; ".join("Face{}: {}".format(f["face"], f["reason"]) for f in failed),
                )
            )
        self.analysis, self.analysis_key = analysis, key
        self.document_analysis = None
        self.apply(kind, options, shown_range)

    def _mesh_failed(self, error):
        """The newest request cannot be shown: the overlay goes, FreeCAD's display comes
        back (an overlay of an older shape would mislead), the report view says why unless
        a script waits for the answer (wait_for_overlay raises it)."""
        self.error = error if isinstance(error, ValueError) else ValueError(str(error))
        if _overlays.get((self.document, self.name)) is self:
            del _overlays[(self.document, self.name)]
            _failures[(self.document, self.name)] = self.error
        self.remove_nodes()
        if not self.waited_for:
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: no overlay: {}\n".format(self.label, self.error)
            )

    waited_for = False

    def apply(self, kind, options, shown_range=None):
        """Builds and shows the nodes of kind from the overlay's mesh (GUI thread)."""
        import time

        start = time.perf_counter()
        analysis = self.analysis
        options = dict(options)
        if kind == "curvature":
            options["shown_range"] = (
                shown_range if shown_range is not None else _shown_range(analysis, options)
            )
        self.show(self.build(kind, options))
        self.kind, self.options = kind, options
        result = {
            "kind": kind,
            "options": dict(options),
            "triangles": int(len(analysis["triangles"])),
            "vertices": int(len(analysis["points"])),
            "faces_failed": list(analysis["summary"]["faces_failed"]),
        }
        if kind == "curvature":
            result["range"] = options["shown_range"]
        # the GUI thread's share of the overlay (the nodes built and put in the switch)
        result["build_ms"] = 1000.0 * (time.perf_counter() - start)
        self.result = result

    def busy(self):
        return self.worker.busy()

    # the scene ----------------------------------------------------------------------------
    def build(self, kind, options):
        import numpy as np
        from pivy import coin

        analysis = self.analysis
        group = coin.SoSeparator()
        group.setName(NODE_NAME)

        # What the display mode showed besides its faces (edges, vertices), shared, and its
        # faces drawn invisible: they stay pickable, so selection works as before.
        mode = self.switch.getChild(self.saved_child) if self.saved_child >= 0 else None
        if mode is not None:
            faces = []
            if self._is_face_part(mode) or not mode.isOfType(coin.SoGroup.getClassTypeId()):
                faces.append(mode)  # "Shaded": the mode is the faces
            else:
                for i in range(mode.getNumChildren()):
                    child = mode.getChild(i)
                    if child.isOfType(coin.SoPolygonOffset.getClassTypeId()):
                        continue
                    if _contains_face_set(child):
                        faces.append(child)
                    else:
                        group.addChild(child)
            if faces:
                picking = coin.SoSeparator()
                style = coin.SoDrawStyle()
                style.style = coin.SoDrawStyle.INVISIBLE
                style.setOverride(True)
                picking.addChild(style)
                for face in faces:
                    picking.addChild(face)
                group.addChild(picking)

        surface = coin.SoSeparator()
        pick_style = coin.SoPickStyle()
        pick_style.style = coin.SoPickStyle.UNPICKABLE
        surface.addChild(pick_style)
        offset = coin.SoPolygonOffset()  # edges in front of the faces, as FreeCAD draws them
        surface.addChild(offset)
        hints = coin.SoShapeHints()
        hints.vertexOrdering = coin.SoShapeHints.UNKNOWN_ORDERING  # both sides are shaded
        surface.addChild(hints)
        surface.addChild(self._shader(kind, options))

        # numpy arrays go into the fields as they are: a list per vertex would cost the GUI
        # thread milliseconds per ten thousand vertices
        coordinates = coin.SoCoordinate3()
        points = np.ascontiguousarray(analysis["points"], dtype=np.float32)
        coordinates.point.setValues(0, len(points), points)
        surface.addChild(coordinates)
        normals = coin.SoNormal()
        vectors = np.ascontiguousarray(analysis["normals"], dtype=np.float32)
        normals.vector.setValues(0, len(vectors), vectors)
        surface.addChild(normals)
        binding = coin.SoNormalBinding()
        binding.value = coin.SoNormalBinding.PER_VERTEX_INDEXED
        surface.addChild(binding)
        if kind == "curvature":
            values = analysis[options["curvature"]]
            texture = coin.SoTexture2()  # the ramp; also makes Coin send the coordinates
            size = 256
            pixels = bytes(
                int(round(255 * c)) for i in range(size) for c in ramp_color(i / (size - 1))
            )
            texture.image.setValue(coin.SbVec2s(size, 1), 3, pixels)
            texture.wrapS = coin.SoTexture2.CLAMP
            texture.wrapT = coin.SoTexture2.CLAMP
            surface.addChild(texture)
            texture_coordinates = coin.SoTextureCoordinate2()
            along = np.empty((len(values), 2), dtype=np.float32)
            along[:, 0] = values
            along[:, 1] = 0.5
            texture_coordinates.point.setValues(0, len(along), along)
            surface.addChild(texture_coordinates)
            texture_binding = coin.SoTextureCoordinateBinding()
            texture_binding.value = coin.SoTextureCoordinateBinding.PER_VERTEX_INDEXED
            surface.addChild(texture_binding)
        face_set = coin.SoIndexedFaceSet()
        triangles = analysis["triangles"]
        index = np.full((len(triangles), 4), -1, dtype=np.int32)
        index[:, :3] = triangles
        index = index.ravel()
        face_set.coordIndex.setValues(0, len(index), index)
        surface.addChild(face_set)
        group.addChild(surface)

        if kind == "curvature" and options["legend"]:
            group.addChild(self._legend(options))
        return group

    def _is_face_part(self, node):
        """True when node is a display mode made of the faces alone (FreeCAD's "Shaded")."""
        from pivy import coin

        if not node.isOfType(coin.SoGroup.getClassTypeId()):
            return False
        for i in range(node.getNumChildren()):
            if node.getChild(i).isOfType(coin.SoIndexedFaceSet.getClassTypeId()):
                return True
        return False

    def _shader(self, kind, options):
        from pivy import coin

        def source(name):
            with open(os.path.join(SHADER_DIR, name), encoding="utf-8") as f:
                return f.read()

        vertex = coin.SoVertexShader()
        vertex.sourceType = coin.SoShaderObject.GLSL_PROGRAM
        vertex.sourceProgram = source("surface_analysis.vert")
        fragment = coin.SoFragmentShader()
        fragment.sourceType = coin.SoShaderObject.GLSL_PROGRAM
        fragment.sourceProgram = source(FRAGMENT_SHADERS[kind])

        def parameter(node_type, name, value):
            node = node_type()
            node.name = name
            node.value = value
            fragment.parameter.set1Value(fragment.parameter.getNum(), node)

        if kind == "isophotes":
            direction = coin.SbVec3f(*options["direction"])
            parameter(coin.SoShaderParameter3f, "lightDirection", direction)
            parameter(coin.SoShaderParameter1i, "lockToObject", int(options["lock"] == "object"))
            parameter(coin.SoShaderParameter1f, "lineCount", float(options["count"]))
            parameter(coin.SoShaderParameter1f, "lineWidth", float(options["line_width"]))
            parameter(coin.SoShaderParameter3f, "surfaceColor", coin.SbVec3f(0.85, 0.85, 0.88))
            parameter(coin.SoShaderParameter3f, "lineColor", coin.SbVec3f(0.05, 0.05, 0.1))
        elif kind == "zebra":
            direction = coin.SbVec3f(*options["direction"])
            parameter(coin.SoShaderParameter3f, "tubeDirection", direction)
            parameter(coin.SoShaderParameter1i, "lockToObject", int(options["lock"] == "object"))
            parameter(coin.SoShaderParameter1f, "stripeCount", float(options["count"]))
            parameter(coin.SoShaderParameter1f, "widthRatio", float(options["width_ratio"]))
            parameter(coin.SoShaderParameter3f, "lightColor", coin.SbVec3f(1.0, 1.0, 1.0))
            parameter(coin.SoShaderParameter3f, "darkColor", coin.SbVec3f(0.0, 0.0, 0.0))
        else:
            low, high = options["shown_range"]
            parameter(coin.SoShaderParameter1f, "rangeMinimum", float(low))
            parameter(coin.SoShaderParameter1f, "rangeMaximum", float(high))
            parameter(coin.SoShaderParameter1f, "levelCount", float(options["levels"]))
            parameter(coin.SoShaderParameter1i, "ramp", 0)

        program = coin.SoShaderProgram()
        program.shaderObject.set1Value(0, vertex)
        program.shaderObject.set1Value(1, fragment)
        return program

    def _legend(self, options):
        """A colour bar with its values and title at the left of the view (a 2D overlay: an
        annotation with its own orthographic camera), left out of the bounding box."""
        from pivy import coin

        low, high = options["shown_range"]
        skip = coin.SoType.fromName(coin.SbName("SoSkipBoundingGroup"))
        legend = skip.createInstance() if not skip.isBad() else coin.SoSeparator()
        annotation = coin.SoAnnotation()
        legend.addChild(annotation)
        pick_style = coin.SoPickStyle()
        pick_style.style = coin.SoPickStyle.UNPICKABLE
        annotation.addChild(pick_style)
        camera = coin.SoOrthographicCamera()
        camera.viewportMapping = coin.SoCamera.LEAVE_ALONE  # x, y in [-1, 1] span the view
        camera.position = coin.SbVec3f(0, 0, 5)
        camera.height = 2
        camera.nearDistance = 1
        camera.farDistance = 10
        annotation.addChild(camera)
        light_model = coin.SoLightModel()
        light_model.model = coin.SoLightModel.BASE_COLOR
        annotation.addChild(light_model)

        # a light panel under the bar and the words keeps them readable on any background
        panel = coin.SoSeparator()
        panel_color = coin.SoBaseColor()
        panel_color.rgb = (0.93, 0.93, 0.93)
        panel.addChild(panel_color)
        panel_corners = coin.SoCoordinate3()
        panel_corners.point.setValues(
            0, 4, [(-0.97, -0.76, 0), (-0.50, -0.76, 0), (-0.50, 0.89, 0), (-0.97, 0.89, 0)]
        )
        panel.addChild(panel_corners)
        panel_face = coin.SoFaceSet()
        panel_face.numVertices.setValue(4)
        panel.addChild(panel_face)
        annotation.addChild(panel)

        steps = 32
        x0, x1, y0, y1 = -0.94, -0.90, -0.7, 0.7  # left: a view centres its object
        points, colors, index = [], [], []
        for i in range(steps + 1):
            y = y0 + (y1 - y0) * i / steps
            points += [(x0, y, 0), (x1, y, 0)]
            colors += [ramp_color(i / steps)] * 2
        for i in range(steps):
            a = 2 * i
            index += [a, a + 1, a + 3, a + 2, -1]
        bar = coin.SoSeparator()
        material = coin.SoMaterial()
        material.diffuseColor.setValues(0, len(colors), colors)
        bar.addChild(material)
        binding = coin.SoMaterialBinding()
        binding.value = coin.SoMaterialBinding.PER_VERTEX_INDEXED
        bar.addChild(binding)
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(points), points)
        bar.addChild(coordinates)
        faces = coin.SoIndexedFaceSet()
        faces.coordIndex.setValues(0, len(index), index)
        bar.addChild(faces)
        annotation.addChild(bar)

        text = coin.SoSeparator()
        color = coin.SoBaseColor()
        color.rgb = (0.0, 0.0, 0.0)
        text.addChild(color)
        font = coin.SoFont()
        font.size = 14
        text.addChild(font)
        ticks = 5
        for i in range(ticks):
            t = i / (ticks - 1)
            label = coin.SoSeparator()
            move = coin.SoTranslation()
            move.translation = (x1 + 0.01, y0 + (y1 - y0) * t - 0.01, 0)
            label.addChild(move)
            words = coin.SoText2()
            value = low + (high - low) * t
            if abs(value) < 1e-6 * (high - low):  # rounding noise of a zero
                value = 0.0
            words.string = "{:.4g}".format(value)
            label.addChild(words)
            text.addChild(label)
        title = coin.SoSeparator()
        move = coin.SoTranslation()
        move.translation = (x0, y1 + 0.11, 0)  # two lines above the bar
        title.addChild(move)
        words = coin.SoText2()
        unit = "1/mm^2" if options["curvature"] == "gaussian" else "1/mm"
        words.string.setValues(0, 2, [CURVATURE_TITLES[options["curvature"]], "[{}]".format(unit)])
        title.addChild(words)
        text.addChild(title)
        annotation.addChild(text)
        return legend

    def show(self, group):
        """Puts the overlay in the switch (replacing a previous one) and selects it."""
        self.remove_nodes()
        self.switch.addChild(group)
        self.group = group
        self.switch.whichChild = self.switch.getNumChildren() - 1

    def remove_nodes(self):
        if self.group is None:
            return
        index = self.switch.findChild(self.group)
        showing = index >= 0 and self.switch.whichChild.getValue() == index
        if index >= 0:
            self.switch.removeChild(index)
        if showing:
            self.switch.whichChild = self.saved_child
        self.group = None


def _key(obj):
    return (obj.Document.Name, obj.Name)


# Per-vertex arrays of an analysis mesh (NurbsLOD.analysis_mesh); triangles and face_ids are
# per triangle.
_VERTEX_ARRAYS = ("points", "normals", "parameters", "gaussian", "mean", "minimum", "maximum")


def _with_face_replaced(analysis, face_index, replacement):
    """The analysis mesh with face face_index's vertices and triangles replaced by those of
    `replacement` (the analysis mesh of the new face alone). Each vertex belongs to one face
    (analysis_mesh repeats a vertex per face), so the face's vertices are exactly those its
    triangles use."""
    import numpy as np

    triangles = analysis["triangles"].astype(np.int64)
    face_ids = analysis["face_ids"]
    mine = face_ids == face_index
    keep_vertex = np.ones(len(analysis["points"]), dtype=bool)
    keep_vertex[np.unique(triangles[mine])] = False
    renumber = np.cumsum(keep_vertex) - 1
    kept = len(np.flatnonzero(keep_vertex))
    result = {"summary": analysis["summary"]}
    for name in _VERTEX_ARRAYS:
        result[name] = np.concatenate([analysis[name][keep_vertex], replacement[name]])
    result["triangles"] = np.concatenate(
        [renumber[triangles[~mine]], replacement["triangles"].astype(np.int64) + kept]
    ).astype(analysis["triangles"].dtype)
    result["face_ids"] = np.concatenate(
        [face_ids[~mine], np.full(len(replacement["triangles"]), face_index, face_ids.dtype)]
    )
    return result


# A live move re-analyses its face at this many times the overlay's tolerance: the triangles
# go as 1 / tolerance, so about 16 times fewer (20 x 20 bicubic face: 41,548 -> ~2,600
# triangles, ~1.1 s -> ~60 ms). The normals stay exact at every vertex, so the stripes keep
# their shape; the full fineness comes back with the document's next shape change.
LIVE_COARSENING = 16.0


def _live_tolerance(obj, coarsening):
    overlay = _overlays.get(_key(obj))
    if overlay is None or overlay.analysis is None:
        return None
    return overlay.analysis["summary"]["tolerance"] * coarsening


def _analyse_face(face, tolerance):
    """The analysis mesh of one face (may run in a worker thread: analysis_mesh releases the
    GIL while it tessellates)."""
    import NurbsLOD

    replacement = NurbsLOD.analysis_mesh(face, tolerance=tolerance)
    failed = replacement["summary"]["faces_failed"]
    if failed:
        raise ValueError(failed[0]["reason"])
    return replacement


def _show_face(obj, face_index, replacement):
    """Splices a face's new analysis mesh into the object's overlay and redraws it (GUI
    thread). False when the overlay is gone meanwhile."""
    overlay = _overlays.get(_key(obj))
    if overlay is None or overlay.analysis is None:
        return False
    if overlay.analysis_key is not None:  # the document's mesh: kept for a cancel
        overlay.document_analysis = (overlay.analysis_key, overlay.analysis)
    overlay.analysis = _with_face_replaced(overlay.analysis, face_index, replacement)
    overlay.analysis_key = None  # no longer the document's shape
    overlay.show(overlay.build(overlay.kind, overlay.options))
    return True


def follow_face(obj, face_index, face, coarsening=LIVE_COARSENING):
    """Shows face face_index (1-based) of the object's overlay as `face` (a Part.Face in the
    shape's own coordinates) while the document keeps the old face, at once: a scripted pole
    move. Only that face is tessellated again, at `coarsening` times the overlay's tolerance;
    a curvature map keeps its colour range, so colours stay comparable during an edit.
    Returns the milliseconds it took, or None when the object shows no overlay. The
    document's next shape change (the edit written, undo) or refresh_overlay rebuilds the
    whole overlay from the document. A drag uses LiveFaceFollower instead."""
    import time

    tolerance = _live_tolerance(obj, coarsening)
    if tolerance is None:
        return None
    start = time.perf_counter()
    try:
        replacement = _analyse_face(face, tolerance)
    except ValueError as error:
        raise ValueError(
            "NurbsLOD: the overlay of {} keeps the old face {}: {}".format(
                obj.Label, face_index, error
            )
        )
    _show_face(obj, face_index, replacement)
    return 1000.0 * (time.perf_counter() - start)


class LiveFaceFollower:
    """Follows one face of an object's overlay during a drag without holding up the view: the
    face is analysed in a BackgroundWorker while the GUI goes on drawing (the node shows the
    new face at once), and the newest result is spliced in on the GUI thread. Moves that come
    while a worker runs are coalesced: only the last one is analysed next."""

    def __init__(self, obj, face_index, coarsening=LIVE_COARSENING):
        self.obj = obj
        self.face_index = face_index
        self.coarsening = coarsening
        self.shown = 0  # results spliced in so far
        self.worker = BackgroundWorker("NurbsLOD live overlay", self._show, self._report)

    def submit(self, face):
        """Asks for `face` to be shown; returns at once."""
        tolerance = _live_tolerance(self.obj, self.coarsening)
        if tolerance is None:
            return
        self.worker.submit(lambda: _analyse_face(face, tolerance))

    def busy(self):
        return self.worker.busy()

    def _show(self, replacement):
        if _show_face(self.obj, self.face_index, replacement):
            self.shown += 1

    def _report(self, error):
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: the overlay of {} keeps the old face {}: {}\n".format(
                self.obj.Label, self.face_index, error
            )
        )

    def stop(self):
        """Drops what is pending and waits for a running worker (its result is dropped)."""
        self.worker.stop()


# How long set_overlay(wait=True) and wait_for_overlay wait by default for the worker.
WAIT_SECONDS = 300.0


def set_overlay(obj, kind, wait=True, **options):
    """Shows an analysis overlay on the object instead of its shaded faces, or (kind None)
    removes it and restores FreeCAD's display exactly.

    kind: "isophotes", "zebra", "curvature" or None; options: see the module's help. The
    overlay's mesh is made in a worker thread (a second or more for a large part) while the
    GUI keeps drawing what it showed; only the Coin nodes are built on the GUI thread. A
    newer request for the object replaces an older one still running.

    wait=True (for scripts): processes GUI events until the overlay is shown and returns a
    dict: kind, the options used, triangles and vertices of the overlay mesh, faces_failed
    (faces left out, with the reason) and, for "curvature", range (the values at the ends of
    the colour ramp). wait=False (commands, observers): returns at once, {"kind", "options",
    "pending"}; wait_for_overlay gives the dict later. Raises ValueError for a bad kind,
    option or object, and (waiting) when no face can be analysed; without waiting the report
    view says why.
    """
    if kind is None:
        _failures.pop(_key(obj), None)
        overlay = _overlays.pop(_key(obj), None)
        if overlay is not None:
            overlay.worker.abandon()
            overlay.remove_nodes()
        _record(obj, None, None)
        return {"kind": None}
    if kind not in KINDS:
        raise ValueError(
            "NurbsLOD: kind must be one of {} or None, got {!r}".format(", ".join(KINDS), kind)
        )
    given = dict(options)
    options = options_for(kind, options)
    key = _key(obj)
    overlay = _overlays.get(key)
    if overlay is None:
        overlay = _Overlay(obj)
    _failures.pop(key, None)
    _overlays[key] = overlay
    _observe()
    try:
        overlay.given = given  # what a refresh asks for again (preferences may change)
        overlay.request(obj, kind, options)
    except Exception:
        if overlay.group is None and _overlays.get(key) is overlay:
            del _overlays[key]  # nothing shown: no overlay
        raise
    _record(obj, kind, given)
    if wait:
        return wait_for_overlay(obj)
    if overlay.busy():
        return {"kind": kind, "options": dict(options), "pending": True}
    return dict(overlay.result)


def wait_for_overlay(obj, timeout=WAIT_SECONDS):
    """Processes GUI events until the object's newest overlay request is shown; returns
    set_overlay's dict for it, or None when the object has no overlay. Raises ValueError
    when the request failed (the overlay is then removed) and TimeoutError after timeout
    seconds."""
    key = _key(obj)
    overlay = _overlays.get(key)
    if overlay is None:
        error = _failures.pop(key, None)
        if error is not None:
            raise error
        return None
    overlay.waited_for = True
    try:
        idle = overlay.worker.wait(timeout)
    finally:
        overlay.waited_for = False
    if not idle:
        raise TimeoutError(
            "NurbsLOD: the overlay of {} is not ready after {} s".format(obj.Label, timeout)
        )
    if overlay.error is not None:
        _failures.pop(key, None)
        raise overlay.error
    return dict(overlay.result) if overlay.result is not None else None


def overlay_pending(obj):
    """True while the object's overlay is being made in a worker thread."""
    overlay = _overlays.get(_key(obj))
    return overlay is not None and overlay.busy()


def overlay_of(obj):
    """The kind of overlay the object shows, or is about to show (see overlay_pending), or
    None."""
    overlay = _overlays.get(_key(obj))
    if overlay is None:
        return None
    return overlay.requested[0] if overlay.requested is not None else overlay.kind


def refresh_overlay(obj, wait=False):
    """Rebuilds the object's overlay from its current shape (after an edit), in a worker
    thread unless wait; a no-op when it has none. The old overlay stays on until the new
    one is ready. Returns set_overlay's dict, or None."""
    overlay = _overlays.get(_key(obj))
    if overlay is None or overlay.requested is None:
        return None
    return set_overlay(obj, overlay.requested[0], wait=wait, **overlay.given)


# The view properties that keep an object's overlay in its document, so that it comes back
# when the document is opened again (NurbsLODRestore): the kind ("" for none) and the options
# the user gave (JSON; the preferences fill in the rest when it comes back).
OVERLAY_PROPERTY = "Overlay"
OVERLAY_OPTIONS_PROPERTY = "OverlayOptions"


def _record(obj, kind, options):
    """Writes the overlay's kind and options into the object's view properties (added on
    first use, read-only in the property editor: set_overlay changes them)."""
    import json

    view = getattr(obj, "ViewObject", None)
    if view is None:
        return
    try:
        if not hasattr(view, OVERLAY_PROPERTY):
            if kind is None:
                return  # nothing to remember
            view.addProperty(
                "App::PropertyString", OVERLAY_PROPERTY, "NurbsLOD",
                "The analysis overlay shown: isophotes, zebra, curvature or empty",
            )
            view.addProperty(
                "App::PropertyString", OVERLAY_OPTIONS_PROPERTY, "NurbsLOD",
                "The options of the overlay (JSON)",
            )
            view.setEditorMode(OVERLAY_PROPERTY, 1)
            view.setEditorMode(OVERLAY_OPTIONS_PROPERTY, 1)
        text = json.dumps(options or {}, sort_keys=True)
        if getattr(view, OVERLAY_PROPERTY) != (kind or ""):
            setattr(view, OVERLAY_PROPERTY, kind or "")
        if getattr(view, OVERLAY_OPTIONS_PROPERTY) != text:
            setattr(view, OVERLAY_OPTIONS_PROPERTY, text)
    except Exception as error:  # remembering is a convenience: never fail the overlay for it
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: {}: the overlay is not kept in the document: {}\n".format(
                obj.Label, error
            )
        )


def recorded_overlay(obj):
    """(kind, options) that the object's view properties keep, or None."""
    import json

    view = getattr(obj, "ViewObject", None)
    kind = getattr(view, OVERLAY_PROPERTY, "") if view is not None else ""
    if kind not in KINDS:
        return None
    try:
        options = json.loads(getattr(view, OVERLAY_OPTIONS_PROPERTY, "") or "{}")
    except ValueError:
        options = {}
    return kind, options if isinstance(options, dict) else {}


def _forget(key):
    overlay = _overlays.pop(key, None)
    _failures.pop(key, None)
    if overlay is not None:
        overlay.worker.abandon()  # its worker ends by itself, its result is dropped
    return overlay


class _ShapeObserver:
    """Rebuilds an object's overlay when its shape changes, however it changed: move_pole, the
    pole editor, undo and redo, a recompute; forgets it when the object or its document goes."""

    def slotChangedObject(self, obj, prop):
        if prop != "Shape" or _key(obj) not in _overlays:
            return
        try:
            refresh_overlay(obj)
        except Exception as error:  # an observer must not raise into FreeCAD
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: overlay removed, the new shape cannot be analysed: {}\n".format(
                    obj.Label, error
                )
            )
            overlay = _forget(_key(obj))
            if overlay is not None:
                overlay.remove_nodes()

    def slotDeletedObject(self, obj):
        overlay = _forget(_key(obj))
        if overlay is not None:
            overlay.remove_nodes()

    def slotDeletedDocument(self, document):
        for key in [key for key in _overlays if key[0] == document.Name]:
            _forget(key)


_observers = []


def _observe():
    if not _observers:
        _observers.append(_ShapeObserver())
        FreeCAD.addDocumentObserver(_observers[0])


# Commands, for the workbench's menu and toolbar: each shows its overlay (with the defaults
# and preferences) on the selected Part objects; the last one removes any overlay.
COMMANDS = {
    "NurbsLOD_Isophotes": ("isophotes", "Isophotes", "Show isophotes of the exact surface"),
    "NurbsLOD_Zebra": ("zebra", "Reflection lines (zebra)", "Show reflection lines (zebra "
                       "stripes) of the exact surface: a kink where faces meet G1, not G2"),
    "NurbsLOD_CurvatureMap": ("curvature", "Curvature map", "Colour the surface by its "
                              "curvature (kind and range from the preferences), with a legend"),
    "NurbsLOD_OverlayOff": (None, "Remove overlay", "Show FreeCAD's own display again"),
}

ICONS = {
    "isophotes": "NurbsLODIsophotes.svg",
    "zebra": "NurbsLODZebra.svg",
    "curvature": "NurbsLODCurvature.svg",
    None: "NurbsLODOverlayOff.svg",
}


def _selected_objects():
    import FreeCADGui

    return [
        obj
        for obj in FreeCADGui.Selection.getSelection()
        if hasattr(obj, "Shape") and getattr(obj, "ViewObject", None) is not None
    ]


class OverlayCommand:
    def __init__(self, kind, menu_text, tool_tip):
        self.kind, self.menu_text, self.tool_tip = kind, menu_text, tool_tip

    def GetResources(self):
        import NurbsLODPaths

        return {
            "Pixmap": NurbsLODPaths.icon(ICONS[self.kind]),
            "MenuText": self.menu_text,
            "ToolTip": self.tool_tip,
        }

    def IsActive(self):
        objects = _selected_objects()
        if self.kind is None:
            return any(overlay_of(obj) is not None for obj in objects)
        return bool(objects)

    def Activated(self):
        # the meshes are made in worker threads: the view keeps drawing, each overlay comes
        # on when it is ready
        for obj in _selected_objects():
            try:  # a command must not raise: tell the user instead
                set_overlay(obj, self.kind, wait=False)
            except Exception as error:
                FreeCAD.Console.PrintError(
                    "NurbsLOD: no overlay on {}: {}\n".format(obj.Label, error)
                )


def register_commands():
    """Adds the overlay commands to FreeCAD (once); returns their names in menu order."""
    import FreeCADGui

    known = set(FreeCADGui.listCommands())
    for name, (kind, menu_text, tool_tip) in COMMANDS.items():
        if name not in known:
            FreeCADGui.addCommand(name, OverlayCommand(kind, menu_text, tool_tip))
    return list(COMMANDS)
