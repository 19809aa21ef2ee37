#pragma once

#include <algorithm>

#include "geometry/Point.hpp"

namespace nurbslod {

// Distance from p to the segment [a, b] (to a when the segment has no length).
inline double distanceToSegment(const Point3& p, const Point3& a, const Point3& b) {
    const Vector3 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double lambda = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + lambda * ab)).norm();
}

}  // namespace nurbslod
