#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "ParaboloidPatch.hpp"
#include "geometry/BSplineSurface.hpp"
#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "tessellate/TriangleDeviation.hpp"

namespace nurbslod {
namespace {

using testing::unitParaboloid;

// Over the triangle (0, 0), (1/2, 0), (0, 1/2) the paraboloid is 1/8 off the map through its
// corners' points (at (1/4, 1/4)). The hull over the triangle is within twice that (0.15), and
// its cuts close in on 1/8; the hull over the box [0, 1/2]^2 of the same map is larger (1/6),
// since the map leaves the surface faster beyond the triangle.
TEST(TriangleDeviation, ClosesInOnTheTrueDistance) {
    const BezierPatch patch = unitParaboloid();
    const std::array<Point2, 3> triangle{Point2(0, 0), Point2(0.5, 0), Point2(0, 0.5)};
    const std::array<Point3, 3> image{Point3(0, 0, 0), Point3(0.5, 0, 0.25), Point3(0, 0.5, 0.25)};
    const double hull = triangleDeviation(patch, triangle, image, 1.0, 0);
    EXPECT_GE(hull, 0.125 - 1e-12);
    EXPECT_LE(hull, 0.25);
    const double cut = triangleDeviation(patch, triangle, image, 0.13);
    EXPECT_GE(cut, 0.125 - 1e-12);
    EXPECT_LE(cut, 0.13);
    // the box's hull: its piece with the same map at the box's corners
    const BezierPatch box = patch.restricted(0, 0.5, 0, 0.5);
    const double boxHull =
        affineDeviation(box, image[0], image[1], image[2], std::numeric_limits<double>::infinity(),
                        {Point2(0, 0), Point2(1, 0), Point2(0, 1)});
    EXPECT_GT(boxHull, hull);
    // a target the surface is beyond stops with a value over it
    EXPECT_GT(triangleDeviation(patch, triangle, image, 0.1), 0.1);
}

// A bicubic B-spline surface of 4 x 3 spans with uneven knots, bumpy.
BSplineSurface bumpySurface() {
    const KnotVector u(3, {0, 0, 0, 0, 0.2, 0.5, 0.6, 1, 1, 1, 1});
    const KnotVector v(3, {0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1});
    const int countU = 7, countV = 6;
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i < countU; ++i)
        for (int j = 0; j < countV; ++j) {
            const double w = 1 + 0.3 * ((i + 2 * j) % 3);
            poles.push_back(w * HomogeneousPoint3(i / 6.0, j / 5.0, 0.2 * ((i * j) % 3) - 0.1, 1));
        }
    return BSplineSurface(u, v, countU, countV, poles);
}

// Triangles across span borders: the bound over the spans' pieces holds at every sampled point,
// and is close enough to certify a target a tenth over the sampled distance (40 of 40 here).
TEST(TriangleDeviation, HoldsAcrossSpans) {
    const BezierPatchGrid grid(bumpySurface());
    std::mt19937 random(4);
    std::uniform_real_distribution<double> unit(0, 1), side(0.05, 0.3);
    int certified = 0, tried = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const Point2 origin(unit(random) * 0.7, unit(random) * 0.7);
        const std::array<Point2, 3> uv{origin, origin + Point2(side(random), 0.3 * side(random)),
                                       origin + Point2(0.2 * side(random), side(random))};
        std::array<Point3, 3> image;
        for (int k = 0; k < 3; ++k) image[k] = grid.point(uv[k].x(), uv[k].y());
        double sampled = 0;
        for (int a = 0; a <= 24; ++a)
            for (int b = 0; a + b <= 24; ++b) {
                const double l1 = a / 24.0, l2 = b / 24.0, l0 = 1 - l1 - l2;
                const Point2 q = l0 * uv[0] + l1 * uv[1] + l2 * uv[2];
                sampled = std::max(sampled, (grid.point(q.x(), q.y()) -
                                             (l0 * image[0] + l1 * image[1] + l2 * image[2]))
                                                .norm());
            }
        const auto loose = triangleDeviation(grid, uv, *TriangleAffineMap::through(uv, image),
                                             std::numeric_limits<double>::infinity(), 64);
        ASSERT_TRUE(loose.has_value());
        EXPECT_GE(*loose, sampled * (1 - 1e-9));
        const auto close =
            triangleDeviation(grid, uv, *TriangleAffineMap::through(uv, image), 1.1 * sampled, 64);
        ASSERT_TRUE(close.has_value());
        EXPECT_GE(*close, sampled * (1 - 1e-9));
        ++tried;
        if (*close <= 1.1 * sampled) ++certified;
    }
    EXPECT_GE(certified, tried * 9 / 10);
    // more span pairs than allowed: no answer
    const std::array<Point2, 3> wide{Point2(0, 0), Point2(1, 0), Point2(0, 1)};
    const auto flat =
        TriangleAffineMap::through(wide, {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)});
    ASSERT_TRUE(flat.has_value());
    EXPECT_FALSE(triangleDeviation(grid, wide, *flat, 1.0, 4).has_value());
}

}  // namespace
}  // namespace nurbslod
