#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// The plane of a face whose surface lies in one: an origin and two orthonormal directions, with
// e1 x e2 along the surface's own normal du x dv.
struct FacePlane {
    Point3 origin = Point3::Zero();
    Vector3 e1 = Vector3::UnitX(), e2 = Vector3::UnitY();
};

// The plane of the surface where every control point lies within `flatness` of it: with
// positive weights the surface lies in the hull of its control points, so within `flatness` of
// the plane too. None where a control point is farther, where a weight is not positive, or
// where du x dv vanishes at the points tried (no orientation). A B-spline whose parameter runs
// unevenly over a plane (a planar face exported as a bicubic patch) is one: the kd-tree's
// bounds, taken at equal parameters, split it for a twist that lies in the plane.
std::optional<FacePlane> facePlane(const BSplineSurface& surface, double flatness);

// Triangles over rings of points in the plane, by their coordinates there: rings[0] and the
// others one polygon with holes (the ring of largest area taken as the outer one). Each
// triangle holds three indices into the concatenation of the rings, counter-clockwise about
// e1 x e2. None where the rings do not make a valid polygon with holes in the plane (crossing
// chords, two outer rings): the caller then triangulates as before. Triangles made so tile the
// polygon of the rings' chords exactly, whatever the surface's parameter does over it.
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateInPlane(
    const FacePlane& plane, const std::vector<std::vector<Point3>>& rings);

}  // namespace nurbslod
