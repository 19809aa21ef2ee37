#!/usr/bin/python3
"""Write FreeCAD's own BRepMesh tessellation of a model as an OBJ with 'g FaceN' groups.

The same mesh that `meshjudge.py MODEL --baseline D` judges (shape.tessellate(D, True), then
each face's triangulation), so that `nurbslod verify` and meshjudge can be compared on it.

Usage: /usr/bin/python3 brepmesh_obj.py MODEL DEFLECTION OUT.obj
"""
import sys

sys.path.append("/usr/lib/freecad-python3/lib")

import FreeCAD  # noqa: E402,F401
import Part  # noqa: E402


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    model, deflection, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    shape = Part.Shape()
    shape.read(model)
    s = shape.copy()
    s.tessellate(deflection, True)
    lines = []
    groups = []
    base = 0
    for i, face in enumerate(s.Faces, 1):
        points, triangles = face.tessellate(deflection)
        lines.extend("v %.17g %.17g %.17g" % (p.x, p.y, p.z) for p in points)
        if triangles:
            groups.append("g Face%d" % i)
            groups.extend("f %d %d %d" % (a + base + 1, b + base + 1, c + base + 1)
                          for a, b, c in triangles)
        base += len(points)
    with open(out, "w") as fh:
        fh.write("\n".join(lines + groups) + "\n")
    print("%s: %d faces, %d vertices" % (out, len(s.Faces), base))


if __name__ == "__main__":
    main()
