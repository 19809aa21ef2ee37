// A hole wound the same way round as its face's outer wire: OpenCASCADE's check calls the face
// badly oriented and its classifier does not take the hole as one; the face is meshed as drawn
// (even-odd) and reported in the warnings, never silently.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <vector>

#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"
#include "trim/LoopWinding.hpp"

namespace nurbslod {
namespace {

// The top face of a 10 x 10 x 1 box less a cylinder of radius 2: a square with a round hole.
TopoDS_Face plateWithHole() {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 1).Shape();
    const TopoDS_Shape cylinder =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5, 5, -1), gp_Dir(0, 0, 1)), 2, 3).Shape();
    const TopoDS_Shape cut = BRepAlgoAPI_Cut(box, cylinder).Shape();
    for (TopExp_Explorer it(cut, TopAbs_FACE); it.More(); it.Next()) {
        const TopoDS_Face face = TopoDS::Face(it.Current());
        int wires = 0;
        for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
        if (wires == 2) return face;
    }
    return {};
}

// The same face with its hole's wire reversed: wound like the outer wire.
TopoDS_Face withHoleWoundLikeOuter(const TopoDS_Face& face) {
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    TopoDS_Face bad = TopoDS::Face(face.EmptyCopied());
    BRep_Builder builder;
    for (TopExp_Explorer it(face.Oriented(TopAbs_FORWARD), TopAbs_WIRE); it.More(); it.Next()) {
        const TopoDS_Wire wire = TopoDS::Wire(it.Current());
        builder.Add(bad, wire.IsSame(outer) ? wire : TopoDS::Wire(wire.Reversed()));
    }
    return bad;
}

TEST(LoopWinding, SignedAreaAndInside) {
    const std::vector<Point2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_DOUBLE_EQ(signedArea(square), 4.0);
    EXPECT_DOUBLE_EQ(signedArea({square.rbegin(), square.rend()}), -4.0);
    EXPECT_TRUE(insidePolygon(square, {1, 1}));
    EXPECT_FALSE(insidePolygon(square, {3, 1}));
}

TEST(LoopWinding, HoleWoundLikeTheOuterWireIsReportedAndMeshedAsAHole) {
    const TopoDS_Face good = plateWithHole();
    ASSERT_FALSE(good.IsNull());
    const TopoDS_Face bad = withHoleWoundLikeOuter(good);

    TessellationOptions options;
    options.tolerance = 0.01;
    const Model goodModel = occ::importModel(good);
    const Model badModel = occ::importModel(bad);
    ASSERT_EQ(goodModel.faces.size(), 1u);
    ASSERT_EQ(badModel.faces.size(), 1u);
    EXPECT_FALSE(loopWindingProblem(goodModel.faces[0]));
    const auto problem = loopWindingProblem(badModel.faces[0]);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("same way round"), std::string::npos) << *problem;

    const TessellationResult goodMesh = tessellateModel(goodModel, options);
    const TessellationResult badMesh = tessellateModel(badModel, options);
    EXPECT_TRUE(goodMesh.warnings.empty());
    EXPECT_TRUE(goodMesh.failures.empty());
    ASSERT_EQ(badMesh.warnings.size(), 1u);
    EXPECT_EQ(badMesh.warnings[0].face, 1);
    EXPECT_TRUE(badMesh.failures.empty());
    // meshed as drawn: the square less the hole, as the valid face is
    EXPECT_EQ(badMesh.mesh.triangles.size(), goodMesh.mesh.triangles.size());
    for (const auto& triangle : badMesh.mesh.triangles) {
        Point3 centroid = Point3::Zero();
        for (const auto corner : triangle) centroid += badMesh.mesh.positions[corner] / 3.0;
        EXPECT_GT((centroid - Point3(5, 5, 1)).head<2>().norm(), 1.5);
    }
}

}  // namespace
}  // namespace nurbslod
