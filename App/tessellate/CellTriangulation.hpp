#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tessellate/PolygonTriangulator.hpp"

namespace nurbslod {

// Triangles over a whole kd-tree cell: its rectangle with the neighbours' corners that lie on
// its sides (hanging points), counter-clockwise, no point repeated. Each triangle holds three
// indices into `ring` and is counter-clockwise with positive area; n points give n - 2
// triangles, and every corner of every triangle lies on the cell's sides, so the cell's
// untrimmed error bound holds (CellErrorBound::untrimmed).
//
// Why not the zigzag of triangulatePolygon: a hanging point a few integer steps off a side's
// line (a neighbour split one step away from this cell's corner) makes three nearly collinear
// points, and a triangle over them (a cap: one angle near 180 degrees) takes its orientation in
// space from the bending of the side's curve on the surface, not from its (u, v) winding: it
// folds against the surface normal. Needles (one tiny angle) are harmless: their short side
// crosses the long ones. So the triangulation chosen is the one whose largest angle is the
// smallest (dynamic programming over the convex polygon, O(n^3)), measured in the cell scaled
// to the unit square, which stands for the surface's shape over a cell far better than the
// integer plane's aspect. Rings of more than kMostCapFreePoints points fall back to
// triangulatePolygon.
inline constexpr std::size_t kMostCapFreePoints = 96;

std::vector<std::array<std::uint32_t, 3>> triangulateCellWithoutCaps(
    const std::vector<IntegerPoint2>& ring);

// Triangles over a trimmed cell with one side at a pole of the surface (a degenerated edge: a
// sphere's or a cone's tip, a fuselage's nose), where every point of that side is one point in
// space. `atPole[i]` marks the ring's points there. A triangle of the pole and two points of one
// of the cell's sides through the pole has area in (u, v) but lies in the plane of that
// meridian in space: flat, its normal across the surface's, which folds the shading. Larger
// cells at the pole (ErrorBudget::forChordsOnSurface) put hanging points on those sides, and a
// plain triangulation joined them to the pole. Here the cell is triangulated in a frame where
// the pole side is one point (a wedge), so that such triangles are flat there too and never
// chosen: a hanging point on a side joins the cell's far corner or the other side instead.
// Triangles with two corners at the pole vanish in space (their corners weld) and cost
// nothing. Empty where the cell is not of that kind (a point off the cell's sides, the pole
// marks not one whole side), or no such triangulation exists: the caller keeps its own.
std::vector<std::array<std::uint32_t, 3>> triangulateCellAtPole(
    const std::vector<IntegerPoint2>& ring, const std::vector<char>& atPole);

}  // namespace nurbslod
