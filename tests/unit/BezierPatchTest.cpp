#include <gtest/gtest.h>

#include <random>

#include "RandomBezierPatch.hpp"
#include "geometry/BezierPatch.hpp"

namespace nurbslod {
namespace {

using testing::randomRationalPatch;

// de Casteljau's point at (s, t): the first corner of the patch restricted to [s, 1] x [t, 1].
Point3 deCasteljauPoint(const BezierPatch& patch, double s, double t) {
    return patch.restricted(s, 1, t, 1).pole3(0, 0);
}

// The Bernstein grid (used by the approximate error measure) and the Bernstein point give the
// points de Casteljau gives, at every grid parameter, for every degree pair the corpus has and
// beyond.
TEST(BezierPatch, GridPointsAndPointsAreDeCasteljauPoints) {
    std::mt19937 random(7);
    for (int degreeU = 1; degreeU <= 11; degreeU += 2)
        for (int degreeV = 1; degreeV <= 9; degreeV += 4) {
            const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
            const int segmentsU = 2 * degreeU, segmentsV = 2 * degreeV + 1;
            const std::vector<Point3> grid = patch.gridPoints(segmentsU, segmentsV);
            ASSERT_EQ(grid.size(), static_cast<size_t>((segmentsU + 1) * (segmentsV + 1)));
            for (int i = 0; i <= segmentsU; ++i)
                for (int j = 0; j <= segmentsV; ++j) {
                    const double s = static_cast<double>(i) / segmentsU,
                                 t = static_cast<double>(j) / segmentsV;
                    const Point3 expected = deCasteljauPoint(patch, s, t);
                    EXPECT_LT((grid[i * (segmentsV + 1) + j] - expected).norm(), 1e-12)
                        << "degrees " << degreeU << " x " << degreeV << " at " << i << ", " << j;
                    EXPECT_LT((patch.point(s, t) - expected).norm(), 1e-12)
                        << "degrees " << degreeU << " x " << degreeV << " at " << i << ", " << j;
                }
        }
}

// Beyond the degrees point() sums on the stack (a surface's limit and one), it still gives the
// point.
TEST(BezierPatch, PointOfAPatchBeyondTheSurfaceDegreeLimit) {
    std::mt19937 random(5);
    const BezierPatch patch = randomRationalPatch(random, 45, 2);
    for (const double s : {0.0, 0.3, 1.0})
        EXPECT_LT((patch.point(s, 0.6) - deCasteljauPoint(patch, s, 0.6)).norm(), 1e-12) << s;
}

// The halves from one de Casteljau triangle per curve are restricted()'s halves to the last
// bit, in both directions (the kd-tree's settling check takes them).
TEST(BezierPatch, HalvesAreTheRestrictedHalvesExactly) {
    std::mt19937 random(13);
    for (int degreeU = 1; degreeU <= 12; degreeU += 3)
        for (int degreeV = 2; degreeV <= 11; degreeV += 3) {
            const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
            for (int direction = 0; direction < 2; ++direction) {
                const auto halves = patch.halves(direction);
                for (int k = 0; k < 2; ++k) {
                    const double a = 0.5 * k, b = 0.5 * (k + 1);
                    const BezierPatch expected = direction == 0 ? patch.restricted(a, b, 0, 1)
                                                                : patch.restricted(0, 1, a, b);
                    ASSERT_EQ(halves[k].degreeU(), degreeU);
                    ASSERT_EQ(halves[k].degreeV(), degreeV);
                    for (int i = 0; i <= degreeU; ++i)
                        for (int j = 0; j <= degreeV; ++j)
                            EXPECT_EQ(halves[k].pole(i, j), expected.pole(i, j))
                                << degreeU << "x" << degreeV << " direction " << direction
                                << " half " << k << " pole " << i << "," << j;
                }
            }
        }
}

// The quarters from shared de Casteljau triangles are restricted()'s quarters to the last bit:
// the kd-tree's cell bounds must not change with the way they are cut.
TEST(BezierPatch, QuartersAreTheRestrictedQuartersExactly) {
    std::mt19937 random(11);
    for (int degreeU = 1; degreeU <= 16; degreeU += 3)
        for (int degreeV = 1; degreeV <= 14; degreeV += 4) {
            const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
            const auto quarters = patch.quarters();
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    const BezierPatch expected =
                        patch.restricted(0.5 * a, 0.5 * (a + 1), 0.5 * b, 0.5 * (b + 1));
                    const BezierPatch& quarter = quarters[2 * a + b];
                    ASSERT_EQ(quarter.degreeU(), degreeU);
                    ASSERT_EQ(quarter.degreeV(), degreeV);
                    for (int i = 0; i <= degreeU; ++i)
                        for (int j = 0; j <= degreeV; ++j)
                            EXPECT_EQ(quarter.pole(i, j), expected.pole(i, j))
                                << degreeU << "x" << degreeV << " quarter " << a << b << " pole "
                                << i << "," << j;
                }
        }
}

// A grid of one parameter per direction is the corner (0, 0).
TEST(BezierPatch, GridOfNoSegmentsIsTheFirstCorner) {
    std::mt19937 random(3);
    const BezierPatch patch = randomRationalPatch(random, 3, 2);
    const std::vector<Point3> grid = patch.gridPoints(0, 0);
    ASSERT_EQ(grid.size(), 1u);
    EXPECT_LT((grid[0] - patch.pole3(0, 0)).norm(), 1e-15);
}

}  // namespace
}  // namespace nurbslod
