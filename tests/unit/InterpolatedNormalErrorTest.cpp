// The normal error of the display (paper appearance, section 4.1): the normals interpolated
// across each triangle against the exact ones, and the level choice that bounds it.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "SingleFaceMesh.hpp"
#include "lod/FaceLod.hpp"
#include "lod/FaceLodCache.hpp"
#include "lod/InterpolatedNormalError.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::gui {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

using testing::singleFaceMesh;

TEST(InterpolatedNormalError, IsTheAngleOfTheNormalisedInterpolationOfTheCornerNormals) {
    // A flat triangle on a plane whose first corner carries a normal tilted by 8 degrees: the
    // facet normal is exact, the interpolated one is not. The largest error on the 4-step
    // grid is at 3/4 of the way to the tilted corner: atan2(3/4 sin t, 3/4 cos t + 1/4).
    const Model box = occ::importModel(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape());
    const TrimmedSurface& face = box.faces.at(0);
    const BSplineSurface& plane = face.surface;
    const double u0 = plane.knotsU().first(), u1 = plane.knotsU().last();
    const double v0 = plane.knotsV().first(), v1 = plane.knotsV().last();
    const Vector3 exact = (face.reversed ? -1.0 : 1.0) * plane.normal(u0, v0);
    const Vector3 side = exact.unitOrthogonal();
    const double tilt = 8.0 * degree;
    Mesh mesh;
    mesh.parameters = {Point2(u0, v0), Point2(u1, v0), Point2(u0, v1)};
    for (const Point2& uv : mesh.parameters) mesh.positions.push_back(plane.point(uv.x(), uv.y()));
    mesh.normals = {std::cos(tilt) * exact + std::sin(tilt) * side, exact, exact};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangleNormals = {{0, 1, 2}};
    const InterpolatedNormalError error = measureInterpolatedNormalError(mesh, face);
    EXPECT_EQ(error.triangles, 1);
    const double expected =
        std::atan2(0.75 * std::sin(tilt), 0.75 * std::cos(tilt) + 0.25) / degree;
    EXPECT_NEAR(error.maxDeg, expected, 1e-9);
    // a finer grid gets nearer the tilted corner, and so nearer 8 degrees
    EXPECT_GT(measureInterpolatedNormalError(mesh, face, 12).maxDeg, error.maxDeg);
    // exact corner normals on a plane: no error; a triangle without area is left out
    mesh.normals[0] = exact;
    EXPECT_EQ(measureInterpolatedNormalError(mesh, face).maxDeg, 0.0);
    mesh.normals[0] = std::cos(tilt) * exact + std::sin(tilt) * side;
    mesh.positions[2] = mesh.positions[1];
    EXPECT_EQ(measureInterpolatedNormalError(mesh, face).triangles, 0);
    EXPECT_EQ(measureInterpolatedNormalError(mesh, face).maxDeg, 0.0);
    // no (u, v): nothing to measure against
    mesh.parameters.clear();
    EXPECT_EQ(measureInterpolatedNormalError(mesh, face).maxDeg, 0.0);
}

TEST(InterpolatedNormalError, IsSecondOrderOnASphereWithItsPolesAndSeam) {
    // The sphere's tessellation has fans at both poles and a seam; read with the
    // tessellator's (u, v) as they are, the triangles there would measure up to 180 degrees.
    // The error of the interpolated normal falls with the square of the triangles' size,
    // i.e. in proportion to the tolerance: 16 times the tolerance, at most 0.15 times the
    // error (the facet normal's, first order, would fall to 0.25).
    const Model sphere = occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape());
    ASSERT_EQ(sphere.faces.size(), 1u);
    for (double tolerance : {0.8, 0.4}) {
        const double coarse =
            measureInterpolatedNormalError(singleFaceMesh(sphere, 0, tolerance), sphere.faces[0])
                .maxDeg;
        const double fine = measureInterpolatedNormalError(
                                singleFaceMesh(sphere, 0, tolerance / 16), sphere.faces[0])
                                .maxDeg;
        EXPECT_LT(coarse, 5.0) << tolerance;
        EXPECT_GT(fine, 0.0);
        EXPECT_LT(fine, 0.15 * coarse) << tolerance;
    }
}

TEST(InterpolatedNormalError, TheDefaultGridReadsWithinAFifthOfADenseOne) {
    const Model torus = occ::importModel(BRepPrimAPI_MakeTorus(20.0, 5.0).Shape());
    const Model sphere = occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape());
    for (const Model* model : {&torus, &sphere}) {
        for (double tolerance : {0.5, 0.05}) {
            const Mesh mesh = singleFaceMesh(*model, 0, tolerance);
            const double sampled = measureInterpolatedNormalError(mesh, model->faces[0]).maxDeg;
            const double dense = measureInterpolatedNormalError(mesh, model->faces[0], 12).maxDeg;
            EXPECT_GT(sampled, 0.0);
            EXPECT_LE(sampled, dense + 1e-12);
            EXPECT_LE(dense, 1.2 * sampled) << tolerance;
        }
    }
}

// Plays the display's loop for one face: asks for the level the rule wants until it has it.
int settleNormalLevel(FaceLodCache& cache, int face, double boundDeg, int fromLevel) {
    for (int round = 0; round < 20; ++round) {
        const int wanted = cache.normalErrorLevel(face, boundDeg, fromLevel);
        if (cache.hasLevel(face, wanted)) return wanted;
        cache.request(face, wanted);
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (cache.pendingJobs() > 0 && std::chrono::steady_clock::now() < end)
            cache.waitForFinished(std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
        cache.collectFinished();
    }
    return -1;
}

TEST(NormalErrorLevel, SettlesOnTheCoarsestLevelMeasuredWithinTheBound) {
    FaceLodCache cache(
        std::make_shared<const Model>(occ::importModel(BRepPrimAPI_MakeSphere(10.0).Shape())));
    EXPECT_EQ(cache.normalErrorLevel(0, 0.0, 3), 3);  // off: the screen's level
    for (double bound : {0.2, 0.05}) {
        const int level = settleNormalLevel(cache, 0, bound, 0);
        ASSERT_GE(level, 0) << bound;
        int shown = -1;
        const FaceLod* lod = cache.bestCached(0, level, &shown);
        ASSERT_EQ(shown, level);
        EXPECT_LE(lod->maxNormalErrorDeg, bound);
        EXPECT_GT(lod->maxNormalErrorDeg, 0.0);
        // the level before it, made to see, is over the bound: the choice is the coarsest
        ASSERT_GT(level, 0);
        cache.request(0, level - 1);
        while (cache.pendingJobs() > 0)
            cache.waitForFinished(std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
        cache.collectFinished();
        ASSERT_TRUE(cache.hasLevel(0, level - 1));
        EXPECT_GT(cache.bestCached(0, level - 1, nullptr)->maxNormalErrorDeg, bound) << bound;
        // a finer screen level is kept when it meets the bound too
        EXPECT_EQ(cache.normalErrorLevel(0, bound, level + 1), level + 1);
    }
}

}  // namespace
}  // namespace nurbslod::gui
