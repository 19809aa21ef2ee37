#pragma once

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <cstddef>
#include <functional>

#include "tessellate/Model.hpp"

namespace nurbslod::occ {

// Converts every face of the shape (TopExp::MapShapes order, FreeCAD's shape.Faces) to a
// trimmed NURBS surface: elementary and swept surfaces by GeomConvert with their pcurves
// carried onto the new parameter (circle edges in their rational form on every face), offset
// surfaces through BRepBuilderAPI_NurbsConvert, the face's location applied to the control
// points, loops from the edges' pcurves. A face that cannot be converted keeps its slot with
// `error` set. threads: how many threads convert the faces (1: the calling thread alone, 0: all
// cores); the model is the same for any count. progress, where given, is called with (faces
// converted, faces) after each face, from the converting threads.
Model importModel(const TopoDS_Shape& shape, int threads = 1,
                  const std::function<void(std::size_t, std::size_t)>& progress = {});

// The NURBS form of a face's surface as the importer sees it (analytic surfaces converted,
// periodic knots clamped, the face's location applied), and its copy in our own type: the
// pair lets tests compare our evaluation with OpenCASCADE's on the very same surface.
Handle(Geom_BSplineSurface) faceSurfaceAsBSpline(const TopoDS_Face& face);
BSplineSurface toBSplineSurface(const Handle(Geom_BSplineSurface) & surface);
// A pcurve in our own type.
BSplineCurve2d toCurve(const Handle(Geom2d_BSplineCurve) & curve);

// Where `original` runs along an isoparametric line (every control point on it), `remade` is put
// back onto that line: a pcurve fitted to projections only comes within rounding of it.
void keepIsoparametric(const BSplineCurve2d& original, Geom2d_BSplineCurve& remade);

}  // namespace nurbslod::occ
