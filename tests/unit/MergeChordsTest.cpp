// An edge's points thinned to the chords its whole trimming share allows (mergeChords): the
// midpoint subdivision stops anywhere between a quarter and all of the bound, and the paper's
// simplification merges little on evenly bent curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "trim/EdgeDiscretizer.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {
namespace {

// The distance from p to the segment [a, b].
double distanceToSegment(const Point3& p, const Point3& a, const Point3& b) {
    const Point3 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * d)).norm();
}

class QuarterCircleOnPlane : public ::testing::Test {
protected:
    static constexpr double w = 0.70710678118654752;
    static constexpr double r = 0.9;
    // the plane z = 0 over [0, 1]^2, (u, v) -> (u, v, 0)
    const BSplineSurface plane{KnotVector(1, {0, 0, 1, 1}),
                               KnotVector(1, {0, 0, 1, 1}),
                               2,
                               2,
                               {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 1, 0, 1),
                                HomogeneousPoint3(1, 0, 0, 1), HomogeneousPoint3(1, 1, 0, 1)}};
    // a quarter circle of radius r about (0, 0), exact (rational quadratic)
    const BSplineCurve2d arc{
        KnotVector(2, {0, 0, 0, 1, 1, 1}),
        {HomogeneousPoint2(r, 0, 1), HomogeneousPoint2(r* w, r* w, w), HomogeneousPoint2(0, r, 1)}};
    const std::vector<CurveOnSurface> uses{CurveOnSurface(plane, arc, 0, 1)};
};

TEST_F(QuarterCircleOnPlane, MergedChordsAreFewerAndWithinTheWholeShare) {
    for (const double share : {1e-3, 3e-4, 1e-5}) {
        const double approximation = 0.75 * share, simplification = 0.25 * share;
        const auto halved = discretizeEdge(uses, approximation, simplification);
        const auto merged = mergeChords(uses, halved, approximation, simplification);
        const auto longest = discretizeEdgeByLongestChords(uses, approximation, simplification);
        ASSERT_GE(merged.size(), 2u);
        EXPECT_EQ(merged.front(), 0.0);
        EXPECT_EQ(merged.back(), 1.0);
        // only points the subdivision chose, fewer of them, and no fewer than the longest
        // chords the bound allows
        for (double s : merged)
            EXPECT_TRUE(std::binary_search(halved.begin(), halved.end(), s)) << s;
        EXPECT_GE(merged.size(), longest.size()) << "share " << share;
        // every chord within the share of the exact circle, measured: the circle's sag
        double largest = 0;
        for (size_t k = 0; k + 1 < merged.size(); ++k) {
            const Point3 a = uses[0].point(merged[k]), b = uses[0].point(merged[k + 1]);
            for (int i = 1; i < 64; ++i) {
                const double s = merged[k] + (merged[k + 1] - merged[k]) * i / 64.0;
                largest = std::max(largest, distanceToSegment(uses[0].point(s), a, b));
            }
        }
        EXPECT_LE(largest, share) << "share " << share;
        // At 1e-5 the 256 halved chords sag 0.47 of the share, two of them together four times
        // that: nothing merges. Above, they merge and use the share the subdivision alone kept
        // under three quarters.
        if (share < 1e-4) {
            EXPECT_EQ(merged, halved);
            continue;
        }
        EXPECT_LT(merged.size(), halved.size()) << "share " << share;
        EXPECT_GT(largest, 0.75 * share) << "share " << share;
    }
}

// Points already at the bound are kept: nothing merges past it.
TEST_F(QuarterCircleOnPlane, ChordsAtTheBoundStay) {
    const double share = 1e-3;
    const auto longest = discretizeEdgeByLongestChords(uses, 0.75 * share, 0.25 * share);
    EXPECT_EQ(mergeChords(uses, longest, 0.75 * share, 0.25 * share), longest);
    const std::vector<double> ends{0.0, 1.0};
    EXPECT_EQ(mergeChords(uses, ends, 0.75 * share, 0.25 * share), ends);
}

// The points evaluated for the subdivision serve the merging (and a second subdivision) where
// they are handed on: the same parameters, fewer evaluations.
TEST_F(QuarterCircleOnPlane, SharedPointsGiveTheSameChordsWithFewerEvaluations) {
    for (const double share : {1e-3, 1e-5}) {
        const double approximation = 0.75 * share, simplification = 0.25 * share;
        const auto halved = discretizeEdge(uses, approximation, simplification);
        const auto merged = mergeChords(uses, halved, approximation, simplification);
        std::size_t separate = 0, shared = 0;
        {
            std::vector<CurvePoints> first{CurvePoints(uses[0], &separate)};
            discretizeEdge(uses, approximation, simplification, {}, &first);
            std::vector<CurvePoints> second{CurvePoints(uses[0], &separate)};
            mergeChords(uses, halved, approximation, simplification, &second);
        }
        std::vector<CurvePoints> points{CurvePoints(uses[0], &shared)};
        EXPECT_EQ(discretizeEdge(uses, approximation, simplification, {}, &points), halved);
        EXPECT_EQ(mergeChords(uses, halved, approximation, simplification, &points), merged);
        EXPECT_LT(shared, separate) << "share " << share;
    }
}

}  // namespace
}  // namespace nurbslod
