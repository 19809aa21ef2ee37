"""NurbsLODGui: the macro API of the NurbsLOD workbench's display side.

    import NurbsLODGui
    NurbsLODGui.enable_adaptive_display(obj, pixel_error=0.5, normal_error_deg=1.0)
    NurbsLODGui.stats(obj)        # what the last frame drew
    NurbsLODGui.set_overlay(obj, "zebra", stripes=12)
    NurbsLODGui.move_pole(obj, face_index, i, j, FreeCAD.Vector(...))
    NurbsLODGui.disable_adaptive_display(obj)

Adaptive display puts an SoNurbsLODShape node (Gui/, module NurbsLODCoin) into the object's
view provider, next to FreeCAD's face set. The face set stays in the scene graph under an
invisible draw style: Coin still ray-picks it, so FreeCAD's pre-selection and selection of
faces ("Face3") work as before, but it is not drawn. Faces that the tessellator cannot
handle are drawn from FreeCAD's own mesh of them instead, and the report view says which and
why.
"""

import math

import FreeCAD

from NurbsLODPaths import PARAMETER_PATH

# The defaults of the preferences page (Resources/ui/NurbsLODPreferences.ui); a macro's
# arguments override them.
DEFAULT_PIXEL_ERROR = 0.5
DEFAULT_FRAME_BUDGET_MS = 20.0
# Largest angle between the drawn normals (the exact ones at the vertices, interpolated across
# each triangle) and the exact normals (appearance-preserving tessellation, paper appearance
# section 4.1); 0 turns the bound off.
DEFAULT_NORMAL_ERROR_DEG = 1.0

try:
    from NurbsLODOverlays import set_overlay, wait_for_overlay  # noqa: F401 (re-exported)
except ImportError as _overlay_import_error:
    _OVERLAY_ERROR = str(_overlay_import_error)

    def set_overlay(obj, kind, wait=True, **options):
        """Analysis overlays (isophotes, zebra, curvature) are not installed."""
        raise RuntimeError(
            "NurbsLOD: the overlays module NurbsLODOverlays cannot be imported ({}); "
            "set_overlay is not available".format(_OVERLAY_ERROR)
        )

    def wait_for_overlay(obj, timeout=None):
        return None


def parameters():
    """The workbench's parameter group (the preferences page writes it)."""
    return FreeCAD.ParamGet(PARAMETER_PATH)


def default_pixel_error():
    value = parameters().GetFloat("PixelError", DEFAULT_PIXEL_ERROR)
    return value if math.isfinite(value) and value > 0 else DEFAULT_PIXEL_ERROR


def default_frame_budget_ms():
    value = parameters().GetFloat("FrameBudgetMs", DEFAULT_FRAME_BUDGET_MS)
    return value if math.isfinite(value) and value > 0 else DEFAULT_FRAME_BUDGET_MS


def default_normal_error_deg():
    value = parameters().GetFloat("NormalErrorDeg", DEFAULT_NORMAL_ERROR_DEG)
    return value if math.isfinite(value) and 0 <= value < 90 else DEFAULT_NORMAL_ERROR_DEG


def _normal_error(value):
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(
            "NurbsLOD: normal_error_deg must be a number, got {!r}".format(value)
        ) from None
    if not (math.isfinite(number) and 0 <= number < 90):
        raise ValueError(
            "NurbsLOD: normal_error_deg must be in [0, 90) degrees (0: off), got {!r}".format(
                value
            )
        )
    return number


def _positive(value, name):
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError("NurbsLOD: {} must be a number, got {!r}".format(name, value)) from None
    if not (math.isfinite(number) and number > 0):
        raise ValueError(
            "NurbsLOD: {} must be a positive finite number, got {!r}".format(name, value)
        )
    return number


def _key(obj):
    return (obj.Document.Name, obj.Name)


class AdaptiveDisplay:
    """The nodes that adaptive display added to one object's view provider."""

    def __init__(self, obj, node, groups):
        self.obj = obj
        self.node = node
        # [(group, [nodes inserted])]; the groups are held (ref) so that removing works even
        # after FreeCAD dropped the view provider's scene graph (a closed document)
        self.groups = groups
        for group, _ in groups:
            group.ref()
        self.failures = []
        self.edges = None

    def remove(self):
        for group, inserted in self.groups:
            for child in inserted:
                index = group.findChild(child)
                if index >= 0:
                    group.removeChild(index)
            group.unref()
        self.groups = []
        if self.node is not None:
            self.node.unref()  # the reference enable_adaptive_display took
            self.node = None
        if self.edges is not None:
            self.edges.unref()
            self.edges = None


