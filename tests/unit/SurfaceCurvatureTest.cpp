#include <gtest/gtest.h>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "geometry/SurfaceCurvature.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"

namespace nurbslod {
namespace {

Vector3 toVector(const gp_Vec& v) {
    return {v.X(), v.Y(), v.Z()};
}
Vector3 toVector(const gp_Dir& v) {
    return {v.X(), v.Y(), v.Z()};
}

// A wavy rational surface of the given degrees on non-uniform knots; `middleMultiplicity`
// repeats the middle knot of each direction (degree 3 with 2: a C1 joint).
Handle(Geom_BSplineSurface)
    wavySurface(int degreeU, int degreeV, int middleMultiplicity, bool rational, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> height(-0.4, 0.4), weight(0.5, 2.0);
    auto knots = [&](int degree, TColStd_Array1OfReal& values, TColStd_Array1OfInteger& mults) {
        const double inner[] = {0.0, 0.3, 0.55, 1.4};  // non-uniform on purpose
        for (int i = 1; i <= 4; ++i) {
            values(i) = inner[i - 1];
            mults(i) = (i == 1 || i == 4) ? degree + 1 : (i == 2 ? middleMultiplicity : 1);
        }
    };
    TColStd_Array1OfReal knotsU(1, 4), knotsV(1, 4);
    TColStd_Array1OfInteger multsU(1, 4), multsV(1, 4);
    knots(degreeU, knotsU, multsU);
    knots(degreeV, knotsV, multsV);
    const int countU = degreeU + 1 + middleMultiplicity + 1;
    const int countV = degreeV + 1 + middleMultiplicity + 1;
    TColgp_Array2OfPnt poles(1, countU, 1, countV);
    TColStd_Array2OfReal weights(1, countU, 1, countV);
    for (int i = 1; i <= countU; ++i)
        for (int j = 1; j <= countV; ++j) {
            poles(i, j) = gp_Pnt(2.0 * i + 0.1 * j, 1.5 * j, height(random) + 0.2 * i * j);
            weights(i, j) = rational ? weight(random) : 1.0;
        }
    return new Geom_BSplineSurface(poles, weights, knotsU, knotsV, multsU, multsV, degreeU,
                                   degreeV);
}

// Compares our derivatives and curvature with OpenCASCADE's at (u, v) (issue: 1e-9 relative).
// Returns false where OpenCASCADE has no curvature there (the point is not counted).
bool agreesWithOpenCascade(const Handle(Geom_BSplineSurface) & occSurface,
                           const BSplineSurface& ours, double u, double v) {
    gp_Pnt p;
    gp_Vec du, dv, duu, dvv, duv;
    occSurface->D2(u, v, p, du, dv, duu, dvv, duv);
    const SurfaceSecondDerivatives d = secondDerivatives(ours, u, v);
    const double size = std::max(1.0, toVector(gp_Vec(p.XYZ())).norm());
    EXPECT_LE((d.point - Vector3(p.X(), p.Y(), p.Z())).norm(), 1e-9 * size);
    auto expectNear = [&](const Vector3& mine, const gp_Vec& theirs, const char* what) {
        const double scale = std::max(toVector(theirs).norm(), 1e-300);
        EXPECT_LE((mine - toVector(theirs)).norm(), 1e-9 * scale)
            << what << " at (" << u << ", " << v << ")";
    };
    expectNear(d.du, du, "du");
    expectNear(d.dv, dv, "dv");
    // second derivatives are small beside the first ones on a flat-ish patch: compare them on
    // the scale of the surface's size, which is what the curvature sees
    const double secondScale =
        std::max({toVector(duu).norm(), toVector(dvv).norm(), toVector(duv).norm(),
                  toVector(du).norm() * toVector(du).norm() / size});
    EXPECT_LE((d.duu - toVector(duu)).norm(), 1e-9 * secondScale) << "duu at " << u << ", " << v;
    EXPECT_LE((d.dvv - toVector(dvv)).norm(), 1e-9 * secondScale) << "dvv at " << u << ", " << v;
    EXPECT_LE((d.duv - toVector(duv)).norm(), 1e-9 * secondScale) << "duv at " << u << ", " << v;

    GeomLProp_SLProps props(occSurface, u, v, 2, 1e-12);
    const auto c = curvatureAt(ours, u, v);
    if (!props.IsCurvatureDefined()) return false;
    EXPECT_TRUE(c.has_value()) << "no curvature at (" << u << ", " << v << ")";
    if (!c) return false;
    EXPECT_LE((c->normal - toVector(props.Normal())).norm(), 1e-9);
    const double scale = std::max({std::abs(props.MaxCurvature()), std::abs(props.MinCurvature()),
                                   1 / size});  // a flat face: relative to the part
    EXPECT_LE(std::abs(c->maximum - props.MaxCurvature()), 1e-9 * scale) << u << ", " << v;
    EXPECT_LE(std::abs(c->minimum - props.MinCurvature()), 1e-9 * scale) << u << ", " << v;
    EXPECT_LE(std::abs(c->mean - props.MeanCurvature()), 1e-9 * scale) << u << ", " << v;
    EXPECT_LE(std::abs(c->gaussian - props.GaussianCurvature()), 1e-9 * scale * scale)
        << u << ", " << v;
    if (c->maximum - c->minimum > 1e-3 * scale) {  // directions are defined off umbilics
        gp_Dir maxDirection, minDirection;
        props.CurvatureDirections(maxDirection, minDirection);
        EXPECT_GE(std::abs(c->maximumDirection.dot(toVector(maxDirection))), 1 - 1e-9);
        EXPECT_GE(std::abs(c->minimumDirection.dot(toVector(minDirection))), 1 - 1e-9);
    }
    return true;
}

void checkGrid(const Handle(Geom_BSplineSurface) & occSurface, int steps) {
    const BSplineSurface ours = occ::toBSplineSurface(occSurface);
    double u0, u1, v0, v1;
    occSurface->Bounds(u0, u1, v0, v1);
    int compared = 0;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; j <= steps; ++j) {
            // off the knots: at a C1 knot the second derivative has two sides, and which one
            // an evaluator takes is a convention, not a value to compare
            const double u = u0 + (u1 - u0) * (i + 0.37) / (steps + 1);
            const double v = v0 + (v1 - v0) * (j + 0.61) / (steps + 1);
            compared += agreesWithOpenCascade(occSurface, ours, u, v);
        }
    EXPECT_GT(compared, (steps + 1) * (steps + 1) / 2);
}

TEST(SurfaceCurvature, AgreesWithOpenCascadeOnRationalBicubic) {
    checkGrid(wavySurface(3, 3, 1, true, 1), 12);
}

TEST(SurfaceCurvature, AgreesWithOpenCascadeOnMixedDegreesAndDoubleKnot) {
    checkGrid(wavySurface(3, 2, 2, true, 2), 12);
    checkGrid(wavySurface(5, 4, 3, false, 3), 8);
    checkGrid(wavySurface(1, 2, 1, true, 4), 8);  // degree 1: no second derivative in u
}

Handle(Geom_BSplineSurface) sphereSurface(double radius) {
    const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(radius).Shape();
    BRepBuilderAPI_NurbsConvert converter(sphere, Standard_False);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(converter.Shape(), TopAbs_FACE, faces);
    return occ::faceSurfaceAsBSpline(TopoDS::Face(faces(1)));
}

// The rational sphere has curvature 1/R in every direction; du x dv points outwards, so the
// surface bends away from the normal: -1/R.
TEST(SurfaceCurvature, SphereIsUmbilicWithRadiusCurvature) {
    const double radius = 2.5;
    const auto occSurface = sphereSurface(radius);
    checkGrid(occSurface, 10);
    const BSplineSurface ours = occ::toBSplineSurface(occSurface);
    double u0, u1, v0, v1;
    occSurface->Bounds(u0, u1, v0, v1);
    for (double s : {0.1, 0.33, 0.5, 0.8}) {
        const auto c = curvatureAt(ours, u0 + s * (u1 - u0), v0 + (1 - s) * (v1 - v0));
        ASSERT_TRUE(c.has_value());
        const double sign = c->mean < 0 ? -1 : 1;
        EXPECT_NEAR(c->minimum, sign / radius, 1e-9);
        EXPECT_NEAR(c->maximum, sign / radius, 1e-9);
        EXPECT_NEAR(c->gaussian, 1 / (radius * radius), 1e-9);
        EXPECT_NEAR(c->minimumDirection.dot(c->normal), 0, 1e-12);
        EXPECT_NEAR(c->maximumDirection.dot(c->normal), 0, 1e-12);
    }
}

// At a pole du vanishes: no curvature there, and the display takes the limit from inside.
TEST(SurfaceCurvature, PoleHasNoCurvatureButDisplayTakesTheLimit) {
    const double radius = 2.5;
    const auto occSurface = sphereSurface(radius);
    const BSplineSurface ours = occ::toBSplineSurface(occSurface);
    double u0, u1, v0, v1;
    occSurface->Bounds(u0, u1, v0, v1);
    bool sawPole = false;
    for (double v : {v0, v1}) {
        const double u = 0.5 * (u0 + u1);
        if (curvatureAt(ours, u, v)) continue;
        sawPole = true;
        const SurfaceCurvature c = displayCurvature(ours, u, v);
        EXPECT_NEAR(c.gaussian, 1 / (radius * radius), 1e-4);
        EXPECT_NEAR(std::abs(c.mean), 1 / radius, 1e-4);
    }
    EXPECT_TRUE(sawPole) << "the converted sphere should have a collapsed row of poles";
}

// Bad parameters give no curvature (and no crash); the display falls back to flat.
TEST(SurfaceCurvature, NotANumberParameterGivesNoCurvature) {
    const BSplineSurface ours = occ::toBSplineSurface(wavySurface(3, 3, 1, true, 5));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(curvatureAt(ours, nan, 0.5).has_value());
    const SurfaceCurvature c = displayCurvature(ours, nan, nan);
    EXPECT_TRUE(std::isfinite(c.gaussian) && std::isfinite(c.mean));
}

// Every corpus face that OpenCASCADE can give a curvature to agrees with ours.
TEST(SurfaceCurvature, AgreesWithOpenCascadeOnCorpusFaces) {
    const std::filesystem::path corpus = NURBSLOD_CORPUS_DIR;
    if (!std::filesystem::is_directory(corpus)) GTEST_SKIP() << "corpus not found at " << corpus;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    int compared = 0;
    for (const char* name : {"wing.brep", "bug28366_fuselage.stp", "bug3883_xr2-ct-214_bolt.stp"}) {
        const auto path = corpus / name;
        if (!std::filesystem::exists(path)) continue;
        BRepBuilderAPI_NurbsConvert converter(occ::readShape(path.string()), Standard_False);
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(converter.Shape(), TopAbs_FACE, faces);
        for (int k = 1; k <= faces.Extent(); ++k) {
            const auto occSurface = occ::faceSurfaceAsBSpline(TopoDS::Face(faces(k)));
            if (occSurface.IsNull()) continue;
            const BSplineSurface ours = occ::toBSplineSurface(occSurface);
            double u0, u1, v0, v1;
            occSurface->Bounds(u0, u1, v0, v1);
            for (int n = 0; n < 5; ++n)
                compared += agreesWithOpenCascade(occSurface, ours, u0 + unit(random) * (u1 - u0),
                                                  v0 + unit(random) * (v1 - v0));
        }
    }
    if (compared == 0) GTEST_SKIP() << "no corpus model found";
    RecordProperty("compared", compared);
    EXPECT_GT(compared, 50);
}

}  // namespace
}  // namespace nurbslod
