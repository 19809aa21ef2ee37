#include <gtest/gtest.h>

#include <random>
#include <string>

#include "RandomBezierPatch.hpp"
#include "geometry/TriangularBezierPatch.hpp"

namespace nurbslod {
namespace {

using testing::randomRationalPatch;

std::array<Point2, 3> randomTriangle(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::array<Point2, 3> triangle;
    for (Point2& corner : triangle) corner = Point2(unit(random), unit(random));
    return triangle;
}

// At random barycentric coordinates the triangular patch's point is the tensor patch's at the
// same point of `triangle`.
void expectTensorPointsOver(const TriangularBezierPatch& over, const BezierPatch& patch,
                            const std::array<Point2, 3>& triangle, std::mt19937& random,
                            const std::string& what) {
    std::uniform_real_distribution<double> unit(0, 1);
    for (int sample = 0; sample < 10; ++sample) {
        double l1 = unit(random), l2 = unit(random);
        if (l1 + l2 > 1) l1 = 1 - l1, l2 = 1 - l2;
        const double l0 = 1 - l1 - l2;
        const Point2 q = l0 * triangle[0] + l1 * triangle[1] + l2 * triangle[2];
        const Point3 expected = patch.point(q.x(), q.y());
        EXPECT_LT((over.point(l0, l1, l2) - expected).norm(), 1e-10 * (1 + expected.norm()))
            << what;
    }
}

// The triangular patch is the tensor patch over the triangle, exactly: the same point at the
// same barycentric coordinates, rational patches of unequal degrees included.
TEST(TriangularBezierPatch, IsTheTensorPatchOverTheTriangle) {
    std::mt19937 random(5);
    for (const auto& [degreeU, degreeV] :
         {std::pair{1, 1}, std::pair{2, 1}, std::pair{2, 2}, std::pair{3, 3}, std::pair{1, 8},
          std::pair{5, 5}, std::pair{8, 8}}) {
        const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
        for (int trial = 0; trial < 5; ++trial) {
            const auto triangle = randomTriangle(random);
            const TriangularBezierPatch over(patch, triangle);
            ASSERT_EQ(over.degree(), degreeU + degreeV);
            expectTensorPointsOver(over, patch, triangle, random,
                                   std::to_string(degreeU) + " x " + std::to_string(degreeV));
            // its corners are the patch's points at the triangle's corners
            const int n = over.degree();
            EXPECT_LT((projectHomogeneous(over.pole(n, 0)) -
                       patch.point(triangle[0].x(), triangle[0].y()))
                          .norm(),
                      1e-10);
            EXPECT_LT((projectHomogeneous(over.pole(0, n)) -
                       patch.point(triangle[1].x(), triangle[1].y()))
                          .norm(),
                      1e-10);
            EXPECT_LT((projectHomogeneous(over.pole(0, 0)) -
                       patch.point(triangle[2].x(), triangle[2].y()))
                          .norm(),
                      1e-10);
        }
    }
}

// Each half is the tensor patch over its own triangle: cut at the middle of side k, the half
// that keeps corner k has the middle for corner k + 1, and the other the middle for corner k.
TEST(TriangularBezierPatch, HalvesAreThePatchOverEachHalf) {
    std::mt19937 random(13);
    for (const auto& [degreeU, degreeV] : {std::pair{1, 1}, std::pair{2, 2}, std::pair{5, 3}}) {
        const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
        const auto triangle = randomTriangle(random);
        const TriangularBezierPatch whole(patch, triangle);
        for (int side = 0; side < 3; ++side) {
            const int next = (side + 1) % 3;
            const Point2 middle = 0.5 * (triangle[side] + triangle[next]);
            std::array<Point2, 3> first = triangle, second = triangle;
            first[next] = middle;
            second[side] = middle;
            const auto halves = whole.halves(side);
            for (int h = 0; h < 2; ++h) {
                const auto& corners = h == 0 ? first : second;
                ASSERT_EQ(halves[h].degree(), whole.degree());
                expectTensorPointsOver(
                    halves[h], patch, corners, random,
                    "side " + std::to_string(side) + " half " + std::to_string(h));
            }
        }
    }
}

TEST(TriangularBezierPatch, RefusesTooHighADegree) {
    std::mt19937 random(2);
    const BezierPatch patch = randomRationalPatch(random, 9, 9);
    EXPECT_THROW(TriangularBezierPatch(patch, randomTriangle(random)), std::invalid_argument);
}

// The distance from the affine map of the corners is bounded at every point of the triangle
// (rational patches), and nothing on a plane with its own map.
TEST(TriangularBezierPatch, FarthestFromAffineHoldsOverTheTriangle) {
    std::mt19937 random(9);
    for (int trial = 0; trial < 30; ++trial) {
        const BezierPatch patch = randomRationalPatch(random, 1 + trial % 4, 1 + trial % 3);
        const auto triangle = randomTriangle(random);
        const std::array<Point3, 3> image{patch.point(triangle[0].x(), triangle[0].y()),
                                          patch.point(triangle[1].x(), triangle[1].y()),
                                          patch.point(triangle[2].x(), triangle[2].y())};
        const double bound = TriangularBezierPatch(patch, triangle).farthestFromAffine(image);
        for (int a = 0; a <= 12; ++a)
            for (int b = 0; a + b <= 12; ++b) {
                const double l1 = a / 12.0, l2 = b / 12.0, l0 = 1 - l1 - l2;
                const Point2 q = l0 * triangle[0] + l1 * triangle[1] + l2 * triangle[2];
                const Point3 flat = l0 * image[0] + l1 * image[1] + l2 * image[2];
                EXPECT_LE((patch.point(q.x(), q.y()) - flat).norm(), bound * (1 + 1e-9) + 1e-12);
            }
    }
    BezierPatch plane(2, 3);
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 3; ++j) {
            const double s = i / 2.0, t = j / 3.0;  // linear precision: the plane's own map
            plane.pole(i, j) = HomogeneousPoint3(s, t, 2 * s - t, 1);
        }
    const std::array<Point2, 3> triangle{Point2(0.1, 0.2), Point2(0.9, 0.3), Point2(0.4, 0.8)};
    std::array<Point3, 3> image;
    for (int k = 0; k < 3; ++k) image[k] = plane.point(triangle[k].x(), triangle[k].y());
    EXPECT_LT(TriangularBezierPatch(plane, triangle).farthestFromAffine(image), 1e-12);
}

}  // namespace
}  // namespace nurbslod
