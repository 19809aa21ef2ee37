#!/usr/bin/python3
"""periodic_judge: meshjudge.py, with its exact distance also tried on every period of a face
whose parameter range wraps round its periodic surface more than once.

Why it exists: OpenCASCADE's distance from a point to a face (BRepExtrema, behind
Part.Vertex.distToShape, which meshjudge.py uses for its exact re-check) projects the point onto
the surface at one parameter per period and classifies only that one. A face whose (u, v) domain
spans more than one period - bottle.brep's thread, a band on a cylinder with u from 0.12 to
12.45, two turns - then has a turn the distance does not see: a point lying on the second turn
gets its distance to the nearest edge of the face (up to half the band's width). The face's own
Area and BRepMesh's tessellation of it do cover both turns, and the trimming loops say so.

This wrapper changes only that one function. Where the judge's exact distance exceeds a
thousandth of the tolerance on such a face, the point's parameter is also tried one or more
periods on, inside the face's range, and classified against the face's trimming loops in (u, v)
(even-odd rule over fine polylines of the edges' pcurves). If it is inside there, the distance is
the one to the surface at that parameter. All else (sampling, reference meshes, cover, open
edges, the verdict) is the judge's own code, imported unchanged.

Usage (with /usr/bin/python3, which has FreeCAD's modules):
  tests/bench/periodic_judge.py MODEL MESH.obj --tol T [meshjudge options] [--judge PATH]
Prints the judge's own summary line, then per face where the re-check changed a distance the
judge's largest exact distance there and the re-checked one. Exit code as meshjudge.py's.
"""
import argparse
import importlib.util
import os
import sys

sys.path.append("/usr/lib/freecad-python3/lib")

import numpy as np  # noqa: E402

PCURVE_SAMPLES = 4000


def load_judge(path):
    spec = importlib.util.spec_from_file_location("meshjudge", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def wraps_more_than_once(face):
    surface = face.Surface
    u0, u1, v0, v1 = face.ParameterRange
    spans = []
    if surface.isUPeriodic() and u1 - u0 > surface.UPeriod() * (1 + 1e-9):
        spans.append((0, surface.UPeriod(), u0, u1))
    if surface.isVPeriodic() and v1 - v0 > surface.VPeriod() * (1 + 1e-9):
        spans.append((1, surface.VPeriod(), v0, v1))
    return spans


def loop_segments(face):
    """(u, v) segments of every trimming curve: the even-odd rule needs no loop order."""
    starts, ends = [], []
    for edge in face.Edges:
        curve, first, last = face.curveOnSurface(edge)[:3]
        ts = np.linspace(first, last, PCURVE_SAMPLES)
        points = np.array([(p.x, p.y) for p in (curve.value(t) for t in ts)])
        starts.append(points[:-1])
        ends.append(points[1:])
    return np.concatenate(starts), np.concatenate(ends)


def inside(segments, u, v):
    a, b = segments
    crosses = (a[:, 1] > v) != (b[:, 1] > v)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = a[:, 0] + (v - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(crosses & (at > u)) % 2)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(add_help=False)
    parser.add_argument("--judge", default=os.environ.get(
        "MESHJUDGE", os.path.join(here, "..", "..", "..", "shared", "tools", "meshjudge.py")))
    parser.add_argument("--tol", type=float)
    mine, rest = parser.parse_known_args()
    judge = load_judge(mine.judge)
    import FreeCAD  # noqa: E402  (after the judge put FreeCAD's path in place)

    original = judge.exact_dist
    cache, changed = {}, {}
    floor = (mine.tol or 0.0) * 1e-3

    def exact_dist(face, p):
        distance = original(face, p)
        if distance <= floor:
            return distance
        key = face.hashCode()
        if key not in cache:
            spans = wraps_more_than_once(face)
            cache[key] = (spans, loop_segments(face) if spans else None)
        spans, segments = cache[key]
        if not spans:
            return distance
        surface = face.Surface
        point = FreeCAD.Vector(*p)
        uv = list(surface.parameter(point))
        best = distance
        for direction, period, low, high in spans:
            base = uv[direction]
            first = int(np.floor((low - base) / period))
            last = int(np.ceil((high - base) / period))
            for k in range(first, last + 1):
                trial = list(uv)
                trial[direction] = base + k * period
                if not (low <= trial[direction] <= high):
                    continue
                if inside(segments, trial[0], trial[1]):
                    best = min(best, (surface.value(*trial) - point).Length)
        if best < distance:
            was, now = changed.get(key, (0.0, 0.0))
            changed[key] = (max(was, distance), max(now, best))
        return best

    judged = {}
    original_judge = judge.judge

    def judge_and_keep_shape(shape, *args, **kwargs):
        judged["shape"] = shape
        return original_judge(shape, *args, **kwargs)

    judge.exact_dist = exact_dist
    judge.judge = judge_and_keep_shape
    sys.argv = [mine.judge] + rest + (["--tol", repr(mine.tol)] if mine.tol is not None else [])
    try:
        judge.main()
    finally:  # main() ends with sys.exit
        faces = judged.get("shape").Faces if "shape" in judged else []
        for number, face in enumerate(faces, 1):
            if face.hashCode() in changed:
                was, now = changed[face.hashCode()]
                print("Face%d wraps its surface more than once: largest exact distance %.4g "
                      "as judged, %.4g on every period" % (number, was, now))

if __name__ == "__main__":
    main()
