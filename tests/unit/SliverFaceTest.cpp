// A face narrower than the weld of points 1e-2 T apart loses every triangle to it, while the
// judges count a face without triangles as missing where its area exceeds T^2. SOD_323.stp of
// FreeCAD's IDF library (a diode package; the freecad package installs it) has faces 1.5e-6 mm
// wide along 1.8 mm edges (faces 15 and 28: area 2.6e-6 against T^2 = 9.9e-8 at relative
// 1e-4), and faces of no area at all, two edges along one curve (16 and 27).
#include <gtest/gtest.h>

#include <algorithm>

#include "SampleModels.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

TEST(SliverFace, KeepsItsOwnTrianglesAndIsMeasured) {
    const auto sample = test::sampleModel(test::kFreecadIdfLibrary / "SOD_323.stp");
    if (!sample) GTEST_SKIP() << "FreeCAD's IDF library not found";
    const TopoDS_Shape& shape = *sample;
    const Model model = occ::importModel(shape);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const TessellationResult result = tessellateModel(model, options);
        const auto hasTriangles = [&](int face) {
            return std::count(result.mesh.triangleFaces.begin(), result.mesh.triangleFaces.end(),
                              face) > 0;
        };
        // above T^2 at relative 1e-4 only; at 1e-3 the weld left them none, and they are
        // meshed again alone at a finer tolerance (tessellateModel)
        EXPECT_TRUE(hasTriangles(15)) << "relative " << relative;
        EXPECT_TRUE(hasTriangles(28)) << "relative " << relative;
        const occ::VerificationReport report =
            occ::verifyMesh(shape, result.mesh, options.tolerance);
        EXPECT_TRUE(report.facesMissing.empty()) << "relative " << relative;
        // the faces of no area, where the tessellator's triangles are a sliver, are measured
        // against the face itself
        EXPECT_TRUE(report.facesUnmeasured.empty()) << "relative " << relative;
        EXPECT_TRUE(report.pass) << "relative " << relative << ": dev " << report.maxDev
                                 << " cover " << report.maxCover;
    }
}

}  // namespace
}  // namespace nurbslod
