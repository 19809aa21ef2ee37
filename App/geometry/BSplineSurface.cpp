#include "geometry/BSplineSurface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

BSplineSurface::BSplineSurface(KnotVector u, KnotVector v, int countU, int countV,
                               std::vector<HomogeneousPoint3> weightedPoles)
    : u_(std::move(u)),
      v_(std::move(v)),
      countU_(countU),
      countV_(countV),
      poles_(std::move(weightedPoles)) {}

void BSplineSurface::clampToDomain(double& u, double& v) const {
    // Trimming curves of real files stray outside the domain by their tolerance; a polynomial
    // continued past a short end span would fly off, so they meet the border instead.
    u = std::clamp(u, u_.first(), u_.last());
    v = std::clamp(v, v_.first(), v_.last());
}

bool BSplineSurface::isRational() const {
    if (poles_.empty()) return false;
    const double w0 = poles_.front()[3];
    for (const auto& p : poles_)
        if (p[3] != w0) return true;
    return false;
}

HomogeneousPoint3 BSplineSurface::homogeneousPoint(double u, double v) const {
    clampToDomain(u, v);
    const int pu = u_.degree(), pv = v_.degree();
    const int su = u_.findSpan(u), sv = v_.findSpan(v);
    double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    basisFunctions(u_, su, u, Nu);
    basisFunctions(v_, sv, v, Nv);
    HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
    for (int k = 0; k <= pu; ++k) {
        HomogeneousPoint3 inner = HomogeneousPoint3::Zero();
        const HomogeneousPoint3* row = &poles_[(su - pu + k) * countV_ + (sv - pv)];
        for (int l = 0; l <= pv; ++l) inner += Nv[l] * row[l];
        sum += Nu[k] * inner;
    }
    return sum;
}

std::pair<Point3, Point3> BSplineSurface::controlNetBox() const {
    Point3 low = Point3::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (const HomogeneousPoint3& pole : poles_) {
        const Point3 p = projectHomogeneous(pole);
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    return {low, high};
}

Point3 BSplineSurface::point(double u, double v) const {
    return projectHomogeneous(homogeneousPoint(u, v));
}

BSplineSurface::FirstDerivatives BSplineSurface::derivatives(double u, double v) const {
    clampToDomain(u, v);
    const int pu = u_.degree(), pv = v_.degree();
    const int su = u_.findSpan(u), sv = v_.findSpan(v);
    double Nu[kMaxDegree + 1], dNu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
    basisFunctionsWithDerivative(u_, su, u, Nu, dNu);
    basisFunctionsWithDerivative(v_, sv, v, Nv, dNv);
    HomogeneousPoint3 S = HomogeneousPoint3::Zero(), Su = S, Sv = S;
    for (int k = 0; k <= pu; ++k) {
        HomogeneousPoint3 inner = HomogeneousPoint3::Zero(), innerDv = inner;
        const HomogeneousPoint3* row = &poles_[(su - pu + k) * countV_ + (sv - pv)];
        for (int l = 0; l <= pv; ++l) {
            inner += Nv[l] * row[l];
            innerDv += dNv[l] * row[l];
        }
        S += Nu[k] * inner;
        Su += dNu[k] * inner;
        Sv += Nu[k] * innerDv;
    }
    // quotient rule for the rational case (NURBS Book, equation 4.19)
    FirstDerivatives d;
    const double w = S[3];
    d.point = S.head<3>() / w;
    d.du = (Su.head<3>() - Su[3] * d.point) / w;
    d.dv = (Sv.head<3>() - Sv[3] * d.point) / w;
    return d;
}

Vector3 BSplineSurface::normal(double u, double v) const {
    // du x dv is reliable only where neither derivative has collapsed: at a pole (a sphere's
    // tip) du is rounding noise and so is the direction of du x dv. There the normal is taken a
    // growing step inside the domain: the limit a display wants.
    auto reliable = [](const FirstDerivatives& d, Vector3& n) {
        const double a = d.du.norm(), b = d.dv.norm();
        n = d.du.cross(d.dv);
        return a > 1e-8 * b && b > 1e-8 * a && n.norm() > 1e-10 * a * b;
    };
    Vector3 n;
    if (reliable(derivatives(u, v), n)) return n.normalized();
    const double um = 0.5 * (u_.first() + u_.last()), vm = 0.5 * (v_.first() + v_.last());
    for (double step = 1e-6; step <= 0.5; step *= 4) {
        if (reliable(derivatives(u + step * (um - u), v + step * (vm - v)), n))
            return n.normalized();
    }
    return Vector3(0, 0, 1);
}

const BSplineSurface& BSplineSurface::validated() const {
    if (auto why = problem()) throw std::invalid_argument(*why);
    return *this;
}

std::optional<std::string> BSplineSurface::problem() const {
    if (countU_ < 2 || countV_ < 2) return "fewer than 2 control points in u or v";
    if (static_cast<int>(poles_.size()) != countU_ * countV_)
        return "control point count does not match the grid";
    if (auto p = u_.problem(countU_)) return "u knots: " + *p;
    if (auto p = v_.problem(countV_)) return "v knots: " + *p;
    for (size_t k = 0; k < poles_.size(); ++k) {
        const auto& p = poles_[k];
        if (!p.allFinite()) return "control point " + std::to_string(k) + " is not finite";
        if (!(p[3] > 0)) return "weight of control point " + std::to_string(k) + " is <= 0";
    }
    return std::nullopt;
}

}  // namespace nurbslod
