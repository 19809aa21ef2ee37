#!/usr/bin/python3
"""sloppy_meeting: can the two faces of a sloppy B-rep edge share mesh points along it?

For each given B-rep edge (1-based, FreeCAD's shape.Edges order; tests/bench/open_edges.py
names the edges that carry open edges) it samples points along the 3D edge and moves each,
by alternating projection onto the two faces' untrimmed surfaces (the midpoint of the two
feet, repeated), towards where the surfaces meet or come closest. A point passes as meshjudge
would judge a vertex shared by both faces: within 0.2 T of both untrimmed surfaces
(surface.parameter + surface.value) and within slack of both trimmed faces, slack = the largest
tolerance of the face's edges. Prints per edge how many samples pass, the worst distances and
how far the point moved, then the totals (edges, length, length that passes).

Usage (with /usr/bin/python3, which has FreeCAD's modules):
  tests/bench/sloppy_meeting.py MODEL --tol T --edges 1024,96,511 [--samples 40]
"""
import argparse
import collections
import sys

sys.path.append("/usr/lib/freecad-python3/lib")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model")
    parser.add_argument("--tol", type=float, required=True, help="tolerance in model units")
    parser.add_argument("--edges", required=True, help="B-rep edge numbers, comma separated")
    parser.add_argument("--samples", type=int, default=40, help="points per edge")
    args = parser.parse_args()

    import FreeCAD  # noqa: F401 (loads the modules Part needs)
    import Part

    shape = Part.Shape()
    shape.read(args.model)
    edges, faces = shape.Edges, shape.Faces
    tol = args.tol

    def foot(surface, point):
        u, v = surface.parameter(point)
        q = surface.value(u, v)
        return q, (q - point).Length

    totals = collections.Counter()
    for number in (int(x) for x in args.edges.split(",")):
        edge = edges[number - 1]
        own = [f for f, face in enumerate(faces, 1) if any(e.isSame(edge) for e in face.Edges)]
        if len(own) != 2:
            print("edge %d: %d faces, skipped" % (number, len(own)))
            continue
        a, b = (faces[f - 1] for f in own)
        slack = [max(e.Tolerance for e in face.Edges) for face in (a, b)]
        first, last = edge.ParameterRange
        passing, near, worst = 0, 0, [0.0, 0.0, 0.0, 0.0]
        for i in range(args.samples):
            start = edge.valueAt(first + (last - first) * (i + 0.5) / args.samples)
            point, best = start, (float("inf"), start)
            for _ in range(200):
                qa, da = foot(a.Surface, point)
                qb, db = foot(b.Surface, point)
                if max(da, db) < best[0]:
                    best = (max(da, db), point)
                if max(da, db) < 1e-3 * tol:
                    break
                point = (qa + qb) * 0.5
            ds, point = best
            dt = [Part.Vertex(point).distToShape(face)[0] for face in (a, b)]
            near += ds <= 0.2 * tol
            passing += ds <= 0.2 * tol and dt[0] <= slack[0] and dt[1] <= slack[1]
            worst = [max(worst[0], ds / tol), max(worst[1], dt[0]), max(worst[2], dt[1]),
                     max(worst[3], (point - start).Length)]
        print("edge %d faces %d,%d tolerance %.3g length %.4g: %d/%d samples within 0.2 T of both"
              " surfaces, %d/%d also within slack (%.3g, %.3g) of both faces; worst ds/T %.3g,"
              " dt %.3g / %.3g, moved %.3g"
              % (number, own[0], own[1], edge.Tolerance, edge.Length, near, args.samples,
                 passing, args.samples, slack[0], slack[1], *worst))
        totals["edges"] += 1
        totals["edges passing everywhere"] += passing == args.samples
        totals["length"] += edge.Length
        totals["length passing"] += edge.Length * passing / args.samples
    print(dict(totals))


if __name__ == "__main__":
    main()
