#pragma once

#include "geometry/BSplineSurface.hpp"

namespace nurbslod {

// The foot of a point on a surface near a known (u, v): Gauss-Newton steps on the squared
// distance, kept inside the surface's domain. Used to move a trimming curve's end onto its
// B-rep vertex where a sloppy file leaves a gap between them.
struct SurfaceFoot {
    Point2 uv;
    Point3 point;
};
SurfaceFoot projectOntoSurface(const BSplineSurface& surface, const Point3& target, Point2 start);

}  // namespace nurbslod