_displays = {}


def _coin():
    from pivy import coin

    import NurbsLODCoin  # registers SoNurbsLODShape

    return coin, NurbsLODCoin


def _face_set_groups(view_object, type_name="SoBrepFaceSet"):
    """(group, index of the node) for every group that holds FreeCAD's face set (or another
    node type of its view provider, such as its edge set SoBrepEdgeSet)."""
    coin, _ = _coin()
    search = coin.SoSearchAction()
    search.setType(coin.SoType.fromName(coin.SbName(type_name)))
    search.setInterest(coin.SoSearchAction.ALL)
    search.setSearchingAll(True)
    search.apply(view_object.RootNode)
    found = []
    seen = set()
    for k in range(search.getPaths().getLength()):
        path = search.getPaths()[k]
        group = path.getNodeFromTail(1)
        address = int(group.this)
        if address in seen:  # the shaded and flat-lines modes share one group
            continue
        seen.add(address)
        found.append((group, path.getIndexFromTail(0)))
    return found


def local_shape(obj):
    """obj's shape without its placement: the coordinates the view provider's nodes live in
    (its transform node applies obj.Placement to them)."""
    try:
        shape = obj.Shape.copy(False)  # shares the geometry
    except TypeError:
        shape = obj.Shape.copy()
    shape.Placement = FreeCAD.Placement()
    return shape


def _fallback_node(obj, failures):
    """FreeCAD's own mesh of the faces the tessellator could not handle, not pickable (the
    face set still answers picks for them)."""
    coin, _ = _coin()
    points = []
    indices = []
    shape = local_shape(obj)
    diagonal = shape.BoundBox.DiagonalLength
    import NurbsLOD

    # the least diagonal the tessellator takes (ten times OpenCASCADE's confusion distance): a
    # smaller shape gets no fallback mesh either
    if not diagonal >= NurbsLOD.SMALLEST_MODEL:
        # OpenCASCADE's mesher ran for ever on a sphere of radius 5e-8 (FreeCAD's own display
        # refuses it): the GUI thread must not wait for it
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: {}: the shape is only {:.3g} across, below what OpenCASCADE can mesh: "
            "it is not drawn\n".format(obj.Label, diagonal)
        )
        return None
    deviation = diagonal * 1e-3
    for failure in failures:
        face = shape.Faces[failure["face"] - 1]
        try:
            vertices, triangles = face.tessellate(deviation)
        except Exception as error:  # the face shows nothing, but say so
            FreeCAD.Console.PrintWarning(
                "NurbsLOD: {}: FreeCAD cannot mesh face {} either: {}\n".format(
                    obj.Label, failure["face"], error
                )
            )
            continue
        if not triangles:
            # OpenCASCADE's mesher, which FreeCAD's own display uses, leaves some faces of
            # sloppy files empty: FreeCAD showed nothing there either
            FreeCAD.Console.PrintWarning(
                "NurbsLOD: {}: FreeCAD's own mesh of face {} is empty too: it is not "
                "drawn\n".format(obj.Label, failure["face"])
            )
            continue
        base = len(points)
        points.extend((v.x, v.y, v.z) for v in vertices)
        for a, b, c in triangles:
            indices.extend((base + a, base + b, base + c, -1))
    if not indices:
        return None
    separator = coin.SoSeparator()
    pick_style = coin.SoPickStyle()
    pick_style.style = coin.SoPickStyle.UNPICKABLE
    coordinates = coin.SoCoordinate3()
    coordinates.point.setValues(0, len(points), points)
    faces = coin.SoIndexedFaceSet()
    faces.coordIndex.setValues(0, len(indices), indices)
    for child in (pick_style, coordinates, faces):
        separator.addChild(child)
    return separator


def report_failures(obj, failures):
    for failure in failures:
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: {}: face {} keeps FreeCAD's display: {}\n".format(
                obj.Label, failure["face"], failure["reason"]
            )
        )


