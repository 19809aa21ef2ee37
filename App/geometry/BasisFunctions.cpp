#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

namespace {

// Binomial coefficients C(p, k) for p up to kMaxDegree, exact in a double (C(40, 20) < 2^53).
struct BinomialTable {
    double value[kMaxDegree + 1][kMaxDegree + 1] = {};
    constexpr BinomialTable() {
        for (int p = 0; p <= kMaxDegree; ++p) {
            value[p][0] = value[p][p] = 1;
            for (int k = 1; k < p; ++k) value[p][k] = value[p - 1][k - 1] + value[p - 1][k];
        }
    }
};
constexpr BinomialTable kBinomial;

}  // namespace

void basisFunctions(const KnotVector& knots, int span, double t, double* out) {
    const int p = knots.degree();
    const auto& U = knots.knots();
    if (knots.isBezierSpan(span)) {
        // The Bernstein polynomials C(p, k) x^k (1 - x)^(p - k) from two tables of powers:
        // O(p) products where the triangular scheme below takes O(p^2) (the surface points of
        // the edges' chord bounds on degree-16 patches spent most of their time there). Both
        // x and 1 - x are taken from their own knot, so neither loses digits near its end.
        const double reciprocal = knots.reciprocalDifferences(1)[span];
        const double x = (t - U[span]) * reciprocal, y = (U[span + 1] - t) * reciprocal;
        double powerX[kMaxDegree + 1], powerY[kMaxDegree + 1];
        powerX[0] = powerY[0] = 1.0;
        for (int k = 1; k <= p; ++k) {
            powerX[k] = powerX[k - 1] * x;
            powerY[k] = powerY[k - 1] * y;
        }
        for (int k = 0; k <= p; ++k) out[k] = kBinomial.value[p][k] * powerX[k] * powerY[p - k];
        return;
    }
    double left[kMaxDegree + 1], right[kMaxDegree + 1];
    out[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - U[span + 1 - j];
        right[j] = U[span + j] - t;
        // right[r + 1] + left[j - r] is the knot difference U[span + r + 1] - U[span + 1 - j + r]
        const double* reciprocal = knots.reciprocalDifferences(j) + (span + 1 - j);
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = out[r] * reciprocal[r];
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

void basisFunctionTable(const KnotVector& knots, int span, double t,
                        double (*ndu)[kMaxDegree + 1]) {
    const int p = knots.degree();
    const auto& U = knots.knots();
    double left[kMaxDegree + 1], right[kMaxDegree + 1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - U[span + 1 - j];
        right[j] = U[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const double temp = ndu[j][r] != 0.0 ? ndu[r][j - 1] / ndu[j][r] : 0.0;
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
}

void basisFunctionsWithDerivative(const KnotVector& knots, int span, double t, double* values,
                                  double* derivatives) {
    const int p = knots.degree();
    double ndu[kMaxDegree + 1][kMaxDegree + 1];
    basisFunctionTable(knots, span, t, ndu);
    for (int j = 0; j <= p; ++j) values[j] = ndu[j][p];
    if (p == 0) {
        derivatives[0] = 0.0;
        return;
    }
    // N'_{i,p} = p (N_{i,p-1}/(u_{i+p}-u_i) - N_{i+1,p-1}/(u_{i+p+1}-u_{i+1}))
    for (int r = 0; r <= p; ++r) {
        double d = 0.0;
        if (r >= 1) {
            const double denominator = ndu[p][r - 1];
            if (denominator != 0.0) d += ndu[r - 1][p - 1] / denominator;
        }
        if (r <= p - 1) {
            const double denominator = ndu[p][r];
            if (denominator != 0.0) d -= ndu[r][p - 1] / denominator;
        }
        derivatives[r] = p * d;
    }
}

}  // namespace nurbslod
