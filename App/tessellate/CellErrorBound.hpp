#pragma once

#include "geometry/BezierPatch.hpp"
#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

// How far a kd-tree cell's surface piece may be from the triangles made over it, and where to
// split the cell if that is too far (paper section 5.2).
struct CellErrorBound {
    // Bound on |S - B| over the cell, B the bilinear interpolant of the corners.
    double interior = 0;
    // Bound on |S - B| along the four cell edges: where the triangle corners are.
    double boundary = 0;
    // |P00 - Pm0 - P0n + Pmn| / 4: the most the two triangles (or any triangles inside the cell)
    // deviate from the bilinear patch (paper section 5.2, [Kah02]).
    double twist = 0;
    // Preferred split: direction (0 = u, 1 = v) and local position in (0, 1).
    int splitDirection = 0;
    double splitAt = 0.5;

    // Bound for triangles whose corners are cell corners or lie on the cell edges.
    double untrimmed() const { return interior + boundary + twist; }
    // Bound for triangles with corners anywhere in the cell (trimming points).
    double trimmed() const { return 2 * interior + twist; }
};

// Conservative (mode Guaranteed): from the control net. For rational patches the numerator
// N - w B is written in the degree-elevated Bernstein basis and bounded by its largest
// coefficient over the smallest weight, which is exact for weights of 1 and a true bound for
// any positive weights. Approximate: the control points replaced by surface points at the
// control points' parameters (paper section 5.2).
CellErrorBound cellErrorBound(const BezierPatch& patch, ErrorMode mode);

}  // namespace nurbslod
