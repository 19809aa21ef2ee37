"""Benchmark (not a test): how long set_overlay holds up the GUI thread.

    xvfb-run -a -s "-screen 0 1280x1024x24" freecad tests/gui/bench_set_overlay.py

For each model (the project's sample model and a 20 x 20 bicubic face, generated; bottle and
trj7 from the corpus when it is there) and each overlay kind, side by side in one run:
  - on the GUI thread: the whole analysis mesh made on the GUI thread, then the nodes built
    and shown (what set_overlay did before the worker);
  - in the worker: set_overlay(wait=False), the mesh made in a BackgroundWorker while the
    event loop runs, the nodes built on the GUI thread when it is ready.
A 1 ms QTimer on the GUI thread measures the longest gap between its ticks from the request
until the overlay has been drawn once: the longest time the GUI could not answer (a click,
a redraw). The view is drawn by Mesa's software renderer here, so the first draw of a large
overlay mesh is a block of its own, in both columns alike. The frame budget of the adaptive
display is 20 ms.

A second table: adaptive display when the object's shape changes, the model re-read on the
GUI thread (as before) or in a thread (as now), the longest block until the new node is in.
"""

import os
import sys
import time
import traceback

from PySide import QtCore

KINDS = ("zebra", "curvature")


def _here():
    for argument in sys.argv:
        if argument.endswith("bench_set_overlay.py"):
            return os.path.dirname(os.path.abspath(argument))
    return os.path.join(os.getcwd(), "tests", "gui")


class GapMeter:
    """Ticks every millisecond on the GUI thread; a gap between two ticks is a time the event
    loop was held."""

    def __init__(self):
        self.timer = QtCore.QTimer()
        self.timer.setInterval(1)
        self.timer.timeout.connect(self._tick)
        self.last = None
        self.gaps = []  # (end, seconds)

    def _tick(self):
        now = time.perf_counter()
        if self.last is not None:
            self.gaps.append((now, now - self.last))
        self.last = now

    def start(self):
        self.last, self.gaps = time.perf_counter(), []
        self.timer.start()

    def stop(self):
        self.timer.stop()
        self._tick()

    def longest_ms(self, after=None, before=None):
        """The longest gap that began in [after, before)."""
        gaps = [
            gap
            for end, gap in self.gaps
            if (after is None or end - gap >= after) and (before is None or end - gap < before)
        ]
        return 1000.0 * max(gaps, default=0.0)


def _run_in_event_loop(action, done, seconds=600.0):
    """Runs action() from the event loop and spins a real Qt event loop until done() (checked
    every 2 ms), then lets one more redraw happen. Returns the seconds until done."""
    loop = QtCore.QEventLoop()
    start = []
    finished = []

    def check():
        if finished:
            return
        if done() or time.perf_counter() - start[0] > seconds:
            finished.append(time.perf_counter())
            QtCore.QTimer.singleShot(100, loop.quit)  # the first draw of the overlay
        else:
            QtCore.QTimer.singleShot(2, check)

    def begin():
        start.append(time.perf_counter())
        action()
        check()

    QtCore.QTimer.singleShot(0, begin)
    loop.exec_()
    return start[0], finished[0]


def _blocking(obj, kind):
    """set_overlay as it was: the mesh made on the GUI thread."""
    import NurbsLODOverlays as overlays

    options = overlays.options_for(kind, {})
    overlay = overlays._Overlay(obj)
    overlays._overlays[overlays._key(obj)] = overlay
    overlay.analysis = overlays._analysis_mesh(overlays._local_shape(obj), options)
    overlay.requested = (kind, options)
    overlay.apply(kind, options)
    obj.ViewObject.RootNode.touch()  # redraw, as set_overlay's node change does


def _measure(obj, view, kind):
    import FreeCADGui

    import NurbsLODOverlays as overlays

    # when the nodes are in the switch: a gap that began before is the request's or the
    # build's, one that began after is the first draw's
    applied = []
    apply = overlays._Overlay.apply

    def timed_apply(self, *args, **kwargs):
        apply(self, *args, **kwargs)
        applied.append(time.perf_counter())

    overlays._Overlay.apply = timed_apply
    meter = GapMeter()
    results = {}
    for mode in ("gui", "worker"):
        overlays.set_overlay(obj, None)
        FreeCADGui.updateGui()
        meter.start()
        request = []

        def ask():
            begin = time.perf_counter()
            if mode == "gui":
                _blocking(obj, kind)
            else:
                overlays.set_overlay(obj, kind, wait=False)
            request.append(1000.0 * (time.perf_counter() - begin))

        applied.clear()
        start, shown = _run_in_event_loop(ask, lambda: not overlays.overlay_pending(obj))
        meter.stop()
        shown = applied[-1]
        overlay = overlays._overlays[overlays._key(obj)]
        results[mode] = {
            "triangles": len(overlay.analysis["triangles"]),
            "seconds": shown - start,
            "block_ms": meter.longest_ms(),
            "until_shown_ms": meter.longest_ms(before=shown),
            "first_draw_ms": meter.longest_ms(after=shown),
            "request_ms": request[0],
            "build_ms": overlay.result["build_ms"],
        }
        view.redraw()
    overlays._Overlay.apply = apply
    overlays.set_overlay(obj, None)
    return results


