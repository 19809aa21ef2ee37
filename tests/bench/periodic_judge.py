#!/usr/bin/python3
"""periodic_judge: meshjudge.py, with its exact distance also tried on every period of a face
whose parameter range wraps round its periodic surface more than once or leaves the surface's
first period, and its distances to triangles over half the tolerance taken again in double
precision.

Why it exists: OpenCASCADE's distance from a point to a face (BRepExtrema, behind
Part.Vertex.distToShape, which meshjudge.py uses for its exact re-check) projects the point onto
the surface at one parameter per period and classifies only that one. A face whose (u, v) domain
spans more than one period - bottle.brep's thread, a band on a cylinder with u from 0.12 to
12.45, two turns - then has a turn the distance does not see: a point lying on the second turn
gets its distance to the nearest edge of the face (up to half the band's width). The face's own
Area and BRepMesh's tessellation of it do cover both turns, and the trimming loops say so.
The same holds for a face over one period that is not the surface's first: a partial torus
from BRepPrimAPI (FreeCAD's Part.makeTorus with angles -180, 180) has its tube angle over
[-pi, pi]; the projection answers in [0, 2 pi), and half the tube reads about its radius off.

Where the judge's exact distance exceeds a thousandth of the tolerance on such a face, the
point's parameter is also tried one or more periods on, inside the face's range, and classified
against the face's trimming loops in (u, v) (even-odd rule over fine polylines of the edges'
pcurves). If it is inside there, the distance is the one to the surface at that parameter.

The judge's distances from points to triangles (Open3D's ray-casting scene) are in single
precision; on slivers they are far off: hammer.iges at relative 1e-4 has triangles 21,980 long
and 14 wide along its ruled faces, where a reference point on a triangle reads 13.6 (the
tolerance is 4.1) and is 0.0002 away in double precision. Every such distance over half the
tolerance is computed again in double precision against the same triangles.

The wrapper changes only those two functions; all else (sampling, reference meshes, open edges,
the verdict) is the judge's own code, imported unchanged.

Usage (with /usr/bin/python3, which has FreeCAD's modules):
  tests/bench/periodic_judge.py MODEL MESH.obj --tol T [meshjudge options] [--judge PATH]
Prints the judge's own summary line, then per face where a re-check changed a distance the
judge's largest distance there and the re-checked one. Exit code as meshjudge.py's.
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


def periods_to_try(face):
    """(direction, period, low, high) for each periodic direction where a projection's one
    parameter per period may miss the face: its range wraps round more than once, or it leaves
    the surface's own period (a torus's tube angle over [-pi, pi], as BRepPrimAPI makes the
    tube of a partial torus, where the projection answers in [0, 2 pi))."""
    surface = face.Surface
    u0, u1, v0, v1 = face.ParameterRange
    su0, su1, sv0, sv1 = surface.bounds()
    spans = []
    for direction, periodic, period, low, high, own_low, own_high in (
            (0, surface.isUPeriodic(), surface.UPeriod() if surface.isUPeriodic() else 0,
             u0, u1, su0, su1),
            (1, surface.isVPeriodic(), surface.VPeriod() if surface.isVPeriodic() else 0,
             v0, v1, sv0, sv1)):
        if not periodic:
            continue
        slack = 1e-9 * period
        if (high - low > period + slack or low < own_low - slack or high > own_high + slack):
            spans.append((direction, period, low, high))
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


def triangles_distance(p, a, b, c):
    """Distance in double precision from point p to the nearest of the triangles (a[i], b[i],
    c[i]): to the plane where p's foot lies inside a triangle, else to its nearest side."""
    def to_segments(start, end):
        d = end - start
        length2 = np.einsum("ij,ij->i", d, d)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(length2 > 0, np.einsum("ij,ij->i", p - start, d) / length2, 0.0)
        t = np.clip(t, 0.0, 1.0)
        return np.linalg.norm(start + d * t[:, None] - p, axis=1)

    best = np.minimum(np.minimum(to_segments(a, b), to_segments(b, c)), to_segments(c, a))
    n = np.cross(b - a, c - a)
    n2 = np.einsum("ij,ij->i", n, n)
    ok = n2 > 0
    if ok.any():
        a, b, c, n, n2 = a[ok], b[ok], c[ok], n[ok], n2[ok]
        height = np.einsum("ij,ij->i", p - a, n) / n2
        foot = p - n * height[:, None]
        inside = np.ones(len(a), bool)
        for start, end in ((a, b), (b, c), (c, a)):
            inside &= np.einsum("ij,ij->i", np.cross(end - start, foot - start), n) >= 0
        plane = np.abs(height) * np.sqrt(n2)
        best[ok] = np.where(inside, np.minimum(best[ok], plane), best[ok])
    return float(best.min()) if len(best) else float("inf")


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
            spans = periods_to_try(face)
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

    # The judge's distances to triangles come from Open3D's ray-casting scene, in single
    # precision: on a sliver (hammer.iges at relative 1e-4: triangles 21,980 long and 14 wide
    # along a ruled surface) it reads 13.6 where the point lies on the triangle (0.0002). Every
    # distance over half the tolerance is taken again in double precision against the same
    # triangles; the judge then goes on with the exact value.
    original_scene, original_dist = judge.scene_of, judge.dist
    scenes, rechecked = {}, {}
    face_of_triangles, current = {}, {"face": None}

    def scene_of(points, triangles, origin):
        scene = original_scene(points, triangles, origin)
        face = face_of_triangles.get(id(triangles))
        if face is not None:
            current["face"] = face
        scenes[id(scene)] = (scene, points, triangles, face)
        return scene

    def dist(scene, queries, origin):
        distances = np.array(original_dist(scene, queries, origin), dtype=np.float64)
        if not mine.tol or id(scene) not in scenes:
            return distances
        _, points, triangles, face = scenes[id(scene)]
        a, b, c = (np.asarray(points, np.float64)[triangles[:, k]] for k in range(3))
        far = np.nonzero(distances > 0.5 * mine.tol)[0]
        for k in far:
            exact = triangles_distance(np.asarray(queries[k], np.float64), a, b, c)
            if exact < distances[k]:
                key = face if face is not None else current["face"]
                was, now = rechecked.get(key, (0.0, 0.0))
                rechecked[key] = (max(was, distances[k]), max(now, exact))
                distances[k] = exact
        return distances

    judged = {}
    original_judge = judge.judge

    def judge_and_keep_shape(shape, V, tris, *args, **kwargs):
        judged["shape"] = shape
        for number, triangles in tris.items():
            face_of_triangles[id(triangles)] = number
        return original_judge(shape, V, tris, *args, **kwargs)

    judge.exact_dist = exact_dist
    judge.scene_of, judge.dist = scene_of, dist
    judge.judge = judge_and_keep_shape
    sys.argv = [mine.judge] + rest + (["--tol", repr(mine.tol)] if mine.tol is not None else [])
    try:
        judge.main()
    finally:  # main() ends with sys.exit
        faces = judged.get("shape").Faces if "shape" in judged else []
        for number, face in enumerate(faces, 1):
            if face.hashCode() in changed:
                was, now = changed[face.hashCode()]
                print("Face%d spans periods the projection misses: largest exact distance %.4g "
                      "as judged, %.4g on every period" % (number, was, now))
        for number in sorted(k for k in rechecked if k is not None):
            was, now = rechecked[number]
            if was - now <= floor:  # the same but for rounding
                continue
            print("Face%d distances to triangles in double precision: largest %.4g as judged "
                  "(single precision), %.4g recomputed" % (number, was, now))

if __name__ == "__main__":
    main()
