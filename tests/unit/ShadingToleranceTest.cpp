// Appearance-preserving tolerances (paper appearance, section 4.1): the normal error bound
// turned into a distance through the face's maximum curvature, and checked by measuring the
// facet normals of the mesh it gives.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lod/FaceLod.hpp"
#include "lod/FacetNormalError.hpp"
#include "lod/ShadingTolerance.hpp"
#include "occ/ModelImporter.hpp"

namespace nurbslod::gui {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

// The face's mesh at the tolerance, with its measured normal error over the triangles whose
// corners lie on the surface (FacetNormalError says why the others are apart).
double measuredNormalErrorDeg(const Model& model, int face, double tolerance) {
    const FaceLodResult result = tessellateFaceLod(model, face, tolerance);
    if (!result.lod) throw std::runtime_error(result.failure);
    return result.lod->maxNormalErrorInteriorDeg;
}

TEST(ShadingTolerance, ASphereOfRadiusRMeetsTheBoundWhenMeasured) {
    const double radius = 10.0;
    const Model model = occ::importModel(BRepPrimAPI_MakeSphere(radius).Shape());
    ASSERT_EQ(model.faces.size(), 1u);
    // the rational sphere's curvature is 1 / R everywhere, its poles included
    const double curvature = maximumCurvature(model.faces[0]);
    EXPECT_NEAR(curvature, 1.0 / radius, 1e-3 / radius);
    EXPECT_GE(curvature, 1.0 / radius - 1e-12);  // an overestimate only makes it finer
    for (double bound : {2.0, 5.0}) {
        const double tolerance = shadingTolerance(bound * degree, curvature);
        EXPECT_NEAR(tolerance, (1 - std::cos(bound * degree)) / curvature, 1e-15);
        EXPECT_NEAR(tolerance, radius * (1 - std::cos(bound * degree)), 1e-3 * tolerance);
        const double measured = measuredNormalErrorDeg(model, 0, tolerance);
        EXPECT_LE(measured, bound) << "tolerance " << tolerance;
        EXPECT_GT(measured, 0.0);
        // the rule is what keeps the bound: a tolerance 16 times larger misses it
        EXPECT_GT(measuredNormalErrorDeg(model, 0, 16 * tolerance), bound);
    }
}

TEST(ShadingTolerance, ATorusTakesItsTubeCurvatureAndMeetsTheBound) {
    // principal curvatures 1 / r around the tube and cos(phi) / (R + r cos(phi)) along it:
    // the largest is 1 / r
    const double major = 20.0, minor = 5.0;
    const Model model = occ::importModel(BRepPrimAPI_MakeTorus(major, minor).Shape());
    ASSERT_EQ(model.faces.size(), 1u);
    const double curvature = maximumCurvature(model.faces[0]);
    EXPECT_NEAR(curvature, 1.0 / minor, 1e-6);
    const double measured =
        measuredNormalErrorDeg(model, 0, shadingTolerance(5.0 * degree, curvature));
    EXPECT_LE(measured, 5.0);
}

TEST(ShadingTolerance, OffOrFlatMeansNoLimitAndBadInputIsRefused) {
    const double infinity = std::numeric_limits<double>::infinity();
    EXPECT_EQ(shadingTolerance(0.0, 0.1), infinity);
    EXPECT_EQ(shadingTolerance(1.0 * degree, 0.0), infinity);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double angle : {-1.0 * degree, nan, 90.0 * degree, infinity})
        EXPECT_THROW(shadingTolerance(angle, 0.1), std::invalid_argument) << angle;
    for (double curvature : {-0.1, nan, infinity})
        EXPECT_THROW(shadingTolerance(1.0 * degree, curvature), std::invalid_argument) << curvature;
}

TEST(FacetNormalError, IsTheAngleBetweenFacetAndCornerNormals) {
    const BSplineSurface unused;
    Mesh mesh;
    mesh.positions = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(1, 1, 0)};
    const double tilt = 2.0 * degree;
    mesh.normals = {Vector3(0, 0, 1), Vector3(std::sin(tilt), 0, std::cos(tilt))};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangleNormals = {{0, 1, 0}};
    EXPECT_NEAR(measureFacetNormalError(mesh, unused, 0.0).maxDeg, 2.0, 1e-9);
    // a triangle without area has no facet normal, and a T-junction's filler of three nearly
    // collinear vertices (altitude 1e-4) is thinner than the tolerance: both are left out
    mesh.positions.push_back(Point3(2, 1e-4, 0));
    mesh.triangles.push_back({0, 1, 1});
    mesh.triangles.push_back({0, 4, 1});
    mesh.triangleNormals.push_back({1, 1, 1});
    mesh.triangleNormals.push_back({1, 1, 1});
    EXPECT_NEAR(measureFacetNormalError(mesh, unused, 1e-3).maxDeg, 2.0, 1e-9);
    // counted when the tolerance is finer than it is thin
    EXPECT_GT(measureFacetNormalError(mesh, unused, 1e-5).maxDeg, 80.0);
    EXPECT_EQ(measureFacetNormalError(Mesh{}, unused, 0.0).maxDeg, 0.0);
}

}  // namespace
}  // namespace nurbslod::gui
