#include "occ/FaceSewing.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace nurbslod::occ {

namespace {

// An edge that bounds only one face and is neither a seam nor a pole: a candidate for sewing.
bool hasFreeEdges(const TopoDS_Shape& shape) {
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    for (int i = 1; i <= facesOfEdge.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(facesOfEdge.FindKey(i));
        if (BRep_Tool::Degenerated(edge)) continue;
        const auto& faces = facesOfEdge(i);
        if (faces.Extent() == 1 && !BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First())))
            return true;
    }
    return false;
}

}  // namespace

SewnShape sewFaces(const TopoDS_Shape& shape, double tolerance) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    SewnShape input{shape, {}};
    for (int k = 1; k <= faces.Extent(); ++k) input.faces.push_back(TopoDS::Face(faces(k)));
    if (!(tolerance > 0) || faces.IsEmpty() || !hasFreeEdges(shape)) return input;
    try {
        BRepBuilderAPI_Sewing sewing(tolerance);
        sewing.Add(shape);
        sewing.Perform();
        SewnShape sewn{sewing.SewedShape(), input.faces};
        if (sewn.shape.IsNull()) return input;
        TopTools_IndexedMapOfShape sewnFaces;
        TopExp::MapShapes(sewn.shape, TopAbs_FACE, sewnFaces);
        for (int k = 1; k <= faces.Extent(); ++k) {
            TopoDS_Shape face = faces(k);
            if (sewing.IsModifiedSubShape(face)) face = sewing.ModifiedSubShape(face);
            // every face must still be there, one for one, or the sewing is not used
            if (face.IsNull() || face.ShapeType() != TopAbs_FACE || !sewnFaces.Contains(face))
                return input;
            sewn.faces[k - 1] = TopoDS::Face(face);
        }
        return sewn;
    } catch (const Standard_Failure&) {
        return input;  // open edges, but every face still meshed
    }
}

}  // namespace nurbslod::occ
