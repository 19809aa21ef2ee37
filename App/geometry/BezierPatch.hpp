#pragma once

#include <array>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// A (rational) tensor-product Bezier patch over the local square [0,1]^2, homogeneous control
// points P^w_ij with i along u (0..degreeU) and j along v (0..degreeV).
class BezierPatch {
public:
    BezierPatch() = default;
    BezierPatch(int degreeU, int degreeV);

    int degreeU() const { return degreeU_; }
    int degreeV() const { return degreeV_; }
    HomogeneousPoint3& pole(int i, int j) { return poles_[i * (degreeV_ + 1) + j]; }
    const HomogeneousPoint3& pole(int i, int j) const { return poles_[i * (degreeV_ + 1) + j]; }
    Point3 pole3(int i, int j) const { return projectHomogeneous(pole(i, j)); }

    // The patch restricted to [u0,u1] x [v0,v1] (local parameters), by de Casteljau
    // subdivision: an exact reparameterisation, so its control net bounds that piece.
    BezierPatch restricted(double u0, double u1, double v0, double v1) const;

    // The halves [0, 1/2] and [1/2, 1] along u (direction 0) or v (1), the same numbers as
    // restricted() gives each, from one de Casteljau triangle per curve.
    std::array<BezierPatch, 2> halves(int direction) const;

    // The four quarters [0, 1/2] x [0, 1/2], [0, 1/2] x [1/2, 1], [1/2, 1] x [0, 1/2] and
    // [1/2, 1] x [1/2, 1], the same numbers as restricted() gives each: one de Casteljau
    // triangle yields both halves, so three passes do what four restrictions do in eight.
    std::array<BezierPatch, 4> quarters() const;

    // Point at local parameters (s, t): the Bernstein sum over the poles.
    Point3 point(double s, double t) const;

    // Points at the local parameters (i / segmentsU, j / segmentsV), i = 0..segmentsU,
    // j = 0..segmentsV, at index i * (segmentsV + 1) + j. One Bernstein row per parameter and a
    // sum over v shared by every u (tensor product): a grid of k^2 points costs about
    // k^2 (degreeU + 1) + k (degreeU + 1)(degreeV + 1) products instead of de Casteljau's
    // k^2 (degreeU + 1) degreeV^2 / 2 per point.
    std::vector<Point3> gridPoints(int segmentsU, int segmentsV) const;
    // The same at the local parameters (us[i], vs[j]), at index i * vs.size() + j.
    std::vector<Point3> gridPointsAt(const std::vector<double>& us,
                                     const std::vector<double>& vs) const;

private:
    int degreeU_ = 0, degreeV_ = 0;
    std::vector<HomogeneousPoint3> poles_;
};

// Restrict the Bezier curve with `degree`+1 control points at pts[0], pts[stride], ... to the
// local interval [a, b] in place; with `width`, that many curves side by side, curve w's
// points at pts[w], pts[stride + w], ...
void restrictBezierCurve(HomogeneousPoint3* pts, int degree, int stride, double a, double b,
                         int width = 1);

}  // namespace nurbslod
