#pragma once

#include "geometry/Point.hpp"

namespace nurbslod {

// `levels` steps of de Casteljau's algorithm on the points pts[0..degree] at local parameter t
// (complement = 1 - t, precomputed): afterwards pts[0..degree-levels] are the points of that
// level. Shared by the Bezier evaluation methods.
inline void deCasteljauReduce(HomogeneousPoint3* pts, int degree, int levels, double t,
                              double complement) {
    for (int r = 1; r <= levels; ++r)
        for (int i = 0; i <= degree - r; ++i) pts[i] = complement * pts[i] + t * pts[i + 1];
}

}  // namespace nurbslod
