#include "occ/ShapeDiagonal.hpp"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cmath>

namespace nurbslod::occ {

ShapeExtent shapeExtent(const TopoDS_Shape& shape) {
    Bnd_Box box;
    try {
        OCC_CATCH_SIGNALS
        BRepBndLib::Add(shape, box);
    } catch (const Standard_Failure&) {
        box.SetVoid();
        TopTools_IndexedMapOfShape faces, vertices;
        TopExp::MapShapes(shape, TopAbs_FACE, faces);
        for (int k = 1; k <= faces.Extent(); ++k) {
            try {
                OCC_CATCH_SIGNALS
                Bnd_Box faceBox;
                BRepBndLib::Add(faces(k), faceBox);
                box.Add(faceBox);
            } catch (const Standard_Failure&) {
            }
        }
        TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
        for (int k = 1; k <= vertices.Extent(); ++k)
            box.Add(BRep_Tool::Pnt(TopoDS::Vertex(vertices(k))));
    }
    if (box.IsVoid()) return {};
    box.SetGap(0.0);
    ShapeExtent extent;
    extent.diagonal = std::sqrt(box.SquareExtent());
    extent.centre = 0.5 * (box.CornerMin().XYZ() + box.CornerMax().XYZ());
    return extent;
}

double boundingBoxDiagonal(const TopoDS_Shape& shape) {
    return shapeExtent(shape).diagonal;
}

}  // namespace nurbslod::occ
