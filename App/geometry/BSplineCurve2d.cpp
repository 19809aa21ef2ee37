#include "geometry/BSplineCurve2d.hpp"

#include <algorithm>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

BSplineCurve2d::BSplineCurve2d(KnotVector knots, std::vector<HomogeneousPoint2> weightedPoles)
    : knots_(std::move(knots)), poles_(std::move(weightedPoles)) {}

Point2 BSplineCurve2d::point(double t) const {
    t = std::clamp(t, knots_.first(), knots_.last());
    const int p = knots_.degree();
    const int span = knots_.findSpan(t);
    double N[kMaxDegree + 1];
    basisFunctions(knots_, span, t, N);
    HomogeneousPoint2 sum = HomogeneousPoint2::Zero();
    for (int k = 0; k <= p; ++k) sum += N[k] * poles_[span - p + k];
    return projectHomogeneous(sum);
}

std::pair<Point2, Point2> BSplineCurve2d::pointAndDerivative(double t) const {
    t = std::clamp(t, knots_.first(), knots_.last());
    const int p = knots_.degree();
    const int span = knots_.findSpan(t);
    double N[kMaxDegree + 1], dN[kMaxDegree + 1];
    basisFunctionsWithDerivative(knots_, span, t, N, dN);
    HomogeneousPoint2 c = HomogeneousPoint2::Zero(), dc = c;
    for (int k = 0; k <= p; ++k) {
        c += N[k] * poles_[span - p + k];
        dc += dN[k] * poles_[span - p + k];
    }
    const Point2 point = c.head<2>() / c[2];
    return {point, (dc.head<2>() - dc[2] * point) / c[2]};
}

std::optional<std::string> BSplineCurve2d::problem() const {
    if (poles_.size() < 2) return "trimming curve has fewer than 2 control points";
    if (auto p = knots_.problem(static_cast<int>(poles_.size())))
        return "trimming curve knots: " + *p;
    for (size_t k = 0; k < poles_.size(); ++k) {
        if (!poles_[k].allFinite())
            return "trimming curve control point " + std::to_string(k) + " is not finite";
        if (!(poles_[k][2] > 0)) return "trimming curve weight " + std::to_string(k) + " is <= 0";
    }
    return std::nullopt;
}

}  // namespace nurbslod
