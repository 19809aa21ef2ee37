#pragma once

#include <span>
#include <vector>

#include "geometry/KnotVector.hpp"

namespace nurbslod {

// The basis functions and their first derivatives of one direction of a surface, once per grid
// parameter: the first stage of grid evaluation that every B-spline method shares (evaluation
// paper, section 2.2: computed and stored per direction, then used at each parametric pair).
struct GridBasis {
    int degree = 0;
    std::vector<double> parameter;  // clamped to the knot vector's domain
    std::vector<int> span;
    std::vector<double> values, derivatives;  // (degree + 1) per parameter

    const double* valuesAt(size_t k) const { return &values[k * (degree + 1)]; }
    const double* derivativesAt(size_t k) const { return &derivatives[k * (degree + 1)]; }
};

// Throws std::invalid_argument naming the parameter (`name`[k]) when one is not finite.
GridBasis makeGridBasis(const KnotVector& knots, std::span<const double> parameters, char name);

}  // namespace nurbslod
