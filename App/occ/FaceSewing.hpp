#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <vector>

namespace nurbslod::occ {

// Faces of a file that was written without its topology (a compound of loose faces, as many
// IGES and some STEP files are) each own a copy of the edges they have in common, so nothing
// tells the tessellator that the two copies are one edge and the mesh opens along it.
// OpenCASCADE's sewing (BRepBuilderAPI_Sewing) finds the copies that coincide within
// `tolerance` and makes them one shared edge. A single face is sewn too: IGES keeps no seam,
// so a whole torus or sphere read from it is one face whose seam is two separate edges (a torus
// at relative 1e-3 had 394 open edges along them, none once sewn).
struct SewnShape {
    TopoDS_Shape shape;              // the sewn shape (the input when nothing was sewn)
    std::vector<TopoDS_Face> faces;  // in the input's face order (TopExp::MapShapes)
};
// The shape as it is, with its faces.
SewnShape unsewn(const TopoDS_Shape& shape);
// The input as it is when it has no free edges or sewing fails.
SewnShape sewFaces(const TopoDS_Shape& shape, double tolerance);

}  // namespace nurbslod::occ
