#pragma once

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <utility>
#include <vector>

#include "tessellate/Model.hpp"

namespace nurbslod::occ {

// The edges of a shape that bound one face only and are neither seams nor poles.
std::vector<TopoDS_Edge> freeEdges(const TopoDS_Shape& shape);

// Two free edges of different faces that are one edge of the part: the file wrote each face
// with its own copy (loose faces, as many IGES files are). `kept` is the one whose parameter both
// faces then share.
struct FreeEdgePair {
    TopoDS_Edge kept, joined;
};

// The pairs of free edges whose ends coincide within `tolerance` (either way round) and whose
// points between the ends lie within `tolerance` of each other's curve, and the faces of the
// free edges left without a pair. Loose faces written edge for edge pair up whole; anything else
// (an edge met by two shorter ones, a seam written as two edges of one face, an open shell,
// copies farther apart than the tolerance) is left to OpenCASCADE's sewing (sewFaces), which
// can cut edges.
struct FreeEdgeMatch {
    std::vector<FreeEdgePair> pairs;
    // 1-based (TopExp::MapShapes), ascending, each once; every face with a free edge where the
    // edges cannot be compared (no curve, a tolerance that is not a positive number)
    std::vector<int> facesLeft;
};
FreeEdgeMatch matchFreeEdges(const TopoDS_Shape& shape, double tolerance);
// The pairs where every free edge has its pair, else none.
std::vector<FreeEdgePair> pairFreeEdges(const TopoDS_Shape& shape, double tolerance);

// Makes each pair (kept, joined) of the model's edges one edge: the joined edge's face takes a
// pcurve in the kept edge's parameter, projected onto its surface (surfaces[face], OpenCASCADE's
// form of the face's B-spline surface) from the kept face's points within `accuracy`. Its loop
// then runs along the kept edge, the kept edge's tolerance covers the copies' gap, and the
// copies' vertices become one. A pair whose projection fails stays two edges (open in the mesh,
// every face still meshed). threads: as importModel's; the model is the same for any count.
void joinFreeEdgePairs(Model& model, const std::vector<std::pair<int, int>>& pairs,
                       const std::vector<Handle(Geom_BSplineSurface)>& surfaces, double accuracy,
                       int threads = 1);

}  // namespace nurbslod::occ
