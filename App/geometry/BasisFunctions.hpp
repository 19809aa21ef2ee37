#pragma once

#include "geometry/KnotVector.hpp"

namespace nurbslod {

// Largest degree the fixed-size scratch buffers of the evaluators accept.
inline constexpr int kMaxDegree = 40;

// The binomial coefficient C(n, k) as a double, by the product of (n - k + i) / i.
inline double binomial(int n, int k) {
    double c = 1;
    for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
    return c;
}

// The degree+1 non-zero B-spline basis functions at t in span `span`, written to out[0..degree]
// (NURBS Book, algorithm A2.2, the triangular Cox-de Boor scheme without divisions by zero).
void basisFunctions(const KnotVector& knots, int span, double t, double* out);

// The triangular table of algorithm A2.3 (NURBS Book): ndu[r][j] (r <= j) is N_{span-j+r,j}(t),
// the basis functions of every degree j up to the knots' degree, and ndu[j][r] (r < j) the knot
// difference u_{span+r+1} - u_{span+1-j+r}, from which the derivatives follow. A knot
// difference of zero gives 0 instead of a division by zero, as in basisFunctions.
void basisFunctionTable(const KnotVector& knots, int span, double t, double (*ndu)[kMaxDegree + 1]);

// Basis functions and their first derivatives at t: values[0..degree], derivatives[0..degree]
// (NURBS Book, algorithm A2.3 restricted to the first derivative).
void basisFunctionsWithDerivative(const KnotVector& knots, int span, double t, double* values,
                                  double* derivatives);

}  // namespace nurbslod
