#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/KnotVector.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// A (rational) tensor-product B-spline surface with homogeneous control points
// P^w_ij = (w x, w y, w z, w), i along u, j along v (NURBS Book, equation 4.15).
class BSplineSurface {
public:
    struct FirstDerivatives {
        Point3 point;
        Vector3 du;
        Vector3 dv;
    };

    BSplineSurface() = default;
    BSplineSurface(KnotVector u, KnotVector v, int countU, int countV,
                   std::vector<HomogeneousPoint3> weightedPoles);

    const KnotVector& knotsU() const { return u_; }
    const KnotVector& knotsV() const { return v_; }
    int degreeU() const { return u_.degree(); }
    int degreeV() const { return v_.degree(); }
    int countU() const { return countU_; }
    int countV() const { return countV_; }
    const HomogeneousPoint3& pole(int i, int j) const { return poles_[i * countV_ + j]; }
    HomogeneousPoint3& pole(int i, int j) { return poles_[i * countV_ + j]; }
    const std::vector<HomogeneousPoint3>& poles() const { return poles_; }
    bool isRational() const;
    // The corners (low, high) of the axis-aligned box of the control points, projected; with
    // positive weights the surface lies in their hull, so in the box.
    std::pair<Point3, Point3> controlNetBox() const;

    Point3 point(double u, double v) const;
    FirstDerivatives derivatives(double u, double v) const;
    // Unit normal du x dv. Where it vanishes (a pole of a sphere, a collapsed edge) the normal
    // is taken a small step inside the domain, the limit a display wants there.
    Vector3 normal(double u, double v) const;

    // Why this surface cannot be evaluated (knots that do not fit, a weight <= 0, a NaN), or
    // nothing if it can.
    std::optional<std::string> problem() const;
    // This surface, or std::invalid_argument naming its problem: for the evaluators, which
    // take a surface once and then trust it in their inner loops.
    const BSplineSurface& validated() const;

private:
    void clampToDomain(double& u, double& v) const;
    HomogeneousPoint3 homogeneousPoint(double u, double v) const;

    KnotVector u_, v_;
    int countU_ = 0, countV_ = 0;
    std::vector<HomogeneousPoint3> poles_;
};

}  // namespace nurbslod
