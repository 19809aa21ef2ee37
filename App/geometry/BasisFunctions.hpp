#pragma once

#include "geometry/KnotVector.hpp"

namespace nurbslod {

// The degree+1 non-zero B-spline basis functions at t in span `span`, written to out[0..degree]
// (NURBS Book, algorithm A2.2, the triangular Cox-de Boor scheme without divisions by zero).
void basisFunctions(const KnotVector& knots, int span, double t, double* out);

// Basis functions and their first derivatives at t: values[0..degree], derivatives[0..degree]
// (NURBS Book, algorithm A2.3 restricted to the first derivative).
void basisFunctionsWithDerivative(const KnotVector& knots, int span, double t, double* values,
                                  double* derivatives);

// Largest degree the fixed-size scratch buffers of the evaluators accept.
inline constexpr int kMaxDegree = 40;

}  // namespace nurbslod