def enable_adaptive_display(
    obj, pixel_error=None, frame_budget_ms=None, wait=True, normal_error_deg=None
):
    """Draws obj's faces view-dependently: each face within pixel_error pixels on screen and
    its normals within normal_error_deg degrees of the exact ones (0: no normal bound).

    pixel_error, frame_budget_ms and normal_error_deg default to the preferences (0.5 px,
    20 ms, 1 degree). With wait
    (the default) the model is imported here and the summary of the import is returned:
    {faces, faces_failed: [{face, reason}], seconds}. With wait=False the import runs in a
    thread while FreeCAD keeps drawing the object, the swap happens when it is done (see
    is_pending) and None is returned. Raises ValueError for an object without faces or a bad
    argument; the object then keeps FreeCAD's display.
    """
    if pixel_error is None:
        pixel_error = default_pixel_error()
    if frame_budget_ms is None:
        frame_budget_ms = default_frame_budget_ms()
    if normal_error_deg is None:
        normal_error_deg = default_normal_error_deg()
    pixel_error = _positive(pixel_error, "pixel_error")
    frame_budget_ms = _positive(frame_budget_ms, "frame_budget_ms")
    options = (pixel_error, frame_budget_ms, _normal_error(normal_error_deg))
    if not hasattr(obj, "Shape") or obj.Shape.isNull() or not obj.Shape.Faces:
        raise ValueError("NurbsLOD: {} has no faces to display".format(getattr(obj, "Label", obj)))
    if obj.ViewObject is None:
        raise RuntimeError("NurbsLOD: adaptive display needs the FreeCAD GUI")
    if not _face_set_groups(obj.ViewObject):
        raise RuntimeError("NurbsLOD: {} has no face set in its view provider".format(obj.Label))
    _, NurbsLODCoin = _coin()
    brep = local_shape(obj).exportBrepToString()
    if wait:
        _pending.pop(_key(obj), None)
        return _install(obj, NurbsLODCoin.prepare(brep), *options)
    _prepare_in_thread(obj, brep, options)
    return None


# Imports running in threads: key -> Preparation. The GUI thread polls them with a timer and
# installs what is ready; a newer request for the same object replaces an older one.
_pending = {}
_poll_timer = None


class _Preparation:
    def __init__(self, obj, brep, options):
        import threading

        self.obj = obj
        self.label = obj.Label
        self.options = options  # (pixel_error, frame_budget_ms, normal_error_deg)
        self.prepared = None
        self.error = None
        self.thread = threading.Thread(target=self._run, args=(brep,), daemon=True)

    def _run(self, brep):
        _, NurbsLODCoin = _coin()
        try:
            self.prepared = NurbsLODCoin.prepare(brep)  # C++ without the GIL
        except Exception as error:
            self.error = error


def _prepare_in_thread(obj, brep, options):
    global _poll_timer
    from PySide import QtCore

    preparation = _Preparation(obj, brep, options)
    _pending[_key(obj)] = preparation
    FreeCAD.Console.PrintMessage("NurbsLOD: {}: preparing adaptive display...\n".format(obj.Label))
    preparation.thread.start()
    if _poll_timer is None:
        _poll_timer = QtCore.QTimer()
        _poll_timer.setInterval(50)
        _poll_timer.timeout.connect(_poll_preparations)
    if not _poll_timer.isActive():
        _poll_timer.start()


def _poll_preparations():
    for key, preparation in list(_pending.items()):
        if preparation.thread.is_alive():
            continue
        if _pending.get(key) is preparation:
            del _pending[key]
        try:
            if preparation.error is not None:
                raise preparation.error
            _install(preparation.obj, preparation.prepared, *preparation.options)
        except Exception as error:  # a timer must not raise into FreeCAD
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: adaptive display not enabled, FreeCAD's display kept: {}\n".format(
                    preparation.label, error
                )
            )
    if not _pending and _poll_timer is not None:
        _poll_timer.stop()


def is_pending(obj):
    """True while obj's model is being prepared in a thread (enable with wait=False)."""
    return _key(obj) in _pending


def wait_until_ready(obj, seconds=60.0):
    """Processes GUI events until obj's threaded preparation is installed; returns
    is_enabled(obj)."""
    import time

    import FreeCADGui

    end = time.time() + seconds
    while is_pending(obj) and time.time() < end:
        FreeCADGui.updateGui()
        time.sleep(0.02)
    _poll_preparations()
    return is_enabled(obj)


