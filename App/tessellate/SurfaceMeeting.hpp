#pragma once

#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// A point near where several surfaces meet (cross, or come closest), found from `start`:
// each surface's foot (SurfaceProjection) gives its tangent plane there, and the point moves to
// the nearest point of the planes' common line (Gauss-Newton on the surfaces' distances). Where
// the surfaces cross at an angle it converges quadratically, however small the angle; where
// their normals are nearly parallel (surfaces that touch, or run side by side) the planes' line
// is ill-posed and the step is the least-squares one along the normals, which ends midway
// between the surfaces. Alternating projections, by contrast, creep along a shallow crossing
// by the cosine of its angle per step.
struct SurfaceMeeting {
    Point3 point;
    std::vector<Point2> uv;    // per surface, its foot's (u, v)
    std::vector<Point3> feet;  // per surface, its foot
    double offset = 0;         // the largest distance from the point to a foot
    int iterations = 0;        // how many times the feet were found
};

// `starts` holds one (u, v) per surface to start its foot search from.
SurfaceMeeting findSurfaceMeeting(const std::vector<const BSplineSurface*>& surfaces,
                                  const Point3& start, const std::vector<Point2>& starts,
                                  int iterations = 12);

}  // namespace nurbslod
