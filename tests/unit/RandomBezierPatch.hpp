#pragma once

#include <random>

#include "geometry/BezierPatch.hpp"

namespace nurbslod::testing {

// A rational patch with control points in the unit cube and weights from 0.2 to 5.
inline BezierPatch randomRationalPatch(std::mt19937& random, int degreeU, int degreeV) {
    std::uniform_real_distribution<double> coordinate(-1, 1), weight(0.2, 5.0);
    BezierPatch patch(degreeU, degreeV);
    for (int i = 0; i <= degreeU; ++i)
        for (int j = 0; j <= degreeV; ++j) {
            const double w = weight(random);
            patch.pole(i, j) = HomogeneousPoint3(w * coordinate(random), w * coordinate(random),
                                                 w * coordinate(random), w);
        }
    return patch;
}

}  // namespace nurbslod::testing
