#include "geometry/BezierReparametrization.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

namespace {

// The Bernstein coefficients of the product of two polynomials given by theirs.
std::vector<double> product(const std::vector<double>& f, const std::vector<double>& g) {
    const int p = static_cast<int>(f.size()) - 1, q = static_cast<int>(g.size()) - 1;
    std::vector<double> h(static_cast<size_t>(p + q + 1), 0.0);
    for (int k = 0; k <= p; ++k)
        for (int l = 0; l <= q; ++l)
            h[k + l] += binomial(p, k) * binomial(q, l) / binomial(p + q, k + l) * f[k] * g[l];
    return h;
}

// coefficients[i][r]: B^m_i(alpha(s)) in the Bernstein basis of degree 2m.
std::vector<std::vector<double>> composedBasis(int m, double a) {
    const double middle = 0.5 * (1 + a);
    const std::vector<double> alpha{0.0, middle, 1.0}, rest{1.0, 1 - middle, 0.0};
    std::vector<std::vector<double>> alphaPower{{1.0}}, restPower{{1.0}};
    for (int k = 1; k <= m; ++k) {
        alphaPower.push_back(product(alphaPower.back(), alpha));
        restPower.push_back(product(restPower.back(), rest));
    }
    std::vector<std::vector<double>> coefficients;
    for (int i = 0; i <= m; ++i) {
        std::vector<double> c = product(alphaPower[i], restPower[m - i]);
        for (double& x : c) x *= binomial(m, i);
        coefficients.push_back(std::move(c));
    }
    return coefficients;
}

// a for the sides of `patch` along u (s), each a row j = 0 and j = degreeV.
double evenSpeedAlongU(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    if (m < 2) return 0;  // a line runs at even speed in its own parameter
    double sum = 0;
    for (const int j : {0, n}) {
        const Point3 first = patch.pole3(0, j), last = patch.pole3(m, j);
        const Point3 chord = last - first;
        const double length2 = chord.squaredNorm();
        if (!(length2 > 0) || !std::isfinite(length2)) return 0;
        const double w0 = patch.pole(0, j)[3], w1 = patch.pole(1, j)[3];
        const double wLast = patch.pole(m, j)[3], wBefore = patch.pole(m - 1, j)[3];
        const double start = m * w1 / w0 * (patch.pole3(1, j) - first).dot(chord) / length2;
        const double end =
            m * wBefore / wLast * (last - patch.pole3(m - 1, j)).dot(chord) / length2;
        if (!(start > 0) || !(end > 0)) return 0;
        sum += 0.5 * (1 / start - 1 / end);
    }
    const double a = 0.5 * sum;
    return std::isfinite(a) ? std::clamp(a, -0.75, 0.75) : 0.0;
}

// The patch with its u and v exchanged.
BezierPatch exchanged(const BezierPatch& patch) {
    BezierPatch out(patch.degreeV(), patch.degreeU());
    for (int i = 0; i <= patch.degreeU(); ++i)
        for (int j = 0; j <= patch.degreeV(); ++j) out.pole(j, i) = patch.pole(i, j);
    return out;
}

// S(alpha(s), t).
BezierPatch reparametrizedAlongU(const BezierPatch& patch, double a) {
    const int m = patch.degreeU(), n = patch.degreeV();
    if (a == 0 || m == 0) return patch;
    const auto coefficients = composedBasis(m, a);
    BezierPatch out(2 * m, n);
    for (int r = 0; r <= 2 * m; ++r)
        for (int j = 0; j <= n; ++j) {
            HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
            for (int i = 0; i <= m; ++i) sum += coefficients[i][r] * patch.pole(i, j);
            out.pole(r, j) = sum;
        }
    return out;
}

}  // namespace

BezierPatch reparametrized(const BezierPatch& patch, double a, double b) {
    return exchanged(reparametrizedAlongU(exchanged(reparametrizedAlongU(patch, a)), b));
}

EvenSpeed evenSpeed(const BezierPatch& patch) {
    return {evenSpeedAlongU(patch), evenSpeedAlongU(exchanged(patch))};
}

}  // namespace nurbslod
