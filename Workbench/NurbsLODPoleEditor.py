"""Control-point editing of one B-spline face (paper out-of-core-lod, section 5).

PoleEditor shows the face's control net in the 3D view; moving a pole (a dragger on the pole
the user clicked, or move() from a macro) updates only that face in the adaptive-display node
at once, the document untouched; finish() writes the new surface into the document in one
undoable transaction ("Edit control points"), cancel() (Escape) puts everything back.
"""

import FreeCAD

import NurbsLODGui
import NurbsLODOverlays

COMMAND_NAME = "NurbsLOD_EditPoles"
# How close (pixels) a click must be to a pole to grab it.
GRAB_RADIUS_PX = 12


def _selected_face():
    """(object, 1-based face index) of the single selected face, or (None, reason)."""
    import FreeCADGui

    selection = FreeCADGui.Selection.getSelectionEx()
    faces = [
        (item.Object, int(name[4:]))
        for item in selection
        for name in item.SubElementNames
        if name.startswith("Face") and name[4:].isdigit()
    ]
    if len(faces) != 1:
        return None, "select one face of a B-spline surface"
    return faces[0]


class PoleEditor:
    """Live editing of the poles of face face_index (1-based) of obj."""

    def __init__(self, obj, face_index, view=None):
        import FreeCADGui
        import Part
        from pivy import coin

        # poles in the shape's own coordinates (the nodes'); the net gets obj's placement
        shape = NurbsLODGui.local_shape(obj)
        if not 1 <= face_index <= len(shape.Faces):
            raise ValueError("NurbsLOD: {} has no face {}".format(obj.Label, face_index))
        surface = shape.Faces[face_index - 1].Surface
        if not isinstance(surface, Part.BSplineSurface):
            raise ValueError(
                "NurbsLOD: {} face {} is a {}, not a B-spline surface: convert it first".format(
                    obj.Label, face_index, type(surface).__name__
                )
            )
        if not NurbsLODGui.is_enabled(obj):
            NurbsLODGui.enable_adaptive_display(obj)
        self.obj = obj
        self.face_index = face_index
        self.original = [list(row) for row in surface.getPoles()]
        self.poles = [list(row) for row in self.original]
        self.moved = set()
        self.view = view or FreeCADGui.getDocument(obj.Document.Name).activeView()
        self.timings = []

        # the net: poles as points, rows and columns as lines, always on top of nothing else
        self.placement = obj.Placement
        self.root = coin.SoSeparator()
        transform = coin.SoTransform()
        base, rotation = self.placement.Base, self.placement.Rotation.Q
        transform.translation.setValue(base.x, base.y, base.z)
        transform.rotation.setValue(rotation[0], rotation[1], rotation[2], rotation[3])
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        material = coin.SoMaterial()
        material.diffuseColor = (1.0, 0.45, 0.0)
        style = coin.SoDrawStyle()
        style.pointSize = 7
        style.lineWidth = 1
        self.coordinates = coin.SoCoordinate3()
        self._write_coordinates()
        rows, columns = len(self.poles), len(self.poles[0])
        lines = []
        for i in range(rows):
            lines.extend([i * columns + j for j in range(columns)] + [-1])
        for j in range(columns):
            lines.extend([i * columns + j for i in range(rows)] + [-1])
        net = coin.SoIndexedLineSet()
        net.coordIndex.setValues(0, len(lines), lines)
        for child in (transform, pick, material, style, self.coordinates, coin.SoPointSet(), net):
            self.root.addChild(child)
        self.dragger = None
        self.dragged = None
        self.view.getSceneGraph().addChild(self.root)
        self.callbacks = []

    def _write_coordinates(self):
        flat = [(p.x, p.y, p.z) for row in self.poles for p in row]
        self.coordinates.point.setValues(0, len(flat), flat)

    def move(self, i, j, position):
        """Moves pole (i, j) (1-based) to position (document coordinates): the node shows the
        new face at once, the document is not changed until finish(). Returns the node's
        timings."""
        position = self.placement.inverse().multVec(NurbsLODGui._finite_vector(position))
        return self._move_local(i, j, position)

    def pole(self, i, j):
        """Pole (i, j) (1-based) as it is now, in document coordinates."""
        return self.placement.multVec(self.poles[i - 1][j - 1])

    def _move_local(self, i, j, position):
        import NurbsLODCoin

        position = NurbsLODGui._finite_vector(position)
        rows, columns = len(self.poles), len(self.poles[0])
        if not (1 <= i <= rows and 1 <= j <= columns):
            raise ValueError(
                "NurbsLOD: face {} has poles (1..{}, 1..{}), not ({}, {})".format(
                    self.face_index, rows, columns, i, j
                )
            )
        node = NurbsLODGui.node_of(self.obj)
        timing = NurbsLODCoin.move_pole(
            node, self.face_index, i, j, (position.x, position.y, position.z), 0
        )
        self.poles[i - 1][j - 1] = position
        self.moved.add((i, j))
        index = (i - 1) * columns + (j - 1)
        self.coordinates.point.set1Value(index, position.x, position.y, position.z)
        self._follow_overlay(timing)
        self.timings.append(timing)
        return timing

    def _edited_face(self):
        """The face with the moved poles, in the shape's own coordinates, and the face it
        replaces."""
        shape = NurbsLODGui.local_shape(self.obj)
        face = shape.Faces[self.face_index - 1]
        surface = face.Surface.copy()
        for i, j in sorted(self.moved):
            surface.setPole(i, j, self.poles[i - 1][j - 1])
        return shape, face, NurbsLODGui._face_on_surface(face, surface)

    def _follow_overlay(self, timing):
        """An analysis overlay the object shows follows the live face; its cost goes into
        timing["overlay_ms"]. A face the overlay cannot analyse keeps the old stripes."""
        if NurbsLODOverlays.overlay_of(self.obj) is None:
            return
        try:
            timing["overlay_ms"] = NurbsLODOverlays.follow_face(
                self.obj, self.face_index, self._edited_face()[2]
            )
        except Exception as error:
            FreeCAD.Console.PrintWarning("{}\n".format(error))

    def grab(self, i, j):
        """Puts a dragger on pole (i, j); dragging it moves the pole live."""
        from pivy import coin

        self.release()
        self.dragger = coin.SoDragPointDragger()
        pole = self.poles[i - 1][j - 1]
        self.dragger.translation.setValue(pole.x, pole.y, pole.z)
        self.dragged = (i, j)
        self.dragger.addValueChangedCallback(self._dragged)
        self.root.addChild(self.dragger)
        return self.dragger

    def _dragged(self, data, dragger=None):
        dragger = dragger or self.dragger
        if self.dragged is None:
            return
        x, y, z = dragger.translation.getValue().getValue()
        try:  # the dragger sits under the net's transform: shape coordinates
            self._move_local(self.dragged[0], self.dragged[1], FreeCAD.Vector(x, y, z))
        except Exception as error:  # a callback must not raise into Coin
            FreeCAD.Console.PrintError("NurbsLOD: pole not moved: {}\n".format(error))

    def release(self):
        if self.dragger is not None:
            self.root.removeChild(self.dragger)
            self.dragger = None
            self.dragged = None

    def pole_at(self, x, y):
        """The (i, j) of the pole drawn within GRAB_RADIUS_PX of screen point (x, y), or None."""
        best, best_distance = None, GRAB_RADIUS_PX
        for i, row in enumerate(self.poles, 1):
            for j, pole in enumerate(row, 1):
                px, py = self.view.getPointOnScreen(self.placement.multVec(pole))
                distance = ((px - x) ** 2 + (py - y) ** 2) ** 0.5
                if distance <= best_distance:
                    best, best_distance = (i, j), distance
        return best

    def finish(self):
        """Writes the moved poles into the document in one undoable transaction."""
        self._close()
        if not self.moved:
            return False
        shape, face, new_face = self._edited_face()
        new_shape = new_face if len(shape.Faces) == 1 and shape.ShapeType == "Face" else (
            shape.replaceShape([(face, new_face)])
        )
        new_shape.Placement = self.placement
        document = self.obj.Document
        document.openTransaction("Edit control points")
        NurbsLODGui._editing = True  # the node shows the new face already
        try:
            self.obj.Shape = new_shape
        finally:
            NurbsLODGui._editing = False
            document.commitTransaction()
        return True

    def cancel(self):
        """Puts the node back to the document's face; the document was never changed."""
        import NurbsLODCoin

        self._close()
        node = NurbsLODGui.node_of(self.obj)
        for i, j in sorted(self.moved):
            pole = self.original[i - 1][j - 1]
            NurbsLODCoin.move_pole(node, self.face_index, i, j, (pole.x, pole.y, pole.z), 0)
        self.moved.clear()
        NurbsLODOverlays.refresh_overlay(self.obj)  # the document's face again

    def _close(self):
        self.release()
        for event_type, callback in self.callbacks:
            self.view.removeEventCallbackPivy(event_type, callback)
        self.callbacks = []
        graph = self.view.getSceneGraph()
        if graph.findChild(self.root) >= 0:
            graph.removeChild(self.root)

    # interaction: click a pole to grab it, Escape cancels, Enter finishes
    def listen(self):
        from pivy import coin

        self.callbacks = [
            (coin.SoMouseButtonEvent.getClassTypeId(), self._mouse),
            (coin.SoKeyboardEvent.getClassTypeId(), self._key),
        ]
        for event_type, callback in self.callbacks:
            self.view.addEventCallbackPivy(event_type, callback)

    def _mouse(self, event_callback):
        from pivy import coin

        event = event_callback.getEvent()
        if event.getState() != coin.SoMouseButtonEvent.DOWN or event.getButton() != 1:
            return
        x, y = event.getPosition().getValue()
        pole = self.pole_at(x, y)
        if pole is not None and pole != self.dragged:
            self.grab(*pole)

    def _key(self, event_callback):
        from pivy import coin

        event = event_callback.getEvent()
        if event.getState() != coin.SoButtonEvent.DOWN:
            return
        global _active
        if event.getKey() == coin.SoKeyboardEvent.ESCAPE:
            self.cancel()
            _active = None
            event_callback.setHandled()
        elif event.getKey() in (coin.SoKeyboardEvent.RETURN, coin.SoKeyboardEvent.ENTER):
            self.finish()
            _active = None
            event_callback.setHandled()


_active = None


class EditPoles:
    def GetResources(self):
        import NurbsLODPaths

        return {
            "Pixmap": NurbsLODPaths.icon("NurbsLODEditPoles.svg"),
            "MenuText": "Edit control points",
            "ToolTip": "Show the control net of the selected B-spline face; click a pole and "
            "drag it, the shading follows. Enter (or the command again) keeps the edit as one "
            "undoable step, Escape cancels",
        }

    def IsActive(self):
        return _active is not None or _selected_face()[0] is not None

    def Activated(self):
        global _active
        if _active is not None:
            editor, _active = _active, None
            editor.finish()
            return
        obj, face_index = _selected_face()
        if obj is None:
            FreeCAD.Console.PrintError("NurbsLOD: {}\n".format(face_index))
            return
        try:
            _active = PoleEditor(obj, face_index)
            _active.listen()
        except Exception as error:  # a command must not raise: tell the user instead
            _active = None
            FreeCAD.Console.PrintError(
                "NurbsLOD: cannot edit the control points: {}\n".format(error)
            )


if FreeCAD.GuiUp:
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, EditPoles())
