// The kd-tree halves a cell in the middle of the direction its bound gives (splitDirectionOfNet),
// not through the net point farthest from the bilinear patch (the paper's Fig. 3).

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// A unit square bulged along u by a cubic (heights 0, h, h, 0: x = u, and the net's farthest
// points from the bilinear patch at u = 1/3 and 2/3) and a quarter as much along v by a
// quadratic (y = v). Each cell's bound falls with the square of its side: a cell halved in the
// middle has children at a quarter of its bound, one cut at 1/3 a larger child at 4/9 of it.
// Every corner the kd-tree makes inside the face lies on its cuts, and halvings put the cuts
// along u at multiples of a power of two; before, the first one ran at x = 1/3 (and the
// boundary's cells at 1/3 of theirs).
TEST(MiddleSplit, CellsAreHalvedInTheMiddle) {
    const double h = 0.2;
    TColgp_Array2OfPnt poles(1, 4, 1, 3);
    const double heightsU[4] = {0, h, h, 0}, heightsV[3] = {0, h / 4, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            poles.SetValue(i + 1, j + 1, gp_Pnt(i / 3.0, j / 2.0, heightsU[i] + heightsV[j]));
    const TopoDS_Shape face = BRepBuilderAPI_MakeFace(new Geom_BezierSurface(poles), 1e-7).Face();
    const Model model = occ::importModel(face);
    // 369, 1,254 and 4,594 triangles; 407, 1,317 and 6,419 cut through the farthest points
    for (const auto& [tolerance, most] : {std::pair{2e-3, 400u}, {5e-4, 1300u}, {1e-4, 5000u}}) {
        TessellationOptions options;
        options.tolerance = tolerance;
        // the kd-tree's own cuts: even columns put their lines where they choose, and a cell the
        // boundary crosses is cut through a boundary point near where the bound says (the
        // display's meshes are cut without them too: FaceLod)
        options.evenColumns = false;
        options.splitThroughBoundaryPoints = false;
        // and the first tessellation's: the square's four edges are free, and a second one with
        // finer cells at them (1,493 and 5,069 triangles at 5e-4 and 1e-4, for fewer open edges)
        // is OpenEdgesTest's
        options.refineAtFreeChords = false;
        const auto result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty());
        const auto report = occ::verifyMesh(face, result.mesh, tolerance);
        EXPECT_TRUE(report.pass) << tolerance << ": max dev " << report.maxDev;
        int inside = 0;
        for (const auto& p : result.mesh.positions) {
            if (p.x() < 1e-9 || p.x() > 1 - 1e-9 || p.y() < 1e-9 || p.y() > 1 - 1e-9) continue;
            ++inside;
            const double scaled = std::ldexp(p.x(), 12);
            EXPECT_NEAR(scaled, std::round(scaled), 1e-6) << tolerance << ": x = " << p.x();
        }
        EXPECT_GT(inside, 0) << tolerance;
        EXPECT_LT(result.mesh.triangles.size(), most) << tolerance;
    }
}

}  // namespace
}  // namespace nurbslod
