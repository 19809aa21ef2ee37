#pragma once

#include <optional>
#include <string>
#include <vector>

namespace nurbslod {

// A clamped or unclamped knot vector of a B-spline of a given degree, in flat form (each knot
// repeated by its multiplicity). The valid parameter range is [knots[degree], knots[m-degree]].
class KnotVector {
public:
    KnotVector() = default;
    KnotVector(int degree, std::vector<double> knots);

    int degree() const { return degree_; }
    const std::vector<double>& knots() const { return knots_; }
    int controlPointCount() const { return static_cast<int>(knots_.size()) - degree_ - 1; }
    double first() const { return knots_[degree_]; }
    double last() const { return knots_[knots_.size() - degree_ - 1]; }

    // Index i of the span with knots[i] <= t < knots[i+1], degree <= i < controlPointCount;
    // t outside the range is clamped to the first or last non-empty span.
    int findSpan(double t) const;

    // The distinct knot values in [first(), last()], i.e. the Bezier segment boundaries.
    std::vector<double> breakpoints() const;

    // Why this knot vector cannot carry `controlPoints` control points, or nothing if it can.
    std::optional<std::string> problem(int controlPoints) const;

private:
    int degree_ = 0;
    std::vector<double> knots_;
};

}  // namespace nurbslod
