#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeSphere.hxx>
#include <cstdio>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

struct Measured {
    std::size_t triangles = 0;
    double maxDeviation = 0;  // of the tolerance, both ways
    bool pass = false;
};

Measured tessellateAndVerify(const TopoDS_Shape& shape, double relative) {
    Model model = occ::importModel(shape);
    TessellationOptions options;
    options.tolerance = relative * model.boundingBoxDiagonal;
    options.mode = ErrorMode::Guaranteed;
    const auto result = tessellateModel(model, options);
    EXPECT_TRUE(result.failures.empty());
    const auto report = occ::verifyMesh(shape, result.mesh, result.tolerance);
    return {result.mesh.triangles.size(),
            std::max(report.maxDev, report.maxCover) / result.tolerance, report.pass};
}

// Cells inside the trimmed region spend the surface share and the trimming and gap shares,
// which they do not need (0.95 of the tolerance instead of 0.6): a sphere's cells
// are nearly all inside, so the triangles drop while the deviation measured both ways
// stays within the tolerance. The limit sits between the count with the surface share only
// (10552 at relative 1e-3) and the one with the whole-cell target (6292).
TEST(FullCellBudget, WholeCellsSpendTheTrimmingShareToo) {
    const struct {
        const char* name;
        TopoDS_Shape shape;
        std::size_t mostTriangles;
    } cases[] = {
        {"sphere", BRepPrimAPI_MakeSphere(10).Shape(), 8000},
    };
    for (const auto& c : cases) {
        const Measured m = tessellateAndVerify(c.shape, 1e-3);
        std::printf("%s: %zu triangles, deviation %.3f of T\n", c.name, m.triangles,
                    m.maxDeviation);
        EXPECT_TRUE(m.pass) << c.name;
        EXPECT_LE(m.maxDeviation, 0.95) << c.name;
        EXPECT_LE(m.triangles, c.mostTriangles) << c.name;
    }
}

}  // namespace
}  // namespace nurbslod
