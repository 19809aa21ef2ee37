"""Brings back, when a saved document is opened, the adaptive display and the analysis
overlays its objects were saved with.

The state lives in view properties the workbench owns (AdaptiveDisplay, Overlay,
OverlayOptions; NurbsLODGui and NurbsLODOverlays keep them up to date), which FreeCAD saves
with the document (GuiDocument.xml). InitGui.py installs the observer at start-up, so this
works whether or not the workbench was opened; the display modules are imported only when
a document holds such a property.

FreeCAD 0.20's Python document observer has no "document restored" signal: the observer
takes slotCreatedDocument, which comes before the file is read, and looks at the document
from the event loop, once openDocument has returned.
"""

import FreeCAD

ADAPTIVE_PROPERTY = "AdaptiveDisplay"  # NurbsLODGui.PROPERTY
OVERLAY_PROPERTY = "Overlay"  # NurbsLODOverlays.OVERLAY_PROPERTY


def _saved_state(obj):
    """(adaptive display on, overlay kind or "") that obj's view properties keep."""
    view = getattr(obj, "ViewObject", None)
    if view is None:
        return False, ""
    return bool(getattr(view, ADAPTIVE_PROPERTY, False)), getattr(view, OVERLAY_PROPERTY, "")


def restore(document_name):
    """Turns on what the document's objects were saved with: adaptive display (made in a
    thread) and overlays (meshes made in a worker), so a large document opens without a
    frozen GUI. Returns the names of the objects it restored something for. A failure is
    reported for its object and the others go on: the document itself is never harmed."""
    try:
        document = FreeCAD.getDocument(document_name)
    except NameError:  # closed meanwhile
        return []
    restored = []
    for obj in document.Objects:
        adaptive, overlay = _saved_state(obj)
        if not adaptive and not overlay:
            continue
        try:
            if adaptive:
                import NurbsLODGui

                if not NurbsLODGui.is_enabled(obj) and not NurbsLODGui.is_pending(obj):
                    NurbsLODGui.enable_adaptive_display(obj, wait=False)
            if overlay:
                import NurbsLODOverlays

                recorded = NurbsLODOverlays.recorded_overlay(obj)
                if recorded is not None and NurbsLODOverlays.overlay_of(obj) is None:
                    kind, options = recorded
                    NurbsLODOverlays.set_overlay(obj, kind, wait=False, **options)
            restored.append(obj.Name)
        except Exception as error:  # a document must open whatever its display state
            FreeCAD.Console.PrintError(
                "NurbsLOD: {}: the saved display is not restored: {}\n".format(obj.Label, error)
            )
    return restored


class _OpenObserver:
    def slotCreatedDocument(self, document):
        from PySide import QtCore

        name = document.Name
        QtCore.QTimer.singleShot(0, lambda: restore(name))


_observer = []


def install():
    """Registers the observer (once)."""
    if not _observer:
        _observer.append(_OpenObserver())
        FreeCAD.addDocumentObserver(_observer[0])
