#pragma once

#include <cmath>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// The unit normal du x dv of a surface from its first partial derivatives, with the same
// reliability rule as BSplineSurface::normal: where a derivative has collapsed (a pole, a
// collapsed edge) the direction of du x dv is rounding noise, and the normal is taken from the
// surface's own pole-safe normal at (u, v) instead. The derivatives may carry any common
// positive scale (the evaluators pass w^2 times the true ones: the quotient rule without the
// division), since the test and the result are scale-free.
inline bool isReliableNormal(const Vector3& du, const Vector3& dv, const Vector3& n) {
    const double a2 = du.squaredNorm(), b2 = dv.squaredNorm();
    return a2 > 1e-16 * b2 && b2 > 1e-16 * a2 && n.squaredNorm() > 1e-20 * a2 * b2;
}

inline Vector3 unitNormal(const Vector3& du, const Vector3& dv, const BSplineSurface& surface,
                          double u, double v) {
    const Vector3 n = du.cross(dv);
    // one division per normal rather than three
    if (isReliableNormal(du, dv, n)) return n * (1.0 / std::sqrt(n.squaredNorm()));
    return surface.normal(u, v);
}

}  // namespace nurbslod
