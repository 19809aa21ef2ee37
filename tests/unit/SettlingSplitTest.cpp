// Where halving a cell the way its bound prefers leaves a half above the target and halving it
// the other way settles both halves, the kd-tree takes the other way (settlingSplitDirection).

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// A bicubic quarter of a cylinder, straight along u but with its u poles at x = 0, 1, 2, 12, as
// the long middle span of bug28366_fuselage.stp has them: the piece runs fast near u = 1 and the
// bilinear patch of a cell's corners is off it along u (the parameter, not the shape), so the
// bound prefers to halve along u while the arc along v is what keeps the halves above the
// target.
TopoDS_Shape unevenQuarterCylinder() {
    TColgp_Array2OfPnt poles(1, 4, 1, 4);
    const double xs[4] = {0, 1, 2, 12};
    const double ys[4] = {0, 0.55, 1, 1}, zs[4] = {1, 1, 0.55, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) poles.SetValue(i + 1, j + 1, gp_Pnt(xs[i], ys[j], zs[j]));
    return BRepBuilderAPI_MakeFace(new Geom_BezierSurface(poles), 1e-7).Face();
}

// Before, 1,841 and 5,432 triangles; halving along v where that settles both halves, 1,541 and
// 3,466.
TEST(SettlingSplit, CellsAreHalvedTheWayThatSettlesThem) {
    const TopoDS_Shape face = unevenQuarterCylinder();
    const Model model = occ::importModel(face);
    for (const auto& [tolerance, most] : {std::pair{2e-3, 1700u}, {1e-3, 4200u}}) {
        TessellationOptions options;
        options.tolerance = tolerance;
        const auto result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty());
        EXPECT_LT(result.mesh.triangles.size(), most) << tolerance;
        const auto report = occ::verifyMesh(face, result.mesh, tolerance);
        EXPECT_TRUE(report.pass) << tolerance << ": max dev " << report.maxDev;
        EXPECT_LE(report.maxDev, tolerance) << tolerance;
    }
}

// The approximate mode halves its cells the same way, by its own measure. On the same piece it
// took 1,156 and 4,655 triangles, more than the guaranteed mode at 1e-3 (as
// bug28366_fuselage.stp did: 13,136 against 11,042 at relative 1e-4); now 609 and 2,349. Its
// measure is an estimate: the deviation is 1.02 T at 2e-3 either way.
TEST(SettlingSplit, ApproximateModeHalvesTheWayThatSettlesToo) {
    const TopoDS_Shape face = unevenQuarterCylinder();
    const Model model = occ::importModel(face);
    for (const double tolerance : {2e-3, 1e-3}) {
        TessellationOptions options;
        options.tolerance = tolerance;
        const auto guaranteed = tessellateModel(model, options);
        options.mode = ErrorMode::Approximate;
        const auto approximate = tessellateModel(model, options);
        ASSERT_TRUE(approximate.failures.empty());
        const auto report = occ::verifyMesh(face, approximate.mesh, tolerance);
        EXPECT_LT(approximate.mesh.triangles.size(), guaranteed.mesh.triangles.size()) << tolerance;
        EXPECT_LE(report.maxDev, 1.05 * tolerance) << tolerance;
    }
}

}  // namespace
}  // namespace nurbslod
