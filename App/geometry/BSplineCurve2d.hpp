#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/KnotVector.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// A (rational) B-spline curve in a surface's parameter plane: a trimming curve (pcurve).
// Control points are homogeneous (w u, w v, w).
class BSplineCurve2d {
public:
    BSplineCurve2d() = default;
    BSplineCurve2d(KnotVector knots, std::vector<HomogeneousPoint2> weightedPoles);

    const KnotVector& knots() const { return knots_; }
    int degree() const { return knots_.degree(); }
    const std::vector<HomogeneousPoint2>& poles() const { return poles_; }

    Point2 point(double t) const;
    // Point and first derivative with respect to t.
    std::pair<Point2, Point2> pointAndDerivative(double t) const;

    std::optional<std::string> problem() const;

private:
    KnotVector knots_;
    std::vector<HomogeneousPoint2> poles_;
};

}  // namespace nurbslod
