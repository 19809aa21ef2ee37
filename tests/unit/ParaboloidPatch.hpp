#pragma once

#include "geometry/BezierPatch.hpp"

namespace nurbslod::testing {

// The paraboloid S(s, t) = (s, t, s^2 + t^2) over the unit square, as a biquadratic patch.
inline BezierPatch unitParaboloid() {
    BezierPatch patch(2, 2);
    const double square[3] = {0, 0, 1};  // s^2 in the Bernstein basis of degree 2
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
            patch.pole(i, j) = HomogeneousPoint3(i / 2.0, j / 2.0, square[i] + square[j], 1);
    return patch;
}

}  // namespace nurbslod::testing
