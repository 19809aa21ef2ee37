#pragma once

#include <span>
#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// Exact points and unit normals of a (rational) B-spline surface at arbitrary parameter pairs,
// such as the vertices of an adaptive tessellation: the same results as BSplineSurface::point
// and BSplineSurface::normal (clamping and pole-safe normal included), computed in one pass.
//
// The coherence of grid evaluation (evaluation paper, section 2.2) is kept where the pairs
// offer it: basis functions and spans are computed once per distinct u and per distinct v (the
// corners of a kd-tree's cells share their u and v values), and pairs are grouped by equal u.
// A group whose v values lie in a narrow band of control-point columns computes the row sums
// Q_j = sum_k N_k(u) P_kj, Q'_j = sum_k N'_k(u) P_kj once, so each pair costs (pv+1) terms per
// sum; a group whose few v values are spread over many columns (the usual case on a small face)
// evaluates each pair directly from the cached basis functions instead, whichever does fewer
// multiply-adds. Groups are spread over threads with oneTBB for large sets.
//
// Set-up is cheap, so that a face of a few dozen vertices pays little more than their
// evaluations: no copy of the surface, one small open-addressing table per direction for the
// distinct values; basis functions and sums run in loops of fixed length for the common degrees.
class PointSetEvaluator {
public:
    // Throws std::invalid_argument naming the problem if the surface cannot be evaluated. The
    // surface is referenced, not copied: it must outlive the evaluator.
    explicit PointSetEvaluator(const BSplineSurface& surface);

    // points[k] and normals[k] (null for points only) at uv[k]. Throws std::invalid_argument for
    // a parameter that is not finite.
    void evaluate(std::span<const Point2> uv, Point3* points, Vector3* normals,
                  int threads = 1) const;

private:
    const BSplineSurface* surface_;
};

}  // namespace nurbslod
