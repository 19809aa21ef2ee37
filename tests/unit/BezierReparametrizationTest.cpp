#include <gtest/gtest.h>

#include <random>

#include "RandomBezierPatch.hpp"
#include "geometry/BezierReparametrization.hpp"

namespace nurbslod {
namespace {

using testing::randomRationalPatch;

// The composed patch is the patch at (alpha(s), beta(t)), to rounding, and keeps its corners.
TEST(BezierReparametrization, ComposedPatchIsThePatchAtTheNewParameter) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1), coefficient(-0.9, 0.9);
    for (int degreeU : {1, 2, 3, 5, 9})
        for (int degreeV : {1, 3, 4}) {
            const BezierPatch patch = randomRationalPatch(random, degreeU, degreeV);
            const double a = coefficient(random), b = coefficient(random);
            const BezierPatch even = reparametrized(patch, a, b);
            EXPECT_EQ(even.degreeU(), 2 * degreeU);
            EXPECT_EQ(even.degreeV(), 2 * degreeV);
            for (int k = 0; k < 50; ++k) {
                const double s = unit(random), t = unit(random);
                const Point3 expected = patch.point(s + a * s * (1 - s), t + b * t * (1 - t));
                EXPECT_LT((even.point(s, t) - expected).norm(), 1e-12)
                    << degreeU << "x" << degreeV << " at " << s << ", " << t;
            }
            for (int i : {0, 1})
                for (int j : {0, 1})
                    EXPECT_LT((even.pole3(i * 2 * degreeU, j * 2 * degreeV) -
                               patch.pole3(i * degreeU, j * degreeV))
                                  .norm(),
                              1e-14);
            // a zero coefficient keeps that direction as it is
            EXPECT_EQ(reparametrized(patch, 0, b).degreeU(), degreeU);
        }
}

// Sides whose poles crowd towards their start (x = (i / m)^2 along the chord) run slowly
// there: the even speed takes a > 0, alpha'(0) = 1 + a, so the new parameter hurries there.
// Sides with evenly spaced poles along straight chords need no change.
TEST(BezierReparametrization, EvenSpeedFollowsTheSpeedAlongTheSides) {
    BezierPatch even(3, 1), crowded(3, 1);
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 1; ++j) {
            const double x = i / 3.0;
            even.pole(i, j) = HomogeneousPoint3(x, j, 0.1 * j, 1);
            crowded.pole(i, j) = HomogeneousPoint3(x * x, j, 0.1 * x, 1);
        }
    EXPECT_NEAR(evenSpeed(even).a, 0, 1e-12);
    EXPECT_NEAR(evenSpeed(even).b, 0, 1e-12);
    const EvenSpeed speed = evenSpeed(crowded);
    EXPECT_GT(speed.a, 0.3);   // slow at s = 0: alpha hurries there
    EXPECT_LE(speed.a, 0.75);  // and stays a reparametrisation
    // the crowded side's chord midpoint is reached at alpha(1/2) nearer than at 1/2
    const double middle = 0.5 + 0.25 * speed.a;
    EXPECT_LT(std::abs(crowded.point(middle, 0).x() - 0.5),
              std::abs(crowded.point(0.5, 0).x() - 0.5));
}

}  // namespace
}  // namespace nurbslod
