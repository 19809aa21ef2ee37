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

    // Row j (1 <= j <= degree) of the reciprocal knot differences: row[i] = 1 / (knots[i + j] -
    // knots[i]), or 0 where the two knots are equal. The Cox-de Boor recursion divides by exactly
    // these differences, whatever the parameter; a multiplication by a kept reciprocal is several
    // times quicker than the division, which dominated the evaluation of single points.
    const double* reciprocalDifferences(int j) const {
        return &reciprocals_[static_cast<size_t>(j - 1) * knots_.size()];
    }

private:
    int degree_ = 0;
    std::vector<double> knots_;
    std::vector<double> reciprocals_;
};

}  // namespace nurbslod
