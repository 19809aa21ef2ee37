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

    // Whether span i is a Bezier segment: the degree knots on each side of it equal its ends,
    // so that its basis functions are the Bernstein polynomials in (t - knots[i]) /
    // (knots[i + 1] - knots[i]). Every span of a single-segment patch, and of most patches
    // that files carry (Bezier pieces of degree 5 to 16 on the corpus), is one.
    bool isBezierSpan(int i) const { return bezierSpans_[static_cast<size_t>(i)] != 0; }

private:
    int degree_ = 0;
    std::vector<double> knots_;
    std::vector<double> reciprocals_;
    std::vector<char> bezierSpans_;
    // the span findSpan returns for every t where there is only one (a single Bezier segment,
    // as most of the corpus's patches and trimming curves are), else -1
    int onlySpan_ = -1;
};

}  // namespace nurbslod
