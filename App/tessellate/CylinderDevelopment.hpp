#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Cylinder.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// A face's cylinder as the tessellator unrolls it: the angle about the axis from e1 towards e2
// (axis = e1 x e2) and the height along the axis. `side` is +1 where the surface's du x dv points
// away from the axis, -1 where it points towards it.
struct CylinderFrame {
    Point3 origin = Point3::Zero();
    Vector3 axis = Vector3::UnitZ(), e1 = Vector3::UnitX(), e2 = Vector3::UnitY();
    double radius = 0;
    double side = 1;
};

// The frame of `cylinder` for a surface that lies on it: none where a point of the surface
// (a grid over each of its Bezier spans) is farther than `flatness` from the cylinder, or where
// du x dv does not point across it (no orientation). The cylinder comes from the file
// (TrimmedSurface::cylinder); the points only confirm that the NURBS form is the same surface.
std::optional<CylinderFrame> faceCylinderFrame(const BSplineSurface& surface,
                                               const Cylinder& cylinder, double flatness);

// How far a flat triangle whose corners lie on a cylinder of `radius` is from the cylinder over
// the triangle's unrolled image, both ways, when its corners span `angle` about the axis:
// radius * angle^2 / 8. The unrolled map S(theta, h) has its height linear and its circle's
// second derivative of length radius; at a point with barycentric weights l_i, the corners'
// Taylor expansions about it cancel their first-order terms (sum l_i (theta_i - theta) = 0), so
// |S - sum l_i S_i| <= radius / 2 * sum l_i (theta_i - theta)^2 <= radius / 2 * angle^2 / 4.
double unrolledTriangleBound(double radius, double angle);

// Triangles over rings of points of a face on a cylinder (its trimming loops' points, in the
// loops' order), made in the cylinder's unrolled plane (radius times the angle, height), then
// flipped to narrow the widest; each with its bound (unrolledTriangleBound of the angle its
// corners span). Each triangle holds three indices into the concatenation of the rings,
// counter-clockwise about du x dv. None where the rings do not unroll (a ring that winds about
// the axis, a hole whose turn of the unrolled plane is not clear, a step of more than three
// eighths of a turn between two points) or do not make a valid polygon with holes there. Triangles
// made so tile the unrolled polygon of the rings' chords, which the cylinder maps onto the face
// less the slivers between its trimming curves and their chords, as a kd-tree cell's triangles do
// within their cell's bound.
struct UnrolledTriangles {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<double> bounds;
};
std::optional<UnrolledTriangles> triangulateUnrolled(const CylinderFrame& frame,
                                                     const std::vector<std::vector<Point3>>& rings);

// Points on the rings' chords that let every unrolled triangle keep `surfaceShare`: per ring and
// side (from point i to point i + 1), the fractions along the chord, increasing; all empty where
// the rings' points already do. Each round halves the chord pieces at the corners of the
// triangles over the bound, until none is. None where the rings do not unroll, or where that
// takes `fewerThan` points or more (a dozen rounds at most). `first`, where given, is
// triangulateUnrolled of the rings themselves, which the first round then takes.
//
// A point on a chord is off the cylinder by the chord's distance from its curve, which the
// face's trimming share covers, as it does for the points a kd-tree cell's side cuts on a chord:
// a triangle with such a corner is within its unrolled bound of the cylinder plus that distance.
using ChordFractions = std::vector<std::vector<std::vector<double>>>;
std::optional<ChordFractions> chordPointsForUnrolledBound(
    const CylinderFrame& frame, const std::vector<std::vector<Point3>>& rings, double surfaceShare,
    std::size_t fewerThan, const UnrolledTriangles* first = nullptr);

// Whether every triangle's bound is within `surfaceShare` (a positive share).
bool keepsBound(const UnrolledTriangles& unrolled, double surfaceShare);

// The triangles of triangulateUnrolled where every bound is within `surfaceShare`; none else.
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateOnCylinder(
    const CylinderFrame& frame, const std::vector<std::vector<Point3>>& rings, double surfaceShare);

}  // namespace nurbslod