def _install(obj, prepared, pixel_error, frame_budget_ms, normal_error_deg):
    """Puts the nodes of a prepared model into obj's view provider; returns the summary."""
    if obj.Document is None or getattr(obj, "ViewObject", None) is None:
        raise RuntimeError("the object was deleted")
    if _key(obj) in _displays:
        _disable(obj)  # a refresh: the new node replaces the old one
    coin, NurbsLODCoin = _coin()
    groups = _face_set_groups(obj.ViewObject)
    if not groups:
        raise RuntimeError("NurbsLOD: {} has no face set in its view provider".format(obj.Label))
    node = coin.SoType.fromName(coin.SbName("SoNurbsLODShape")).createInstance()
    # pivy does not own a node made by createInstance: hold it until disable, so that the
    # Python proxy never outlives it
    node.ref()
    node.pixelError = pixel_error
    node.frameBudget = frame_budget_ms
    node.normalError = normal_error_deg
    try:
        summary = NurbsLODCoin.install(node, prepared)
    except Exception:
        node.unref()
        raise
    fallback = _fallback_node(obj, summary["faces_failed"]) if summary["faces_failed"] else None
    inserted_groups = []
    for group, index in groups:
        hide = coin.SoDrawStyle()
        hide.style = coin.SoDrawStyle.INVISIBLE
        inserted = [node] + ([fallback] if fallback else []) + [hide]
        for offset, child in enumerate(inserted):
            group.insertChild(child, index + offset)
        inserted_groups.append((group, inserted))
    # FreeCAD's edges come from one fixed tessellation whose chords sink behind the exact
    # surface up close: the edges node draws the faces' borders at the view's level instead,
    # FreeCAD's edge set stays for picking. Faces left to FreeCAD keep its edges.
    edges = None
    edge_groups = _face_set_groups(obj.ViewObject, "SoBrepEdgeSet")
    if edge_groups and not summary["faces_failed"]:
        edges = coin.SoType.fromName(coin.SbName("SoNurbsLODEdges")).createInstance()
        edges.ref()
        edges.shape.setValue(node)
        for group, index in edge_groups:
            hide = coin.SoDrawStyle()
            hide.style = coin.SoDrawStyle.INVISIBLE
            group.insertChild(edges, index)
            group.insertChild(hide, index + 1)
            inserted_groups.append((group, [edges, hide]))
    display = AdaptiveDisplay(obj, node, inserted_groups)
    display.edges = edges
    display.failures = summary["faces_failed"]
    _displays[_key(obj)] = display
    _observe()
    _record(obj, True)
    _update_hidden_faces(obj.Document.Name, obj.Name)
    report_failures(obj, summary["faces_failed"])
    return summary


def disable_adaptive_display(obj):
    """Gives obj back FreeCAD's own display. Returns False when it was not enabled."""
    was_on = _disable(obj)
    _record(obj, False)
    return was_on


def _disable(obj):
    """disable_adaptive_display without changing the view property (the object goes away,
    or the property changed already)."""
    _pending.pop(_key(obj), None)  # a preparation still running is dropped when it ends
    display = _displays.pop(_key(obj), None)
    if display is None:
        return False
    display.remove()
    return True


def is_enabled(obj):
    return _key(obj) in _displays


def node_of(obj):
    """The SoNurbsLODShape of obj, or None."""
    display = _displays.get(_key(obj))
    return display.node if display else None


def _display_of(obj):
    display = _displays.get(_key(obj))
    if display is None:
        raise ValueError("NurbsLOD: adaptive display is not enabled for {}".format(obj.Label))
    return display


def stats(obj):
    """What obj's last frame drew: triangles, max_screen_error_px, max_normal_error_deg
    (measured on the drawn triangles: the largest angle between the normal interpolated across
    a triangle and the exact normal there), face_normal_error_deg (the same per face, 0: not
    drawn), faces_shading_limited (faces the normal bound made finer), faces_normal_error_over
    (drawn faces over the bound), normal_error_deg (the bound), last_frame_tessellation_ms,
    faces_visible, faces_culled, faces_failed, faces_waiting (drawn coarser than wanted while a
    worker makes the finer level), pending_jobs, background_tessellation_ms, frames."""
    _, NurbsLODCoin = _coin()
    return NurbsLODCoin.stats(_display_of(obj).node)


