// Pole rows of degenerated edges: a surface row a sloppy file leaves spread is collapsed onto
// the pole the B-rep declares, and the display's normals there stay within the bound.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <cmath>
#include <filesystem>

#include "SingleFaceMesh.hpp"
#include "lod/CollapsedCornerNormals.hpp"
#include "lod/CollapsedPoleRows.hpp"
#include "lod/FaceLod.hpp"
#include "lod/InterpolatedNormalError.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"

namespace nurbslod::gui {
namespace {

constexpr double boundDeg = 1.0;

// A sphere of radius 10 whose north pole row (v = last) is spread along x over `spread`, like
// the 0.0013 mm row of corpus trj7 faces 170 and 174, with vertex tolerances `tolerance`.
Model sphereWithSpreadPole(double spread, double tolerance) {
    Model model = occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape());
    BSplineSurface& surface = model.faces.at(0).surface;
    const int row = surface.countV() - 1;
    for (int i = 0; i < surface.countU(); ++i) {
        HomogeneousPoint3& pole = surface.pole(i, row);
        const double weight = pole[3];
        Point3 point = projectHomogeneous(pole);
        point.x() += spread * (double(i) / (surface.countU() - 1) - 0.5);
        pole << weight * point, weight;
    }
    for (ModelVertex& vertex : model.vertices) vertex.tolerance = tolerance;
    return model;
}

TEST(CollapsedPoleRows, ASpreadRowUnderADegeneratedEdgeBecomesThePole) {
    const double spread = 1e-3;
    const Model model = sphereWithSpreadPole(spread, 2 * spread);
    const TrimmedSurface& face = model.faces[0];
    int rows = -1;
    const TrimmedSurface collapsed = withPoleRowsCollapsed(model, face, &rows);
    EXPECT_EQ(rows, 1);
    const BSplineSurface& before = face.surface;
    const BSplineSurface& after = collapsed.surface;
    const int last = before.countV() - 1;
    for (int i = 0; i < before.countU(); ++i) {
        for (int j = 0; j < before.countV(); ++j) {
            EXPECT_DOUBLE_EQ(after.pole(i, j)[3], before.pole(i, j)[3]);  // weights kept
            if (j != last) {
                EXPECT_EQ(after.pole(i, j), before.pole(i, j));
            }
        }
        EXPECT_LT(
            (projectHomogeneous(after.pole(i, last)) - projectHomogeneous(after.pole(0, last)))
                .norm(),
            1e-12);
    }
    // the surface moves by no more than the spread
    for (double s = 0; s <= 1; s += 0.125)
        for (double t = 0; t <= 1; t += 0.125) {
            const double u =
                before.knotsU().first() + s * (before.knotsU().last() - before.knotsU().first());
            const double v =
                before.knotsV().first() + t * (before.knotsV().last() - before.knotsV().first());
            EXPECT_LE((after.point(u, v) - before.point(u, v)).norm(), spread);
        }
}

TEST(CollapsedPoleRows, RowsBeyondTheToleranceTruePolesAndOtherFacesAreLeftAsTheyAre) {
    int rows = -1;
    // spread wider than the vertex's tolerance: the B-rep does not call that a point
    const Model wide = sphereWithSpreadPole(1e-3, 1e-4);
    const TrimmedSurface kept = withPoleRowsCollapsed(wide, wide.faces[0], &rows);
    EXPECT_EQ(rows, 0);
    EXPECT_EQ(kept.surface.poles(), wide.faces[0].surface.poles());
    // true poles (a sphere's, a cone's tip) and faces without degenerated edges
    for (const Model& model : {occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape()),
                               occ::importModel(BRepPrimAPI_MakeCone(5.0, 0.0, 10.0).Shape()),
                               occ::importModel(BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape())}) {
        for (const TrimmedSurface& face : model.faces) {
            const TrimmedSurface same = withPoleRowsCollapsed(model, face, &rows);
            EXPECT_EQ(rows, 0) << "face " << face.faceIndex;
            EXPECT_EQ(same.surface.poles(), face.surface.poles());
        }
    }
}

TEST(CollapsedPoleRows, TheDisplayedNormalsOfASpreadPoleStayWithinTheBound) {
    const Model model = sphereWithSpreadPole(1e-3, 2e-3);
    for (int level = 0; level <= 2; ++level) {
        const double tolerance = 1e-2 * model.boundingBoxDiagonal * std::ldexp(1.0, -level);
        // on the file's surface the normals twist round the spread row (178 degrees measured)
        Mesh mesh = testing::singleFaceMesh(model, 0, tolerance);
        takeCollapsedCornerNormalsInside(mesh, model.faces[0]);
        EXPECT_GT(measureInterpolatedNormalError(mesh, model.faces[0]).maxDeg, 30.0);
        const FaceLodResult result = tessellateFaceLod(model, 0, tolerance);
        ASSERT_TRUE(result.lod) << result.failure;
        EXPECT_LE(result.lod->maxNormalErrorDeg, boundDeg) << "level " << level;
    }
}

TEST(CollapsedPoleRows, CorpusTrj7Faces170And174MeetTheBound) {
    // Both end in a degenerated edge whose surface row is 0.0013 mm long (vertex tolerance
    // 0.14 mm). Measured on the file's surface, face 170 was 17.8 degrees over at level 11,
    // the level the display settled on at the fitted view; now the display settles on level 7
    // (268 triangles, was 3945). From level 10 on every level is within the bound; 174 reads
    // 1.03 at level 9, where the cache goes one level finer.
    const std::filesystem::path path =
        std::filesystem::path(NURBSLOD_CORPUS_DIR) / "trj7_b1-ec-214.stp";
    if (!std::filesystem::is_regular_file(path)) GTEST_SKIP() << "corpus not found at " << path;
    const Model model = occ::importModel(occ::readShape(path.string()));
    ASSERT_GE(model.faces.size(), 174u);
    for (int face : {170, 174}) {
        int rows = 0;
        withPoleRowsCollapsed(model, model.faces[static_cast<std::size_t>(face - 1)], &rows);
        EXPECT_EQ(rows, 1) << "face " << face;
        for (int level : {7, 10, 11, 12}) {
            const double tolerance = 1e-2 * model.boundingBoxDiagonal * std::ldexp(1.0, -level);
            const FaceLodResult result = tessellateFaceLod(model, face - 1, tolerance);
            ASSERT_TRUE(result.lod) << result.failure;
            EXPECT_LE(result.lod->maxNormalErrorDeg, boundDeg)
                << "face " << face << " level " << level;
        }
    }
}

}  // namespace
}  // namespace nurbslod::gui
