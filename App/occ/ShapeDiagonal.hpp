#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_XYZ.hxx>

namespace nurbslod::occ {

// The diagonal of the shape's bounding box (0 for an empty shape): what a relative tolerance
// is a fraction of, the same to `tessellate`, `verify` and the importer. Taken face by face
// where the whole shape's box throws (a broken face, as FreeCAD's makeTorus leaves with some
// angles), and from the vertices where no face gives one, so that a broken face does not stop
// the others: it fails on its own.
double boundingBoxDiagonal(const TopoDS_Shape& shape);

// The same box's diagonal and centre (the origin for an empty shape).
struct ShapeExtent {
    double diagonal = 0;
    gp_XYZ centre{0, 0, 0};
};
ShapeExtent shapeExtent(const TopoDS_Shape& shape);

}  // namespace nurbslod::occ