def refresh_in_background(obj):
    """Re-reads obj's shape in a thread (as enable_adaptive_display(wait=False) does) with
    the display's own pixel error, frame budget and normal bound; the old node keeps drawing
    the old shape until the new one replaces it (bottle: 3.5 s of import that the GUI thread
    would otherwise wait for)."""
    display = _displays.get(_key(obj))
    if display is not None and display.node is not None:
        node = display.node
        options = (
            node.pixelError.getValue(),
            node.frameBudget.getValue(),
            node.normalError.getValue(),
        )
    elif _key(obj) in _pending:
        options = _pending[_key(obj)].options
    else:
        raise ValueError("NurbsLOD: adaptive display is not enabled for {}".format(obj.Label))
    _prepare_in_thread(obj, local_shape(obj).exportBrepToString(), options)


def refresh(obj):
    """Re-reads obj's shape into its node (after a recompute changed it), at once."""
    display = _display_of(obj)
    _, NurbsLODCoin = _coin()
    summary = NurbsLODCoin.set_shape(display.node, local_shape(obj).exportBrepToString())
    report_failures(obj, summary["faces_failed"])
    return summary


# The view property that the command and undo go through; it also keeps the state in the
# saved document, so that adaptive display comes back when it is opened (NurbsLODRestore).
PROPERTY = "AdaptiveDisplay"


def _add_property(view, enabled):
    view.addProperty(
        "App::PropertyBool",
        PROPERTY,
        "NurbsLOD",
        "Draw every face within the screen-space error of the preferences",
    )
    setattr(view, PROPERTY, enabled)


def _record(obj, enabled):
    """Writes the state into obj's view property (the macro API does not go through it),
    unless it says so already."""
    view = getattr(obj, "ViewObject", None)
    if view is None:
        return
    try:
        if not hasattr(view, PROPERTY):
            if enabled:
                _add_property(view, True)
        elif bool(getattr(view, PROPERTY)) != enabled:
            setattr(view, PROPERTY, enabled)
    except Exception as error:  # remembering is a convenience: never fail the display for it
        FreeCAD.Console.PrintWarning(
            "NurbsLOD: {}: adaptive display is not kept in the document: {}\n".format(
                obj.Label, error
            )
        )


def set_adaptive_display(objects, enabled):
    """Turns adaptive display on or off for the objects in one undoable step per document:
    sets their view property AdaptiveDisplay in a transaction, and the change swaps the
    display (so Edit > Undo swaps back)."""
    _observe()
    objects = list(objects)
    documents = []
    for obj in objects:
        if obj.Document not in documents:
            documents.append(obj.Document)
    # The property is added outside the transaction: undoing its addition would remove it
    # without telling the observer, and the display would not swap back.
    for obj in objects:
        view = obj.ViewObject
        if not hasattr(view, PROPERTY):
            _add_property(view, is_enabled(obj))
    name = "Adaptive display {}".format("on" if enabled else "off")
    for document in documents:
        document.openTransaction(name)
    try:
        for obj in objects:
            setattr(obj.ViewObject, PROPERTY, bool(enabled))
    finally:
        for document in documents:
            document.commitTransaction()


class _ViewObserver:
    """Swaps the display when the view property changes: the command, undo, redo, the
    property editor."""

    def slotChangedObject(self, view, prop):
        if prop != PROPERTY:
            return
        obj = view.Object
        try:
            wanted = bool(getattr(view, PROPERTY))
            if wanted and not is_enabled(obj) and not is_pending(obj):
                # in a thread: a large model must not freeze the GUI while it is imported
                enable_adaptive_display(obj, wait=False)
            elif not wanted and (is_enabled(obj) or is_pending(obj)):
                _disable(obj)
        except Exception as error:  # an observer must not raise into FreeCAD
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: adaptive display not changed: {}\n".format(obj.Label, error)
            )


# Selection: FreeCAD's face set draws the selected and pre-selected faces highlighted, so the
# node leaves those faces to it (both drawn would fight in the depth buffer).
_preselection = None  # (document, object, subelement)


def _hidden_faces(document_name, object_name):
    import FreeCADGui

    display = _displays.get((document_name, object_name))
    count = len(display.obj.Shape.Faces)
    faces = set()
    names = []
    for selection in FreeCADGui.Selection.getSelectionEx(document_name):
        if selection.ObjectName != object_name:
            continue
        if not selection.SubElementNames:
            return list(range(1, count + 1))  # the whole object is highlighted
        names.extend(selection.SubElementNames)
    if _preselection and _preselection[:2] == (document_name, object_name):
        names.append(_preselection[2])
    for name in names:
        if name.startswith("Face") and name[4:].isdigit():
            faces.add(int(name[4:]))
    return sorted(faces)


