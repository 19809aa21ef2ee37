#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "geometry/BezierPatch.hpp"
#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/TriangleAffineMap.hpp"

namespace nurbslod {

// A bound on the distance between the Bezier patch `patch` over the triangle `corner` (its local
// parameters) and the flat triangle `image` of those corners (the affine map between them, both
// ways): the hull of the difference over the triangle itself (TriangularBezierPatch), the
// triangle halved at its longest side where that hull is over `target`, `halvings` times at
// most (six halvings: triangles of an eighth of the sides, as three cuts in four). A value over
// the target says that no bound within it was found; stops at the first part over it. The
// patch's degrees must sum to TriangularBezierPatch::kMostDegree at most.
double triangleDeviation(const BezierPatch& patch, const std::array<Point2, 3>& corner,
                         const std::array<Point3, 3>& image, double target, int halvings = 6);

// The same for a triangle of a B-spline surface's parameters (inside its domain) against the
// affine map of its corners' positions (`affineAt`): the triangle cut at the spans' borders,
// each convex piece fanned into triangles bounded on their own span's patch. Nothing where the
// surface's degrees are too high or the triangle crosses more than `mostPieces` span pairs.
std::optional<double> triangleDeviation(const BezierPatchGrid& patches,
                                        const std::array<Point2, 3>& uv,
                                        const TriangleAffineMap& affineAt, double target,
                                        std::size_t mostPieces);

}  // namespace nurbslod
