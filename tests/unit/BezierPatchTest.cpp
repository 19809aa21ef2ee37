#include <gtest/gtest.h>

#include <random>

#include "RandomBezierPatch.hpp"
#include "geometry/BezierPatch.hpp"

namespace nurbslod {
namespace {

using testing::randomRationalPatch;

// The Bernstein grid (used by the approximate error measure) gives the points de Casteljau
// gives, at every grid parameter, for every degree pair the corpus has and beyond.
TEST(BezierPatch, GridPointsAreDeCasteljauPoints) {
    std::mt19937 random(7);
    for (int degreeU = 1; degreeU <= 11; degreeU += 2)
        for (int degreeV = 1; degreeV <= 9; degreeV += 4) {
            const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
            const int segmentsU = 2 * degreeU, segmentsV = 2 * degreeV + 1;
            const std::vector<Point3> grid = patch.gridPoints(segmentsU, segmentsV);
            ASSERT_EQ(grid.size(), static_cast<size_t>((segmentsU + 1) * (segmentsV + 1)));
            for (int i = 0; i <= segmentsU; ++i)
                for (int j = 0; j <= segmentsV; ++j) {
                    const Point3 expected = patch.point(static_cast<double>(i) / segmentsU,
                                                        static_cast<double>(j) / segmentsV);
                    EXPECT_LT((grid[i * (segmentsV + 1) + j] - expected).norm(), 1e-12)
                        << "degrees " << degreeU << " x " << degreeV << " at " << i << ", " << j;
                }
        }
}

// A grid of one parameter per direction is the corner (0, 0).
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

TEST(BezierPatch, GridOfNoSegmentsIsTheFirstCorner) {
    std::mt19937 random(3);
    const BezierPatch patch = randomRationalPatch(random, 3, 2);
    const std::vector<Point3> grid = patch.gridPoints(0, 0);
    ASSERT_EQ(grid.size(), 1u);
    EXPECT_LT((grid[0] - patch.pole3(0, 0)).norm(), 1e-15);
}

}  // namespace
}  // namespace nurbslod