def _update_hidden_faces(document_name, object_name):
    display = _displays.get((document_name, object_name))
    if display is None or display.node is None:
        return
    try:
        faces = _hidden_faces(document_name, object_name)
    except Exception as error:  # an observer must not raise into FreeCAD
        FreeCAD.Console.PrintWarning("NurbsLOD: selection update failed: {}\n".format(error))
        return
    hidden = display.node.hiddenFaces
    current = list(hidden.getValues()) if hidden.getNum() else []
    if current != faces:
        display.node.hiddenFaces.setNum(0)
        if faces:
            display.node.hiddenFaces.setValues(0, len(faces), faces)


def _update_document(document_name):
    for document, name in list(_displays):
        if document == document_name:
            _update_hidden_faces(document, name)


class _SelectionObserver:
    def addSelection(self, document, obj, sub, point):
        _update_hidden_faces(document, obj)

    def removeSelection(self, document, obj, sub):
        _update_hidden_faces(document, obj)

    def setSelection(self, document):
        _update_document(document)

    def clearSelection(self, document):
        _update_document(document)

    def setPreselection(self, document, obj, sub):
        global _preselection
        _preselection = (document, obj, sub)
        _update_hidden_faces(document, obj)

    def removePreselection(self, document, obj, sub):
        global _preselection
        _preselection = None
        _update_hidden_faces(document, obj)


class _DocumentObserver:
    """Forgets objects that go away and re-reads shapes that change."""

    def slotDeletedObject(self, obj):
        if _key(obj) in _displays or _key(obj) in _pending:
            _disable(obj)

    def slotDeletedDocument(self, document):
        for key in [key for key in _pending if key[0] == document.Name]:
            del _pending[key]  # its thread ends by itself, nothing is installed
        for key in [key for key in _displays if key[0] == document.Name]:
            _displays.pop(key).remove()

    def slotChangedObject(self, obj, prop):
        if prop != "Shape" or _editing:
            return
        if _key(obj) not in _displays and _key(obj) not in _pending:
            return
        try:
            if obj.Shape.isNull() or obj.Shape.countElement("Face") == 0:
                disable_adaptive_display(obj)
            else:
                # a recompute, undo or redo of a large part must not freeze the GUI
                refresh_in_background(obj)
        except Exception as error:
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: adaptive display off: {}\n".format(obj.Label, error)
            )
            disable_adaptive_display(obj)


_observers = []
_editing = False  # move_pole updates the node itself


def _observe():
    if _observers:
        return
    import FreeCADGui

    selection, document, view = _SelectionObserver(), _DocumentObserver(), _ViewObserver()
    FreeCADGui.Selection.addObserver(selection)
    FreeCAD.addDocumentObserver(document)
    FreeCADGui.addDocumentObserver(view)
    _observers.extend((selection, document, view))


# Control-point editing (paper out-of-core-lod, section 5): an edit changes one face's
# surface; only that face's LOD cache is dropped and only it is tessellated again.


def _finite_vector(vector):
    try:
        values = [float(vector[k]) for k in range(3)]
    except (TypeError, ValueError, IndexError):
        values = [float(getattr(vector, name, float("nan"))) for name in ("x", "y", "z")]
    if not all(math.isfinite(v) for v in values):
        raise ValueError(
            "NurbsLOD: the pole position must be three finite numbers, got {!r}".format(vector)
        )
    return FreeCAD.Vector(*values)


def _face_on_surface(face, surface):
    """face's boundary on a new surface of the same parameter domain."""
    import Part

    u0, u1, v0, v1 = face.ParameterRange
    su0, su1, sv0, sv1 = face.Surface.bounds()
    tolerance = 1e-9 * max(1.0, abs(su1 - su0), abs(sv1 - sv0))
    natural = len(face.Wires) == 1 and all(
        abs(a - b) <= tolerance for a, b in ((u0, su0), (u1, su1), (v0, sv0), (v1, sv1))
    )
    if natural:
        new_face = surface.toShape(u0, u1, v0, v1)
    else:
        # a trimmed face: its loops' curves in (u, v), put on the new surface
        def on_new_surface(wire):
            edges = []
            for edge in wire.OrderedEdges:
                curve2d, first, last = face.curveOnSurface(edge)
                edges.append(curve2d.toShape(surface, first, last))
            return Part.Wire(edges)

        outer = face.OuterWire
        holes = [wire for wire in face.Wires if not wire.isSame(outer)]
        new_face = Part.Face(surface, on_new_surface(outer))
        if holes:
            new_face.cutHoles([on_new_surface(wire) for wire in holes])
        new_face.validate()
        if not new_face.isValid():
            raise ValueError("NurbsLOD: the trimming loops do not fit the moved surface")
    if face.Orientation == "Reversed":
        new_face.reverse()
    return new_face


