#pragma once

#include <vector>

#include "geometry/BSplineSurface.hpp"
#include "geometry/BezierPatch.hpp"

namespace nurbslod {

// The Bezier patches of a clamped B-spline surface, one per non-empty knot span pair, obtained
// by knot insertion (NURBS Book, algorithm A5.6 applied along u, then along v).
class BezierPatchGrid {
public:
    explicit BezierPatchGrid(const BSplineSurface& surface);

    const std::vector<double>& breakpointsU() const { return breaksU_; }
    const std::vector<double>& breakpointsV() const { return breaksV_; }
    int spansU() const { return static_cast<int>(breaksU_.size()) - 1; }
    int spansV() const { return static_cast<int>(breaksV_.size()) - 1; }
    const BezierPatch& patch(int spanU, int spanV) const {
        return patches_[spanU * spansV() + spanV];
    }

    // The patch of span (spanU, spanV) restricted to [u0, u1] x [v0, v1] (the surface's
    // parameters, clamped to the span).
    BezierPatch piece(int spanU, int spanV, double u0, double u1, double v0, double v1) const;

    // The surface's point at (u, v), from the patch of the span that holds it (clamped to the
    // domain, as spanIndexU/V clamp).
    Point3 point(double u, double v) const;

    // The span index containing t (clamped to the domain).
    int spanIndexU(double u) const;
    int spanIndexV(double v) const;

private:
    std::vector<double> breaksU_, breaksV_;
    std::vector<BezierPatch> patches_;
};

// Bezier segments of a clamped B-spline curve given by homogeneous points with a stride:
// returns segments * (degree+1) points, segment after segment (NURBS Book, A5.6).
std::vector<HomogeneousPoint3> decomposeIntoBezierSegments(const KnotVector& knots,
                                                           const HomogeneousPoint3* pts,
                                                           int stride);

}  // namespace nurbslod
