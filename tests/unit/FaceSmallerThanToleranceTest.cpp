// A face about the size of the tolerance may leave no triangle at it: a small sphere beside a
// large box at relative 1e-2, the workbench's coarsest level, lost its face (its seam one chord,
// its cells' corners all on its poles). It is tessellated again on its own at a finer tolerance.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <stdexcept>
#include <string>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

TEST(FaceSmallerThanTolerance, SmallSphereBesideALargeBoxKeepsItsFace) {
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    builder.Add(compound, BRepPrimAPI_MakeBox(300.0, 300.0, 300.0).Shape());
    builder.Add(compound, BRepPrimAPI_MakeSphere(gp_Pnt(400, 0, 0), 1.0).Shape());
    const Model model = occ::importModel(compound);
    ASSERT_EQ(model.faces.size(), 7u);
    TessellationOptions options;
    options.tolerance = 1e-2 * model.boundingBoxDiagonal;  // 5.8, the sphere's diameter is 2
    const TessellationResult result = tessellateModel(model, options);
    EXPECT_TRUE(result.failures.empty())
        << "face " << result.failures.front().face << ": " << result.failures.front().reason;
    EXPECT_GT(std::count(result.mesh.triangleFaces.begin(), result.mesh.triangleFaces.end(), 7), 0);
    const occ::VerificationReport report =
        occ::verifyMesh(compound, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass) << "dev " << report.maxDev << " cover " << report.maxCover;
    EXPECT_EQ(report.openEdges, 0u);
}

// A tolerance so coarse that no finer try gives the face a triangle still names it.
TEST(FaceSmallerThanTolerance, AbsurdToleranceStillNamesTheFace) {
    const Model model = occ::importModel(BRepPrimAPI_MakeSphere(7.0).Shape());
    TessellationOptions options;
    options.tolerance = 1e300;
    const TessellationResult result = tessellateModel(model, options);
    ASSERT_EQ(result.failures.size(), 1u);
    EXPECT_EQ(result.failures.front().face, 1);
    EXPECT_NE(result.failures.front().reason.find("no triangle left"), std::string::npos);
}

// A model within ten times OpenCASCADE's confusion distance (1e-7) is refused with the reason:
// a sphere of radius 5e-8 made by FreeCAD (its tolerances 1e-7, its poles' balls holding all of
// it) ran for minutes at relative 1e-3. Here FreeCAD's sphere is scaled to that radius.
TEST(FaceSmallerThanTolerance, ModelWithinTheConfusionDistanceIsRefused) {
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), 5e-8 / 7.0);
    const TopoDS_Shape sphere = occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_sphere.brep");
    const Model model =
        occ::importModel(BRepBuilderAPI_Transform(sphere, scale, Standard_True).Shape());
    ASSERT_LT(model.boundingBoxDiagonal, 1e-6);
    TessellationOptions options;
    options.tolerance = 1e-3 * model.boundingBoxDiagonal;
    try {
        tessellateModel(model, options);
        FAIL() << "a model " << model.boundingBoxDiagonal << " across was tessellated";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("confusion distance"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace nurbslod
