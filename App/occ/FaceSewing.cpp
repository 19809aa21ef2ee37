#include "occ/FaceSewing.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <optional>

#include "occ/FreeEdgePairs.hpp"

namespace nurbslod::occ {

TopoDS_Shape SewnShape::edgeOf(const TopoDS_Edge& edge) const {
    const TopoDS_Shape* replacement = replacedEdges.Seek(edge);
    return replacement ? *replacement : TopoDS_Shape(edge);
}

SewnShape unsewn(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    SewnShape input{shape, {}, {}};
    for (int k = 1; k <= faces.Extent(); ++k) input.faces.push_back(TopoDS::Face(faces(k)));
    return input;
}

namespace {

// `given` (0-based slots of input.faces) sewn; `whole`: they are every face, and the sewn shape
// is the sewing's own. nullopt where the sewing failed or lost a face, or (not whole) where it
// changed an edge or a vertex that a face outside `given` shares.
std::optional<SewnShape> sewn(const TopoDS_Shape& shape, const SewnShape& input,
                              const std::vector<int>& given, bool whole, double tolerance) {
    BRepBuilderAPI_Sewing sewing(tolerance);
    if (whole)
        sewing.Add(shape);
    else
        for (int slot : given) sewing.Add(input.faces[slot]);
    sewing.Perform();
    const TopoDS_Shape sewedShape = sewing.SewedShape();
    if (sewedShape.IsNull()) return std::nullopt;
    SewnShape result{whole ? sewedShape : TopoDS_Shape(), input.faces, {}};
    TopTools_IndexedMapOfShape sewnFaces;
    TopExp::MapShapes(sewedShape, TopAbs_FACE, sewnFaces);
    for (int slot : given) {
        TopoDS_Shape face = input.faces[slot];
        if (sewing.IsModifiedSubShape(face)) face = sewing.ModifiedSubShape(face);
        // every face must still be there, one for one, or the sewing is not used
        if (face.IsNull() || face.ShapeType() != TopAbs_FACE || !sewnFaces.Contains(face))
            return std::nullopt;
        result.faces[slot] = TopoDS::Face(face);
    }
    std::vector<char> isGiven(input.faces.size(), 0);
    for (int slot : given) isGiven[slot] = 1;
    TopTools_IndexedMapOfShape allFaces;
    TopExp::MapShapes(shape, TopAbs_FACE, allFaces);
    for (const TopAbs_ShapeEnum type : {TopAbs_EDGE, TopAbs_VERTEX}) {
        TopTools_IndexedDataMapOfShapeListOfShape facesOf;
        TopExp::MapShapesAndAncestors(shape, type, TopAbs_FACE, facesOf);
        for (int k = 1; k <= facesOf.Extent(); ++k) {
            const TopoDS_Shape& part = facesOf.FindKey(k);
            bool inGiven = false, outside = false;
            for (const TopoDS_Shape& face : facesOf(k))
                (isGiven[allFaces.FindIndex(face) - 1] ? inGiven : outside) = true;
            if (!inGiven || !sewing.IsModifiedSubShape(part)) continue;
            if (outside && !whole) return std::nullopt;
            if (type == TopAbs_EDGE) result.replacedEdges.Bind(part, sewing.ModifiedSubShape(part));
        }
    }
    if (!whole) {
        TopoDS_Compound compound;
        BRep_Builder builder;
        builder.MakeCompound(compound);
        for (const TopoDS_Face& face : result.faces) builder.Add(compound, face);
        result.shape = compound;
    }
    return result;
}

}  // namespace

SewnShape sewFaces(const TopoDS_Shape& shape, const std::vector<int>& faceIndices,
                   double tolerance) {
    const SewnShape input = unsewn(shape);
    const int faceCount = static_cast<int>(input.faces.size());
    if (!(tolerance > 0) || input.faces.empty() || freeEdges(shape).empty()) return input;
    std::vector<int> given;
    for (int k : faceIndices)
        if (k >= 1 && k <= faceCount) given.push_back(k - 1);
    std::sort(given.begin(), given.end());
    given.erase(std::unique(given.begin(), given.end()), given.end());
    if (given.empty()) return input;
    std::vector<int> every(input.faces.size());
    for (int slot = 0; slot < faceCount; ++slot) every[slot] = slot;
    if (given.size() < input.faces.size()) {
        try {
            OCC_CATCH_SIGNALS
            if (auto part = sewn(shape, input, given, false, tolerance)) return *part;
        } catch (const Standard_Failure&) {
        }
    }
    try {
        OCC_CATCH_SIGNALS
        if (auto whole = sewn(shape, input, every, true, tolerance)) return *whole;
    } catch (const Standard_Failure&) {
    }
    return input;  // open edges, but every face still meshed
}

}  // namespace nurbslod::occ
