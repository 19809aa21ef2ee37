#pragma once

// Random clamped B-spline surfaces for the evaluation tests: interior knots at random places,
// some repeated, control points in the unit cube, weights in [0.5, 2] when rational.

#include <random>
#include <vector>

#include "geometry/BSplineSurface.hpp"

namespace nurbslod::testing {

inline KnotVector randomKnots(int degree, int interiorKnots, std::mt19937& random) {
    std::uniform_real_distribution<double> position(0.0, 1.0);
    std::vector<double> interior;
    while (static_cast<int>(interior.size()) < interiorKnots) {
        const double k = 0.05 + 0.9 * position(random);
        interior.push_back(k);
        // now and then a repeated knot (lower continuity), never above the degree
        if (degree > 1 && position(random) < 0.2 &&
            static_cast<int>(interior.size()) < interiorKnots)
            interior.push_back(k);
    }
    std::sort(interior.begin(), interior.end());
    std::vector<double> knots(degree + 1, -0.5);
    knots.insert(knots.end(), interior.begin(), interior.end());
    knots.insert(knots.end(), degree + 1, 1.5);
    return KnotVector(degree, std::move(knots));
}

inline BSplineSurface randomSurface(int degreeU, int degreeV, bool rational, std::mt19937& random,
                                    int interiorU = 3, int interiorV = 2) {
    KnotVector u = randomKnots(degreeU, interiorU, random);
    KnotVector v = randomKnots(degreeV, interiorV, random);
    const int nu = u.controlPointCount(), nv = v.controlPointCount();
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.5, 2.0);
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            // a wavy sheet, so that normals are well defined almost everywhere
            const double w = rational ? weight(random) : 1.0;
            const Point3 p(i + 0.3 * coordinate(random), j + 0.3 * coordinate(random),
                           coordinate(random));
            poles.emplace_back(w * p.x(), w * p.y(), w * p.z(), w);
        }
    return BSplineSurface(std::move(u), std::move(v), nu, nv, std::move(poles));
}

inline std::vector<double> uniformParameters(double a, double b, int count) {
    std::vector<double> out(count);
    for (int k = 0; k < count; ++k) out[k] = count == 1 ? a : a + (b - a) * k / (count - 1);
    return out;
}

}  // namespace nurbslod::testing
