#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <random>

#include "geometry/Point.hpp"

namespace nurbslod::testing {

// A point (s, t) on the border of the unit cell, one of its four sides at random: a corner of a
// triangle the tessellator makes from a neighbour's points on the cell's sides.
inline std::array<double, 2> cellBorderPoint(std::mt19937& random) {
    const double x = std::uniform_real_distribution<double>(0, 1)(random);
    switch (std::uniform_int_distribution<int>(0, 3)(random)) {
        case 0:
            return {x, 0};
        case 1:
            return {1, x};
        case 2:
            return {x, 1};
        default:
            return {0, x};
    }
}

// Largest distance between a surface and the flat triangle through its points at the cell
// parameters a, b, c, at equal parameters, sampled on a barycentric grid of `steps`: what a
// cell's bound at equal parameters must never be below.
inline double sampledTriangleDistance(const std::function<Point3(double, double)>& surface,
                                      const std::array<double, 2>& a,
                                      const std::array<double, 2>& b,
                                      const std::array<double, 2>& c, int steps = 12) {
    const Point3 pa = surface(a[0], a[1]), pb = surface(b[0], b[1]), pc = surface(c[0], c[1]);
    double worst = 0;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            const double la = double(i) / steps, lb = double(j) / steps, lc = 1 - la - lb;
            const double s = la * a[0] + lb * b[0] + lc * c[0];
            const double t = la * a[1] + lb * b[1] + lc * c[1];
            worst = std::max(worst, (surface(s, t) - (la * pa + lb * pb + lc * pc)).norm());
        }
    return worst;
}

}  // namespace nurbslod::testing
