// The side of a truncated cone (radii 12 and 13.6, 2.26 high, like bug33398.step's face 1): its
// kd-tree cells are columns between the two circles, the region fills each column exactly, and
// each column's corners make an isosceles trapezoid. Bounded by distance (CellErrorBound::
// planarTwist, and a column filled to its sides taking the bound for corners on its sides), a
// column may be as wide as its bulge allows; bounded at equal parameters, the twist of the
// trapezoid (a quarter of the difference of its parallel sides) keeps it four times narrower.
// Both meshes are within the tolerance as `nurbslod verify` measures it.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeCone.hxx>
#include <cmath>
#include <numbers>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ErrorBudget.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

TEST(FlatCellsByDistance, ConeColumnsAreAsWideAsTheirBulgeAllows) {
    const double smallRadius = 12.0, largeRadius = 13.6, height = 2.26, t = 0.01;
    const TopoDS_Shape shape = BRepPrimAPI_MakeCone(smallRadius, largeRadius, height).Shape();
    const Model model = occ::importModel(shape);
    int side = 0;  // the cone: the face whose loop has four curves (two circles, the seam twice)
    for (std::size_t f = 0; f < model.faces.size(); ++f)
        if (model.faces[f].loops.size() == 1 && model.faces[f].loops[0].curves.size() == 4)
            side = int(f) + 1;
    ASSERT_GT(side, 0);
    auto sideTriangles = [&](bool byDistance) {
        TessellationOptions options;
        options.tolerance = t;
        options.flatCellsByDistance = byDistance;
        // halvings both ways: even columns (up to 256 a span) would narrow the gap the bound
        // makes to what the columns' count rounds
        options.evenColumns = false;
        const TessellationResult result = tessellateModel(model, options);
        EXPECT_TRUE(result.failures.empty());
        const auto report = occ::verifyMesh(shape, result.mesh, t);
        EXPECT_TRUE(report.pass) << "max dev " << report.maxDev << " cover " << report.maxCover;
        EXPECT_EQ(report.openEdges, 0u);
        std::size_t count = 0;
        for (const auto face : result.mesh.triangleFaces) count += face == side;
        return count;
    };
    const std::size_t byDistance = sideTriangles(true), byParameter = sideTriangles(false);
    // the columns a bulge of the surface share (the whole cone is its own curve use) allows at
    // the larger radius, up to the bound's 1.4 over the bulge, rounded up to halvings of the turn
    const ErrorBudget whole = ErrorBudget::forChordsOnSurface(t, ErrorMode::Guaranteed);
    const double widest = 2 * std::acos(1 - whole.surface / 1.4 / largeRadius);
    const double columns = std::exp2(std::ceil(std::log2(2 * std::numbers::pi / widest)));
    EXPECT_LE(double(byDistance), 2 * columns + 8) << byDistance << " triangles on the side";
    EXPECT_GE(double(byParameter), 3.5 * double(byDistance)) << byParameter << " vs " << byDistance;
}

}  // namespace
}  // namespace nurbslod
