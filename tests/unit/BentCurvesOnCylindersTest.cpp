// A bent curve on a face on a cylinder takes the kd-tree lines of that face only where they leave
// it fewer chords than midpoint subdivision (ModelTessellator): a cylinder is mostly triangulated
// unrolled over its boundary points, and the lines' halvings then only add points. A tube drilled
// through one wall: the hole's curves run around the hole cylinder, whose lines halve them to 96
// chords where 81 do.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <gp_Ax2.hxx>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// A tube of radii 10 and 9, 10 high, and a hole of radius 1 through its wall at half height.
TopoDS_Shape drilledTube() {
    const TopoDS_Shape outer = BRepPrimAPI_MakeCylinder(10, 10).Shape();
    const TopoDS_Shape inner = BRepPrimAPI_MakeCylinder(9, 10).Shape();
    const TopoDS_Shape tube = BRepAlgoAPI_Cut(outer, inner).Shape();
    const gp_Ax2 across(gp_Pnt(0, 0, 5), gp_Dir(1, 0, 0));
    return BRepAlgoAPI_Cut(tube, BRepPrimAPI_MakeCylinder(across, 1, 30).Shape()).Shape();
}

TEST(BentCurvesOnCylinders, HoleCurvesTakeFewerChordsThanTheHoleCylindersLines) {
    const TopoDS_Shape shape = drilledTube();
    const Model model = occ::importModel(shape);
    // the hole's face: the one on a cylinder of radius 1
    int hole = -1;
    for (std::size_t f = 0; f < model.faces.size(); ++f)
        if (model.faces[f].cylinder && std::abs(model.faces[f].cylinder->radius - 1) < 1e-9)
            hole = static_cast<int>(f) + 1;
    ASSERT_GT(hole, 0);
    TessellationOptions options;
    options.tolerance = 0.0049;  // the drilled tube of the generated shapes at relative 1e-4
    const TessellationResult result = tessellateModel(model, options);
    ASSERT_TRUE(result.failures.empty());
    // on the lines: two curves of 96 chords, 208 triangles; free: 81 chords each, 180
    const auto holeTriangles =
        std::count(result.mesh.triangleFaces.begin(), result.mesh.triangleFaces.end(), hole);
    EXPECT_LT(holeTriangles, 190);
    const occ::VerificationReport report = occ::verifyMesh(shape, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass) << "dev " << report.maxDev << " cover " << report.maxCover;
    EXPECT_EQ(report.openEdges, 0u);
}

}  // namespace
}  // namespace nurbslod
