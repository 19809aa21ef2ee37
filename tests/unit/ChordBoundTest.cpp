#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "geometry/SegmentDistance.hpp"
#include "trim/CurveOnSurface.hpp"

namespace nurbslod {
namespace {

// A parabola drawn on a plane, (t, a t (1 - t)), is a polynomial curve of degree 2 (the plane
// is affine in u and v), which the interpolant represents exactly: its largest distance
// from the chord is a / 4 at t = 1/2. The whole net's middle point is a / 3 off; the net of the
// two halves measures the distance itself.
TEST(ChordBound, ParabolaOnAPlaneIsBoundedByItsSagitta) {
    const BSplineSurface plane(KnotVector(1, {0, 0, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 2, 2,
                               {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 2, 0, 1),
                                HomogeneousPoint3(2, 0, 0, 1), HomogeneousPoint3(2, 2, 0, 1)});
    const double a = 0.8;
    const BSplineCurve2d parabola(
        KnotVector(2, {0, 0, 0, 1, 1, 1}),
        {HomogeneousPoint2(0, 0, 1), HomogeneousPoint2(0.5, a / 2, 1), HomogeneousPoint2(1, 0, 1)});
    const CurveOnSurface curve(plane, parabola, 0, 1);
    const double sagitta = 2 * a / 4;  // the plane doubles (u, v)
    const ChordBound bound = chordBound(curve, 0, 1);
    EXPECT_LT(bound.residual, 1e-12);
    EXPECT_GE(bound.bound, sagitta - 1e-12);
    EXPECT_LE(bound.bound, 1.01 * sagitta);
    // a piece: over [0, 1/2] the parabola is a quarter of the whole's sagitta off its chord,
    // measured across the chord, whose slope is a / 2
    const double quarter = sagitta / 4 / std::sqrt(1 + a * a / 4);
    const ChordBound half = chordBound(curve, 0, 0.5);
    EXPECT_GE(half.bound, quarter - 1e-12);
    EXPECT_LE(half.bound, 1.01 * quarter);
}

// The points a whole piece's bound evaluated serve its halves (CurvePoints): the same bounds,
// to the bit, as evaluating afresh, and the left half evaluates none of its samples again.
TEST(ChordBound, HalvesReuseTheirParentsPoints) {
    const BSplineSurface surface(
        KnotVector(2, {0, 0, 0, 1, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 3, 2,
        {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 1, 0.2, 1),
         HomogeneousPoint3(0.7, 0, 0.9, 0.7), HomogeneousPoint3(1, 1, 1, 1),
         HomogeneousPoint3(2, 0, 0, 1), HomogeneousPoint3(2, 1, 0.3, 1)});
    const BSplineCurve2d arc(KnotVector(2, {0, 0, 0, 1, 1, 1}),
                             {HomogeneousPoint2(0, 0.1, 1), HomogeneousPoint2(0.35, 0.9, 0.7),
                              HomogeneousPoint2(1, 0.2, 1)});
    const CurveOnSurface curve(surface, arc, 0, 1);
    std::size_t evaluations = 0;
    CurvePoints points(curve, &evaluations);
    std::vector<std::pair<double, double>> pieces{{0, 1}, {0, 0.5}, {0.5, 1}, {0, 0.25}};
    std::vector<std::size_t> after;
    for (const auto& [s0, s1] : pieces) {
        const ChordBound cached = chordBound(points, s0, s1);
        const ChordBound fresh = chordBound(curve, s0, s1);
        EXPECT_EQ(cached.bound, fresh.bound) << s0 << " " << s1;
        EXPECT_EQ(cached.residual, fresh.residual) << s0 << " " << s1;
        after.push_back(evaluations);
    }
    const int n = std::min(curve.bezierDegree(), kMaxChordDegree);
    EXPECT_EQ(after[0], static_cast<std::size_t>(2 * n + 1));
    // [0, 1/2]: its samples are the whole's samples and midpoints; only its midpoints are new
    EXPECT_EQ(after[1] - after[0], static_cast<std::size_t>(n));
    EXPECT_EQ(after[3] - after[2], static_cast<std::size_t>(n));
}

// A rational arc on a rational biquadratic patch is a curve of degree 6 over a rational
// weight, above the interpolant's cap (kMaxChordDegree). Wherever the bound would be taken as
// it is (a residual within a quarter of it, as flatEnough asks of the chord's share), the curve
// must lie within it of the chord, and not far inside it: checked at 2001 points of every piece
// of the first eight halvings, from the whole arc (residual large) to 1/256 of it.
TEST(ChordBound, CappedDegreeStillBoundsAHigherDegreeCurve) {
    const BSplineSurface surface(
        KnotVector(2, {0, 0, 0, 1, 1, 1}), KnotVector(2, {0, 0, 0, 1, 1, 1}), 3, 3,
        {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 0.5, 0.4, 0.8),
         HomogeneousPoint3(0, 1, 0, 1), HomogeneousPoint3(0.4, 0, 0.6, 0.6),
         HomogeneousPoint3(0.5, 0.5, 1.2, 1.3), HomogeneousPoint3(0.5, 1, -0.2, 0.9),
         HomogeneousPoint3(1, 0, 0.1, 1), HomogeneousPoint3(1, 0.5, -0.5, 0.7),
         HomogeneousPoint3(1, 1, 0.3, 1)});
    const BSplineCurve2d arc(KnotVector(2, {0, 0, 0, 1, 1, 1}),
                             {HomogeneousPoint2(0.05, 0.1, 1), HomogeneousPoint2(0.3, 0.9, 0.6),
                              HomogeneousPoint2(0.95, 0.2, 1)});
    const CurveOnSurface curve(surface, arc, 0, 1);
    ASSERT_GT(curve.bezierDegree(), kMaxChordDegree);
    int accepted = 0;
    for (int level = 0; level <= 8; ++level) {
        const int pieces = 1 << level;
        for (int k = 0; k < pieces; ++k) {
            const double s0 = double(k) / pieces, s1 = double(k + 1) / pieces;
            const ChordBound bound = chordBound(curve, s0, s1);
            if (bound.residual > 0.25 * bound.bound) continue;
            ++accepted;
            const Point3 a = curve.point(s0), b = curve.point(s1);
            double farthest = 0;
            for (int i = 0; i <= 2000; ++i)
                farthest = std::max(
                    farthest, distanceToSegment(curve.point(s0 + (s1 - s0) * i / 2000), a, b));
            EXPECT_LE(farthest, bound.bound) << s0 << " " << s1;
            // and not far above it: the quarters' hull hugs the curve
            EXPECT_GE(farthest, 0.5 * bound.bound) << s0 << " " << s1;
        }
    }
    EXPECT_GT(accepted, 400);
}

}  // namespace
}  // namespace nurbslod
