#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// Where a triangle's corner came from: the triangle (its index before splitNeedles) and the
// corner in it.
struct CornerOrigin {
    std::uint32_t triangle = 0;
    int corner = 0;
};

// What splitNeedles left: for each triangle now, where its corners came from, and the triangle
// whose place it takes (its own, or for the two halves of a split one, the split one).
struct TriangleOrigin {
    std::array<CornerOrigin, 3> corners;
    std::uint32_t triangle = 0;
};

// A needle is a triangle of no area whose third corner lies on its longest side: a point cut
// into an edge's chord, placed on the 3D chord so that both faces of the edge share it, which in
// (u, v) the clipper's rounding moved off the chord by a fraction of a step; or a point the
// weld moved onto a chord. Valid in (u, v), of no area in space. Each needle whose longest side
// another triangle runs the other way is removed, and that triangle is split at the needle's
// third corner, which keeps every side shared: the mesh covers the same points as before.
// `position` gives a vertex's position. Returns the triangles' origins, in their new order, so
// that a caller keeps per-corner and per-triangle attributes with them.
std::vector<TriangleOrigin> splitNeedles(
    std::vector<std::array<std::uint32_t, 3>>& triangles,
    const std::function<const Point3&(std::uint32_t)>& position);

}  // namespace nurbslod
