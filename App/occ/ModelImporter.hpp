#pragma once

#include <TopoDS_Shape.hxx>

#include "tessellate/Model.hpp"

namespace nurbslod::occ {

// Converts every face of the shape (TopExp::MapShapes order, FreeCAD's shape.Faces) to a
// trimmed NURBS surface: analytic surfaces through BRepBuilderAPI_NurbsConvert, the face's
// location applied to the control points, loops from the edges' pcurves. A face that cannot
// be converted keeps its slot with `error` set.
Model importModel(const TopoDS_Shape& shape);

}  // namespace nurbslod::occ
