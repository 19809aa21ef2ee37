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
// offer it: pairs are grouped by equal u (the corners of a kd-tree's cells share their u
// values), and each group computes the u basis functions and the row sums
// Q_j = sum_k N_k(u) P_kj, Q'_j = sum_k N'_k(u) P_kj once, over just the control-point columns
// its v values need; basis functions are computed once per distinct v as well, so each pair
// costs (pv+1) terms per sum. A lone pair costs what one direct evaluation does. Groups are
// spread over threads with oneTBB.
class PointSetEvaluator {
public:
    // Throws std::invalid_argument naming the problem if the surface cannot be evaluated.
    explicit PointSetEvaluator(const BSplineSurface& surface);

    // points[k] and normals[k] (null for points only) at uv[k]. Throws std::invalid_argument for
    // a parameter that is not finite.
    void evaluate(std::span<const Point2> uv, Point3* points, Vector3* normals,
                  int threads = 1) const;

private:
    BSplineSurface surface_;
};

}  // namespace nurbslod
