#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "tessellate/FaceMesh.hpp"

namespace nurbslod {

// A triangle of a face's vertices (indices into FaceMesh::vertices), counter-clockwise in (u, v).
using RingTriangle = std::array<std::uint32_t, 3>;

// Bounds how far a triangle of the face's vertices is from the surface, both ways.
using TriangleBound = std::function<double(const RingTriangle& triangle)>;

// The triangulation of the ring n0 .. nm (its vertices in counter-clockwise order around a
// region of the face's triangles, the side nm -> n0 included) whose largest triangle bound
// (`bound`) is least, with that bound: the polygon recurrence over the ring in (u, v). A
// triangle is taken where it turns counter-clockwise in (u, v) with area and holds no other
// ring point, its new sides are not edges outside the region (forbidden[i * size + j]) and cross
// no side of the ring, and it faces the surface's normals at its corners the way the old
// triangles do (`facing`: +1 or -1), so that it folds nowhere in space. A triangle over `limit`
// is not taken. None where no triangulation is within it.
std::optional<std::pair<std::vector<RingTriangle>, double>> leastBoundTriangulation(
    const std::vector<std::uint32_t>& ring, const FaceMesh& mesh,
    const std::vector<char>& forbidden, double facing, const TriangleBound& bound, double limit);

namespace ring {

// +1 where the triangles, summed, turn the way the surface's normals at their corners point,
// else -1: the `facing` that leastBoundTriangulation keeps for their region.
double facingOf(const FaceMesh& mesh, const std::vector<RingTriangle>& triangles);

// Drops the triangles marked removed (by index), keeping the others' order.
void dropRemoved(std::vector<RingTriangle>& triangles, const std::vector<char>& removed);

// Twice the signed area of the triangle abc in (u, v): positive counter-clockwise.
double cross(const Point2& a, const Point2& b, const Point2& c);

// Proper crossing of segments ab and cd in the plane (touching at an end does not count).
bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

// Whether the triangle (i, k, j) of a ring, uv(n) its points in (u, v), turns counter-clockwise
// with more than `minimumArea` and holds no other point of the ring (n < size), in or on it.
template <class Uv>
bool emptyRingTriangle(const Uv& uv, std::size_t size, std::size_t i, std::size_t k, std::size_t j,
                       double minimumArea) {
    if (!(cross(uv(i), uv(k), uv(j)) > minimumArea)) return false;
    for (std::size_t w = 0; w < size; ++w) {
        if (w == i || w == k || w == j) continue;
        if (cross(uv(i), uv(k), uv(w)) >= -minimumArea &&
            cross(uv(k), uv(j), uv(w)) >= -minimumArea &&
            cross(uv(j), uv(i), uv(w)) >= -minimumArea)
            return false;
    }
    return true;
}

// The triangles of a polygon recurrence over the ring n0 .. nm: split[i * ring.size() + j] is
// the apex over the side (i, j) of the best triangulation of the sub-polygon i .. j.
std::vector<RingTriangle> trianglesOfSplits(const std::vector<std::uint32_t>& ring,
                                            const std::vector<std::size_t>& split);

}  // namespace ring

}  // namespace nurbslod
