#!/usr/bin/python3
"""open_edges: where a mesh's open edges lie on the B-rep it was made from.

Counts the open edges as meshjudge.py does (vertices welded on a grid of max(T * 1e-3, 1e-9),
edges used by exactly one triangle), then gives each one to the nearest B-rep edge and prints,
per B-rep edge: its faces (1-based, FreeCAD's shape.Faces order), its tolerance and length, how
many open edges lie on it and in which mesh faces ('g FaceN' groups), how far they are from it
and their mean length. --list prints every open edge with its face and end points.

Usage (with /usr/bin/python3, which has FreeCAD's modules):
  tests/bench/open_edges.py MODEL MESH.obj --tol T [--list]
"""
import argparse
import collections
import sys

sys.path.append("/usr/lib/freecad-python3/lib")

import numpy as np  # noqa: E402


def read_obj(path):
    vertices, triangles, faces, face = [], [], [], 0
    with open(path) as lines:
        for line in lines:
            if line.startswith("v "):
                vertices.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("g Face"):
                face = int(line.split()[1][4:])
            elif line.startswith("f "):
                triangles.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
                faces.append(face)
    return np.array(vertices), np.array(triangles, dtype=np.int64), np.array(faces)


def open_edges(vertices, triangles, faces, tol):
    """(face, a, b) for every edge that one triangle uses, a and b welded positions."""
    key = np.round(vertices / max(tol * 1e-3, 1e-9)).astype(np.int64)
    _, weld = np.unique(key, axis=0, return_inverse=True)
    weld = weld.reshape(-1)
    first = {}
    for i, w in enumerate(weld):
        first.setdefault(w, vertices[i])
    welded = weld[triangles]
    edges = np.concatenate([welded[:, [0, 1]], welded[:, [1, 2]], welded[:, [2, 0]]])
    edge_faces = np.concatenate([faces, faces, faces])
    keep = edges[:, 0] != edges[:, 1]
    edges, edge_faces = edges[keep], edge_faces[keep]
    _, inverse, counts = np.unique(np.sort(edges, axis=1), axis=0, return_inverse=True,
                                   return_counts=True)
    once = counts[inverse.reshape(-1)] == 1
    return [(int(f), first[a], first[b]) for (a, b), f in zip(edges[once], edge_faces[once])]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model")
    parser.add_argument("mesh")
    parser.add_argument("--tol", type=float, required=True, help="tolerance in model units")
    parser.add_argument("--list", action="store_true", help="print every open edge")
    args = parser.parse_args()

    import FreeCAD
    import Part

    shape = Part.Shape()
    shape.read(args.model)
    edges = shape.Edges
    faces_of_edge = collections.defaultdict(list)
    for f, face in enumerate(shape.Faces, 1):
        for edge in face.Edges:
            for e, other in enumerate(edges):
                if other.isSame(edge) and f not in faces_of_edge[e]:
                    faces_of_edge[e].append(f)

    found = open_edges(*read_obj(args.mesh), args.tol)
    print("open edges", len(found))
    by_edge = collections.defaultdict(list)
    for face, a, b in found:
        middle = Part.Vertex(FreeCAD.Vector(*(0.5 * (a + b))))
        distance, nearest = min((edge.distToShape(middle)[0], e) for e, edge in enumerate(edges))
        by_edge[nearest].append((face, distance, float(np.linalg.norm(b - a))))
        if args.list:
            print("  Face%d %s -> %s (B-rep edge %d)" % (face, a, b, nearest + 1))
    for e, hits in sorted(by_edge.items(), key=lambda item: -len(item[1])):
        edge = edges[e]
        in_faces = dict(collections.Counter(hit[0] for hit in hits))
        print("B-rep edge %d faces %s tolerance %.3g length %.4g: %d open edges in mesh faces %s,"
              " at most %.3g from it, mean length %.3g"
              % (e + 1, faces_of_edge[e], edge.Tolerance, edge.Length, len(hits), in_faces,
                 max(hit[1] for hit in hits), np.mean([hit[2] for hit in hits])))


if __name__ == "__main__":
    main()