def move_pole(obj, face_index, i, j, vector):
    """Moves pole (i, j) (1-based, as Part.BSplineSurface counts) of face face_index
    (1-based, obj.Shape.Faces[face_index - 1]) to vector (document coordinates, as
    obj.Shape.Faces[face_index - 1].Surface.getPole(i, j) gives them), in one undoable
    transaction.

    With adaptive display on, only that face is tessellated again: at once at the coarsest
    level (paper out-of-core-lod 6.4), then by the workers at the level the view needs.
    Returns {"display_ms": time until the node holds the new face (None without adaptive
    display), "display": the node's {import_ms, tessellate_ms, total_ms, level, triangles},
    "total_ms": the whole edit including FreeCAD's own update}. Raises ValueError naming the
    face and the reason for anything that cannot be edited.
    """
    import time

    import Part

    start = time.perf_counter()
    if getattr(obj, "TypeId", None) != "Part::Feature":
        raise ValueError(
            "NurbsLOD: {} is a {}, not a plain Part::Feature: a recompute would undo the "
            "edit".format(
                getattr(obj, "Label", obj), getattr(obj, "TypeId", type(obj).__name__)
            )
        )
    # the edit happens without the placement (the nodes' coordinates), which the new shape
    # gets back at the end
    placement = obj.Placement
    shape = local_shape(obj)
    if not isinstance(face_index, int) or not 1 <= face_index <= len(shape.Faces):
        raise ValueError(
            "NurbsLOD: {} has faces 1 to {}, not {!r}".format(
                obj.Label, len(shape.Faces), face_index
            )
        )
    face = shape.Faces[face_index - 1]
    surface = face.Surface
    if not isinstance(surface, Part.BSplineSurface):
        raise ValueError(
            "NurbsLOD: {} face {} is a {}, not a B-spline surface: convert it first".format(
                obj.Label, face_index, type(surface).__name__
            )
        )
    if not (isinstance(i, int) and isinstance(j, int)) or not (
        1 <= i <= surface.NbUPoles and 1 <= j <= surface.NbVPoles
    ):
        raise ValueError(
            "NurbsLOD: {} face {} has poles (1..{}, 1..{}), not ({!r}, {!r})".format(
                obj.Label, face_index, surface.NbUPoles, surface.NbVPoles, i, j
            )
        )
    position = placement.inverse().multVec(_finite_vector(vector))
    new_surface = surface.copy()
    new_surface.setPole(i, j, position)
    new_face = _face_on_surface(face, new_surface)
    if len(shape.Faces) == 1 and shape.ShapeType == "Face":
        new_shape = new_face
    else:
        new_shape = shape.replaceShape([(face, new_face)])
    new_shape.Placement = placement

    global _editing
    node_update = None
    display = _displays.get(_key(obj))
    if display is not None:
        _, NurbsLODCoin = _coin()
        if surface.isUPeriodic() or surface.isVPeriodic():
            # the importer re-knots periodic surfaces: poles do not map one to one
            node_update = NurbsLODCoin.replace_face(
                display.node, face_index, new_face.exportBrepToString(), 0
            )
        else:
            node_update = NurbsLODCoin.move_pole(
                display.node, face_index, i, j, (position.x, position.y, position.z), 0
            )
    document = obj.Document
    document.openTransaction("Move pole")
    _editing = display is not None  # the node has the new face already
    try:
        obj.Shape = new_shape
    finally:
        _editing = False
        document.commitTransaction()
    return {
        "display_ms": node_update["total_ms"] if node_update else None,
        "display": node_update,
        "total_ms": (time.perf_counter() - start) * 1000.0,
    }


def face_bounds(obj, face_index):
    """The box of the mesh the node showed last for face face_index (1-based):
    ((xmin, ymin, zmin), (xmax, ymax, zmax)), or None."""
    _, NurbsLODCoin = _coin()
    return NurbsLODCoin.face_bounds(_display_of(obj).node, face_index)
