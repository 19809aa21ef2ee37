#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "trim/CurveOnSurface.hpp"

namespace nurbslod {
namespace {

// A parabola drawn on a plane, (t, a t (1 - t)), is a polynomial curve that the degree-4 Bezier
// of its surface (degree 1 x 1) and pcurve (degree 2) represents exactly: its largest distance
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
    const int n = std::min(curve.bezierDegree(), 9);
    EXPECT_EQ(after[0], static_cast<std::size_t>(2 * n + 1));
    // [0, 1/2]: its samples are the whole's samples and midpoints; only its midpoints are new
    EXPECT_EQ(after[1] - after[0], static_cast<std::size_t>(n));
    EXPECT_EQ(after[3] - after[2], static_cast<std::size_t>(n));
}

}  // namespace
}  // namespace nurbslod
