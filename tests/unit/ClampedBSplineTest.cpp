#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>

#include "occ/ClampedBSpline.hpp"
#include "occ/ModelImporter.hpp"

namespace nurbslod {
namespace {

// A tube whose u direction is periodic with a C0 seam: degree 3, closing knot of multiplicity
// 3, as FreeCAD's STEP writer leaves a closed loft of B-spline sections. OCCT's own
// SetUNotPeriodic gives this surface weights 0.
Handle(Geom_BSplineSurface) tubeWithSeam() {
    const int rows = 6;
    TColgp_Array2OfPnt poles(1, rows, 1, 2);
    for (int i = 1; i <= rows; ++i) {
        const double angle = 2 * M_PI * (i - 1) / rows;
        const double radius = 10 + 2 * (i % 2);
        for (int j = 1; j <= 2; ++j)
            poles(i, j) = gp_Pnt(radius * std::cos(angle), radius * std::sin(angle), 15.0 * j);
    }
    TColStd_Array1OfReal uKnots(1, 5), vKnots(1, 2);
    TColStd_Array1OfInteger uMults(1, 5), vMults(1, 2);
    const double u[] = {0, 0.25, 0.5, 0.75, 1};
    const int m[] = {3, 1, 1, 1, 3};
    for (int k = 1; k <= 5; ++k) uKnots(k) = u[k - 1], uMults(k) = m[k - 1];
    vKnots(1) = 0, vKnots(2) = 1, vMults(1) = vMults(2) = 2;
    return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 1, Standard_True,
                                   Standard_False);
}

TEST(ClampedBSpline, PeriodicSurfaceWithSeamKeepsItsPointsAndWeights) {
    const Handle(Geom_BSplineSurface) periodic = tubeWithSeam();
    ASSERT_TRUE(periodic->IsUPeriodic());
    const Handle(Geom_BSplineSurface) clamped = occ::clampedSurface(periodic);
    ASSERT_NE(clamped, periodic);
    EXPECT_TRUE(periodic->IsUPeriodic());  // the input is not modified
    EXPECT_FALSE(clamped->IsUPeriodic());
    EXPECT_EQ(clamped->UMultiplicity(1), 4);
    EXPECT_EQ(clamped->UMultiplicity(clamped->NbUKnots()), 4);
    for (int i = 1; i <= clamped->NbUPoles(); ++i)
        for (int j = 1; j <= clamped->NbVPoles(); ++j) EXPECT_GT(clamped->Weight(i, j), 0);
    for (int a = 0; a <= 40; ++a)
        for (int b = 0; b <= 4; ++b) {
            const double s = a / 40.0, t = b / 4.0;
            EXPECT_LT(clamped->Value(s, t).Distance(periodic->Value(s, t)), 1e-12);
        }
    // and the importer's form of the face is a valid surface with the same points
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(periodic, 1e-7);
    const BSplineSurface imported = occ::toBSplineSurface(occ::faceSurfaceAsBSpline(face));
    EXPECT_FALSE(imported.problem()) << *imported.problem();
}

TEST(ClampedBSpline, ClampedInputIsReturnedAsItIs) {
    const Handle(Geom_BSplineSurface) clamped = occ::clampedSurface(tubeWithSeam());
    EXPECT_EQ(occ::clampedSurface(clamped), clamped);
}

// A periodic pcurve over a range that crosses its period's end (a closed edge starting
// mid-period): the clamped piece runs over that same range with the same points.
TEST(ClampedBSpline, PeriodicCurveOverARangeAcrossItsPeriod) {
    TColgp_Array1OfPnt2d poles(1, 6);
    for (int i = 1; i <= 6; ++i) {
        const double angle = 2 * M_PI * (i - 1) / 6;
        poles(i) = gp_Pnt2d(0.5 + 0.3 * std::cos(angle), 0.5 + 0.2 * std::sin(angle));
    }
    TColStd_Array1OfReal knots(1, 5);
    TColStd_Array1OfInteger mults(1, 5);
    const int m[] = {3, 1, 1, 1, 3};
    for (int k = 1; k <= 5; ++k) knots(k) = (k - 1) * 0.25, mults(k) = m[k - 1];
    const Handle(Geom2d_BSplineCurve) periodic =
        new Geom2d_BSplineCurve(poles, knots, mults, 3, Standard_True);
    ASSERT_TRUE(periodic->IsPeriodic());
    const Handle(Geom2d_BSplineCurve) clamped = occ::clampedCurve(periodic, 0.6, 1.4);
    EXPECT_FALSE(clamped->IsPeriodic());
    EXPECT_NEAR(clamped->FirstParameter(), 0.6, 1e-12);
    EXPECT_NEAR(clamped->LastParameter(), 1.4, 1e-12);
    EXPECT_EQ(clamped->Multiplicity(1), 4);
    EXPECT_EQ(clamped->Multiplicity(clamped->NbKnots()), 4);
    for (int k = 0; k <= 40; ++k) {
        const double s = 0.6 + 0.8 * k / 40;
        EXPECT_LT(clamped->Value(s).Distance(periodic->Value(s)), 1e-12) << s;
    }
}

}  // namespace
}  // namespace nurbslod
