// A cylinder's B-spline form (GeomConvert) runs at the angle only at its knots. A face that
// covers a whole turn from a seam between knots has pcurves that end on the border of its turn
// in the file's parameter, but past it on the B-spline: their projections are held on the
// border there and could not be carried over. FreeCAD's IDF library has such a face
// (RLF_7030.stp, an inductor: face 1, a full cylinder from angle -0.67, its circles running
// against its axis). It was converted whole by BRepBuilderAPI_NurbsConvert, 55 ms of the
// model's 60 ms import; its B-spline form is now unwrapped to a quarter turn beyond its pcurves
// and its edges keep their circles' exact rational form.
#include <gtest/gtest.h>

#include "SampleModels.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

TEST(SeamOffKnot, FullCylinderFromASeamBetweenKnotsKeepsItsCircles) {
    const auto sample = test::sampleModel(test::kFreecadIdfLibrary / "RLF_7030.stp");
    if (!sample) GTEST_SKIP() << "FreeCAD's IDF library not found";
    const Model model = occ::importModel(*sample);
    ASSERT_FALSE(model.faces.empty());
    const TrimmedSurface& cylinder = model.faces.front();
    ASSERT_TRUE(cylinder.error.empty()) << cylinder.error;
    // BRepBuilderAPI_NurbsConvert's surface covered the face's turn [-0.67, 5.61] and one more
    // below it; the unwrapped B-spline form reaches a turn beyond it on both sides
    const double low = cylinder.surface.knotsU().first();
    const double high = cylinder.surface.knotsU().last();
    EXPECT_LT(low, -0.67 - 1);
    EXPECT_GT(high, 5.61 + 1);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const TessellationResult result = tessellateModel(model, options);
        EXPECT_TRUE(result.failures.empty()) << "relative " << relative;
        const occ::VerificationReport report =
            occ::verifyMesh(*sample, result.mesh, options.tolerance);
        EXPECT_TRUE(report.pass) << "relative " << relative << ": dev " << report.maxDev
                                 << " cover " << report.maxCover;
    }
}

}  // namespace
}  // namespace nurbslod
