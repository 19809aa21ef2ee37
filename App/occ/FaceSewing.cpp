#include "occ/FaceSewing.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "occ/FreeEdgePairs.hpp"

namespace nurbslod::occ {

SewnShape unsewn(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    SewnShape input{shape, {}};
    for (int k = 1; k <= faces.Extent(); ++k) input.faces.push_back(TopoDS::Face(faces(k)));
    return input;
}

SewnShape sewFaces(const TopoDS_Shape& shape, double tolerance) {
    const SewnShape input = unsewn(shape);
    if (!(tolerance > 0) || input.faces.empty() || freeEdges(shape).empty()) return input;
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    try {
        OCC_CATCH_SIGNALS
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
