// Lone faces (LoneFaces.hpp): which faces tessellateModel tessellates a second time on their
// own, and how their triangles replace the first ones in the mesh.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include "occ/ModelImporter.hpp"
#include "tessellate/LoneFaces.hpp"

namespace nurbslod {
namespace {

// The lateral face of a cylinder of radius 2 and height 7: two free circles and a seam.
TopoDS_Face openCylinder() {
    const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(2.0, 7.0).Shape();
    for (TopExp_Explorer it(cylinder, TopAbs_FACE); it.More(); it.Next())
        if (BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType() == GeomAbs_Cylinder)
            return TopoDS::Face(it.Current());
    return {};
}

TEST(LoneFaces, AnOpenCylinderIsALoneBoxFaceAndABoxsFaceIsNot) {
    const TopoDS_Face lateral = openCylinder();
    ASSERT_FALSE(lateral.IsNull());
    const Model tube = occ::importModel(lateral);
    ASSERT_EQ(tube.faces.size(), 1u);
    EXPECT_EQ(loneBoxFaces(tube, 1e-6), std::vector<int>{0});
    // held to an exactness below its circles' tolerance, they are not exact: not taken
    EXPECT_TRUE(loneBoxFaces(tube, -1).empty());

    const Model box = occ::importModel(BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape());
    EXPECT_TRUE(loneBoxFaces(box, 1e-6).empty());  // every edge shared

    // a square with a round hole: alone, but its region is not the box
    const gp_Pln plane;
    TopoDS_Face square = BRepBuilderAPI_MakeFace(plane, -2, 2, -2, 2).Face();
    const TopoDS_Wire hole =
        BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(), 1.0)).Edge());
    BRepBuilderAPI_MakeFace holed(square);
    holed.Add(TopoDS::Wire(hole.Reversed()));
    const Model sheet = occ::importModel(holed.Face());
    ASSERT_EQ(sheet.faces.size(), 1u);
    EXPECT_TRUE(loneBoxFaces(sheet, 1e-6).empty());
    EXPECT_EQ(loneBoxFaces(occ::importModel(square), 1e-6), std::vector<int>{0});
}

TEST(LoneFaces, ALoneFacesModelHasItsOwnEdgesAndVertices) {
    const Model tube = occ::importModel(openCylinder());
    const Model alone = loneFaceModel(tube, 0);
    ASSERT_EQ(alone.faces.size(), 1u);
    EXPECT_EQ(alone.faces[0].faceIndex, 1);
    EXPECT_EQ(alone.edges.size(), tube.edges.size());
    EXPECT_EQ(alone.vertices.size(), tube.vertices.size());
    for (const auto& loop : alone.faces[0].loops)
        for (const auto& curve : loop.curves) {
            ASSERT_GE(curve.edge, 0);
            ASSERT_LT(curve.edge, static_cast<int>(alone.edges.size()));
        }
}

// Two faces: face 1 a square of two triangles on points 0-3, face 2 one triangle on points
// 2, 3, 4. Face 1 replaced by one triangle of its own keeps face 2 as it was, drops point 0 and
// 1 (no triangle uses them any longer) and the normals of face 1.
TEST(LoneFaces, ReplacedTrianglesTakeTheFacesPlaceAndUnusedPointsGo) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 2, 0}};
    for (int i = 0; i < 7; ++i) {
        mesh.normals.push_back({0, 0, 1});
        mesh.parameters.push_back({double(i), 0});
    }
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}};
    mesh.triangleNormals = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
    mesh.triangleFaces = {1, 1, 2};
    EXPECT_EQ(faceOpenEdges(mesh, 1), 4u);
    EXPECT_EQ(faceOpenEdges(mesh, 2), 3u);

    Mesh alone;
    alone.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    alone.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    alone.parameters = {{10, 0}, {11, 0}, {12, 0}};
    alone.triangles = {{0, 1, 2}};
    alone.triangleNormals = {{0, 1, 2}};
    alone.triangleFaces = {1};
    replaceFaceTriangles(mesh, 1, alone);

    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangleFaces, (std::vector<std::int32_t>{1, 2}));
    EXPECT_EQ(mesh.positions.size(), 6u);  // 3 of face 2, 3 of the new face 1
    EXPECT_EQ(mesh.normals.size(), 6u);
    EXPECT_EQ(mesh.parameters.size(), 6u);
    // face 1 first, where it was; face 2 still on its own three points
    EXPECT_EQ(mesh.positions[mesh.triangles[0][1]], Point3(1, 0, 0));
    EXPECT_EQ(mesh.parameters[mesh.triangleNormals[0][2]], Point2(12, 0));
    EXPECT_EQ(mesh.positions[mesh.triangles[1][2]], Point3(0.5, 2, 0));
    EXPECT_EQ(mesh.parameters[mesh.triangleNormals[1][0]], Point2(4, 0));
    EXPECT_EQ(faceOpenEdges(mesh, 1), 3u);
}

}  // namespace
}  // namespace nurbslod
