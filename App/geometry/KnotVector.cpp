#include "geometry/KnotVector.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

KnotVector::KnotVector(int degree, std::vector<double> knots)
    : degree_(degree), knots_(std::move(knots)) {
    // Rows for degrees past what problem() accepts are not needed: such a vector is refused
    // before anything evaluates on it.
    const int rows = std::clamp(degree_, 0, kMaxDegree);
    const size_t m = knots_.size();
    reciprocals_.assign(static_cast<size_t>(rows) * m, 0.0);
    for (int j = 1; j <= rows; ++j) {
        double* row = &reciprocals_[static_cast<size_t>(j - 1) * m];
        for (size_t i = 0; i + j < m; ++i) {
            const double difference = knots_[i + j] - knots_[i];
            row[i] = difference != 0.0 ? 1.0 / difference : 0.0;
        }
    }
    bezierSpans_.assign(m, 0);
    for (int i = rows; rows > 0 && i + rows < static_cast<int>(m); ++i) {
        bool bezier = knots_[i + 1] > knots_[i];
        for (int k = 1; k < rows && bezier; ++k)
            bezier = knots_[i - k] == knots_[i] && knots_[i + 1 + k] == knots_[i + 1];
        bezierSpans_[i] = bezier;
    }
    if (degree_ >= 0 && m >= static_cast<size_t>(2 * degree_ + 2)) {
        const int n = static_cast<int>(m) - degree_ - 1;  // control points
        int spans = 0, span = -1;
        for (int i = degree_; i < n; ++i)
            if (knots_[i + 1] > knots_[i]) ++spans, span = i;
        if (spans == 1) onlySpan_ = span;
    }
}

int KnotVector::findSpan(double t) const {
    if (onlySpan_ >= 0) return onlySpan_;
    const int n = controlPointCount() - 1;
    if (t >= knots_[n + 1]) {
        // last non-empty span
        int i = n;
        while (i > degree_ && knots_[i] >= knots_[n + 1]) --i;
        return i;
    }
    if (t <= knots_[degree_]) {
        int i = degree_;
        while (i < n && knots_[i + 1] <= knots_[degree_]) ++i;
        return i;
    }
    // upper_bound gives the first knot > t; the span starts one before it
    auto it = std::upper_bound(knots_.begin() + degree_, knots_.begin() + n + 1, t);
    return static_cast<int>(it - knots_.begin()) - 1;
}

std::vector<double> KnotVector::breakpoints() const {
    std::vector<double> out;
    const double a = first(), b = last();
    for (double k : knots_) {
        if (k < a || k > b) continue;
        if (out.empty() || k > out.back()) out.push_back(k);
    }
    return out;
}

std::optional<std::string> KnotVector::problem(int controlPoints) const {
    if (degree_ < 1) return "degree " + std::to_string(degree_) + " is below 1";
    if (degree_ > kMaxDegree)
        return "degree " + std::to_string(degree_) + " is above " + std::to_string(kMaxDegree);
    if (static_cast<int>(knots_.size()) != controlPoints + degree_ + 1)
        return std::to_string(knots_.size()) + " knots do not fit " +
               std::to_string(controlPoints) + " control points of degree " +
               std::to_string(degree_);
    for (size_t i = 0; i < knots_.size(); ++i) {
        if (!std::isfinite(knots_[i])) return "knot " + std::to_string(i) + " is not finite";
        if (i > 0 && knots_[i] < knots_[i - 1])
            return "knots decrease at index " + std::to_string(i);
    }
    if (!(last() > first())) return "the knot vector spans an empty parameter range";
    // a multiplicity above degree+1 would make the curve discontinuous
    for (size_t i = 0, j; i < knots_.size(); i = j) {
        for (j = i; j < knots_.size() && knots_[j] == knots_[i]; ++j) {
        }
        if (static_cast<int>(j - i) > degree_ + 1)
            return "knot " + std::to_string(knots_[i]) + " has multiplicity above degree+1";
    }
    return std::nullopt;
}

}  // namespace nurbslod
