// nearestParameter (Brent's minimisation over the two spans beside the nearest sample) finds
// the curve's nearest parameter as precisely as the golden section search it replaced, in far
// fewer evaluations.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry/NearestParameter.hpp"

namespace nurbslod {
namespace {

// A circle of radius 2 in an uneven parameter: angle(t) = t + 0.3 sin t. The nearest point to
// p is at the angle of p, so the nearest parameter solves angle(t) = atan2(p).
double angleOf(double t) {
    return t + 0.3 * std::sin(t);
}

double parameterOfAngle(double angle) {
    double t = angle;
    for (int k = 0; k < 50; ++k) t -= (angleOf(t) - angle) / (1 + 0.3 * std::cos(t));
    return t;
}

struct Sampled {
    std::vector<double> parameters, distances2;
};

Sampled samplesFor(double x, double y, double first, double last, int count) {
    Sampled s;
    for (int k = 0; k <= count; ++k) {
        const double t = first + (last - first) * k / count;
        const double dx = 2 * std::cos(angleOf(t)) - x, dy = 2 * std::sin(angleOf(t)) - y;
        s.parameters.push_back(t);
        s.distances2.push_back(dx * dx + dy * dy);
    }
    return s;
}

TEST(NearestParameter, FindsTheNearestPointInAFewEvaluations) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> angle(-2.5, 2.5), radius(1.7, 2.3);
    int evaluations = 0, points = 0;
    for (int k = 0; k < 500; ++k) {
        const double a = angle(random), r = radius(random);
        const double x = r * std::cos(a), y = r * std::sin(a);
        const Sampled s = samplesFor(x, y, -3.0, 3.0, 32);
        int calls = 0;
        const double t = nearestParameter(s.parameters, s.distances2, [&](double u) {
            ++calls;
            const double dx = 2 * std::cos(angleOf(u)) - x, dy = 2 * std::sin(angleOf(u)) - y;
            return dx * dx + dy * dy;
        });
        // two spans of 6/32 wide, to a few 1e-9 of them: about where rounding leaves the
        // squared distance flat about its minimum, as it left the golden section search
        EXPECT_NEAR(t, parameterOfAngle(a), 1e-8) << "angle " << a << " radius " << r;
        evaluations += calls;
        ++points;
    }
    // the golden section search took 42 evaluations for the same precision
    EXPECT_LT(double(evaluations) / points, 16.0);
}

TEST(NearestParameter, KeepsTheEndSampleForAPointBeyondTheEnd) {
    // the point lies beyond the end at t = 1: the end sample is the nearest, nothing between
    // the samples is nearer
    const Sampled s = samplesFor(2 * std::cos(1.6), 2 * std::sin(1.6), -1.0, 1.0, 16);
    const double t = nearestParameter(s.parameters, s.distances2, [&](double u) {
        const double dx = 2 * std::cos(angleOf(u)) - 2 * std::cos(1.6),
                     dy = 2 * std::sin(angleOf(u)) - 2 * std::sin(1.6);
        return dx * dx + dy * dy;
    });
    EXPECT_NEAR(t, s.parameters.back(), 1e-9);
}

TEST(NearestParameter, SingleSampleIsItsOwnAnswer) {
    const std::vector<double> parameters{0.5}, distances2{4.0};
    int calls = 0;
    const double t = nearestParameter(parameters, distances2, [&](double) {
        ++calls;
        return 1.0;
    });
    EXPECT_EQ(t, 0.5);
}

}  // namespace
}  // namespace nurbslod