def _measure_refresh(obj):
    """The object's shape replaced by a copy with adaptive display on: re-read on the GUI
    thread (NurbsLODGui.refresh, what the document observer did) or in a thread (what it
    does now). Returns {mode: (longest block ms, seconds until the new node is in)}."""
    import NurbsLODGui

    NurbsLODGui.enable_adaptive_display(obj)
    meter = GapMeter()
    results = {}
    for mode in ("gui", "worker"):
        shape = obj.Shape.copy()
        meter.start()
        if mode == "gui":
            done = []

            def change():
                NurbsLODGui._editing = True  # the observer leaves it to us
                try:
                    obj.Shape = shape
                finally:
                    NurbsLODGui._editing = False
                NurbsLODGui.refresh(obj)
                done.append(1)

            start, shown = _run_in_event_loop(change, lambda: bool(done))
        else:

            def change():
                obj.Shape = shape

            start, shown = _run_in_event_loop(change, lambda: not NurbsLODGui.is_pending(obj))
        meter.stop()
        results[mode] = (meter.longest_ms(before=shown), shown - start)
    NurbsLODGui.disable_adaptive_display(obj)
    return results


def _models(directory):
    import Part

    import gui_testing as gt

    models = [
        ("sample model (generated)", Part.read(gt.sample_model(directory))),
        ("20 x 20 bicubic face (generated)", gt.bicubic_face(20)),
    ]
    for name in ("bottle.brep", "trj7_b1-ec-214.stp"):
        path = os.path.join(gt.CORPUS_DIR, name)
        if os.path.isfile(path):
            models.append((name, Part.read(path)))
        else:
            print("(corpus model {} absent: left out)".format(path))
    return models


def _run():
    import shutil
    import tempfile

    code = 0
    directory = tempfile.mkdtemp(prefix="nurbslod-bench-")
    try:
        sys.path.insert(0, _here())
        import gui_testing as gt

        rows = []
        refreshes = []
        for name, shape in _models(directory):
            document, obj, view = gt.open_shape(shape, "BenchOverlay")
            for kind in KINDS:
                results = _measure(obj, view, kind)
                rows.append((name, kind, results))
                print("{} {}: {}".format(name, kind, results))
                sys.stdout.flush()
            refreshes.append((name, _measure_refresh(obj)))
            print("{} adaptive display refresh: {}".format(name, refreshes[-1][1]))
            gt.close(document)

        print(
            "\nset_overlay: the longest time (ms) the GUI thread is held from the request "
            "until the overlay is shown\n(mesh made on the GUI thread, as before, or in the "
            "worker), the ratio, the seconds until it shows;\nof the worker's: the request "
            "(shape copy and key), the nodes built when the mesh is ready; then the\nfirst "
            "draw of the overlay (software GL; the same in both)"
        )
        widths = (32, 9, 9, 10, 10, 6, 7, 7, 8, 8, 10)
        header = "| " + " | ".join("{:>%d}" % w for w in widths) + " |"
        print(header.format("model", "overlay", "triangles", "GUI thread", "worker", "ratio",
                            "shown s", "shown s", "request", "build", "first draw"))
        print(header.format("", "", "", "block ms", "block ms", "", "GUI", "worker", "ms",
                            "ms", "ms"))
        print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
        row = ("| {:>32} | {:>9} | {:>9} | {:>10.1f} | {:>10.1f} | {:>6.1f} | {:>7.2f} | "
               "{:>7.2f} | {:>8.1f} | {:>8.1f} | {:>10.1f} |")
        for name, kind, results in rows:
            gui, worker = results["gui"], results["worker"]
            print(row.format(
                name, kind, gui["triangles"], gui["until_shown_ms"], worker["until_shown_ms"],
                gui["until_shown_ms"] / worker["until_shown_ms"], gui["seconds"],
                worker["seconds"], worker["request_ms"], worker["build_ms"],
                max(gui["first_draw_ms"], worker["first_draw_ms"])))
        print(
            "\nadaptive display, the object's shape changed (a recompute, undo): the longest "
            "time (ms) the GUI\nthread is held until the new node is in, the shape re-read on "
            "the GUI thread (before) or in a thread"
        )
        widths = (32, 10, 10, 6, 7, 7)
        header = "| " + " | ".join("{:>%d}" % w for w in widths) + " |"
        print(header.format("model", "GUI thread", "thread", "ratio", "in s", "in s"))
        print(header.format("", "block ms", "block ms", "", "GUI", "thread"))
        print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
        row = "| {:>32} | {:>10.1f} | {:>10.1f} | {:>6.1f} | {:>7.2f} | {:>7.2f} |"
        for name, results in refreshes:
            gui, worker = results["gui"], results["worker"]
            print(row.format(name, gui[0], worker[0], gui[0] / worker[0], gui[1], worker[1]))
    except Exception:
        traceback.print_exc()
        code = 1
    shutil.rmtree(directory, True)
    sys.stdout.flush()
    os._exit(code)


QtCore.QTimer.singleShot(200, _run)
