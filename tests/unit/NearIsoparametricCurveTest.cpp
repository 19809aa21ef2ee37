#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "occ/NearIsoparametricCurve.hpp"
#include "trim/CurveOnSurface.hpp"

namespace nurbslod {
namespace {

// The plane z = 0 over [0, 10] x [0, 10], as a bilinear B-spline over [0, 1] x [0, 1].
BSplineSurface square() {
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i <= 1; ++i)
        for (int j = 0; j <= 1; ++j) poles.emplace_back(10.0 * i, 10.0 * j, 0.0, 1.0);
    return BSplineSurface(KnotVector(1, {0, 0, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 2, 2,
                          std::move(poles));
}

// A cubic from v = 0 to v = 1 along u = 0.5, its inner control points `wobble` to either side
// (in u), as a sloppy file's pcurve fitted loosely to an edge along the line.
TrimCurve wobblyCurve(double wobble) {
    std::vector<HomogeneousPoint2> poles;
    const int count = 8;
    for (int i = 0; i < count; ++i) {
        const double u = 0.5 + (i == 0 || i == count - 1 ? 0 : (i % 2 ? wobble : -wobble));
        poles.emplace_back(u, double(i) / (count - 1), 1.0);
    }
    std::vector<double> knots{0, 0, 0, 0};
    for (int k = 1; k <= count - 4; ++k) knots.push_back(double(k) / (count - 3));
    knots.insert(knots.end(), {1, 1, 1, 1});
    TrimCurve curve;
    curve.pcurve = BSplineCurve2d(KnotVector(3, knots), std::move(poles));
    curve.first = 0;
    curve.last = 1;
    return curve;
}

TEST(NearIsoparametricCurve, PutsACurveWithinItsToleranceOntoTheLine) {
    const BSplineSurface surface = square();
    TrimCurve curve = wobblyCurve(1e-3);  // 0.01 off the line at most, in space
    EXPECT_FALSE(CurveOnSurface(surface, curve.pcurve, 0, 1).straightInParameterPlane());
    const double moved = occ::straightenNearIsoparametric(surface, curve, 0.02);
    EXPECT_GT(moved, 0);
    EXPECT_LE(moved, 0.02);
    EXPECT_TRUE(CurveOnSurface(surface, curve.pcurve, 0, 1).straightInParameterPlane());
    for (const auto& pole : curve.pcurve.poles()) EXPECT_DOUBLE_EQ(pole.x() / pole.z(), 0.5);
    // the file's curve is kept for the points the edge's faces share
    ASSERT_TRUE(curve.beforeStraightening.has_value());
    EXPECT_NE(curve.beforeStraightening->poles()[1].x(), 0.5);
}

TEST(NearIsoparametricCurve, LeavesACurveFartherThanItsToleranceAsItIs) {
    const BSplineSurface surface = square();
    TrimCurve curve = wobblyCurve(1e-3);
    const auto before = curve.pcurve.poles();
    EXPECT_EQ(occ::straightenNearIsoparametric(surface, curve, 0.001), 0);
    EXPECT_EQ(curve.pcurve.poles(), before);
    EXPECT_FALSE(curve.beforeStraightening.has_value());
    // nor a seam or a pole, nor with a tolerance of 0 or NaN
    TrimCurve seam = wobblyCurve(1e-3);
    seam.seam = true;
    EXPECT_EQ(occ::straightenNearIsoparametric(surface, seam, 1.0), 0);
    EXPECT_EQ(occ::straightenNearIsoparametric(surface, curve, 0.0), 0);
    EXPECT_EQ(occ::straightenNearIsoparametric(surface, curve, std::nan("")), 0);
    EXPECT_FALSE(curve.beforeStraightening.has_value());
}

}  // namespace
}  // namespace nurbslod
