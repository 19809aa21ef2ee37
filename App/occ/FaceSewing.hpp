#pragma once

#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopoDS_Edge.hxx>
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
    // each edge of the input that the sewing replaced, with what replaced it (an edge, or the
    // pieces of one it cut)
    TopTools_DataMapOfShapeShape replacedEdges;

    // The edge's replacement in the sewn shape, the edge itself where it was kept.
    TopoDS_Shape edgeOf(const TopoDS_Edge& edge) const;
};
// The shape as it is, with its faces.
SewnShape unsewn(const TopoDS_Shape& shape);
// The input with the faces `faceIndices` (1-based, TopExp::MapShapes, in any order) sewn among
// themselves and the others kept as they are (a compound of the faces, in their order). The
// sewing's cost grows with what it is given: bearing.iges's 213 loose faces, whose 925 free edges
// all but 49 pair up (matchFreeEdges), sewn whole took 0.12 s, more than the tessellation. Where
// the sewing would change an edge or vertex that a face it was not given shares, the whole shape is
// sewn instead. The input as it is when it has no free edges or sewing fails.
SewnShape sewFaces(const TopoDS_Shape& shape, const std::vector<int>& faceIndices,
                   double tolerance);

}  // namespace nurbslod::occ
