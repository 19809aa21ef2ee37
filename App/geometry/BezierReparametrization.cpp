#include "geometry/BezierReparametrization.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

namespace {

// C(n, k) for n <= 2 kMaxDegree, each the double binomial() gives: the products below take
// their coefficients from here instead of a loop of k divisions each (the reparametrisation
// was 7% of bottle.brep's tessellation at relative 1e-4, most of it in those loops and in the
// vectors of its polynomials).
struct BinomialTable {
    static constexpr int kLargest = 2 * kMaxDegree;
    std::array<std::array<double, kLargest + 1>, kLargest + 1> c{};
    BinomialTable() {
        for (int n = 0; n <= kLargest; ++n)
            for (int k = 0; k <= n; ++k) c[n][k] = binomial(n, k);
    }
};
const BinomialTable& binomials() {
    static const BinomialTable table;
    return table;
}

// h (degree p + q) = f (degree p) times g (degree q), all by Bernstein coefficients: the
// product formula, summed in the same order for every caller.
void product(const double* f, int p, const double* g, int q, double* h) {
    const auto& c = binomials().c;
    std::fill(h, h + p + q + 1, 0.0);
    for (int k = 0; k <= p; ++k)
        for (int l = 0; l <= q; ++l) h[k + l] += c[p][k] * c[q][l] / c[p + q][k + l] * f[k] * g[l];
}

// coefficients[i * (2m + 1) + r]: B^m_i(alpha(s)) in the Bernstein basis of degree 2m.
// alpha^k and (1 - alpha)^k, degree 2k, are rows of `alphaPower` and `restPower`.
void composedBasis(int m, double a, std::vector<double>& coefficients) {
    const int width = 2 * m + 1;
    thread_local std::vector<double> alphaPower, restPower;
    alphaPower.assign(static_cast<size_t>((m + 1) * width), 0.0);
    restPower.assign(static_cast<size_t>((m + 1) * width), 0.0);
    const double middle = 0.5 * (1 + a);
    const double alpha[3] = {0.0, middle, 1.0}, rest[3] = {1.0, 1 - middle, 0.0};
    alphaPower[0] = restPower[0] = 1.0;
    for (int k = 1; k <= m; ++k) {
        product(&alphaPower[(k - 1) * width], 2 * (k - 1), alpha, 2, &alphaPower[k * width]);
        product(&restPower[(k - 1) * width], 2 * (k - 1), rest, 2, &restPower[k * width]);
    }
    coefficients.resize(static_cast<size_t>((m + 1) * width));
    for (int i = 0; i <= m; ++i) {
        double* c = &coefficients[i * width];
        product(&alphaPower[i * width], 2 * i, &restPower[(m - i) * width], 2 * (m - i), c);
        const double scale = binomials().c[m][i];
        for (int r = 0; r < width; ++r) c[r] *= scale;
    }
}

// a for the sides along the first parameter of pole(i, j), i = 0..along, each a row j = 0 and
// j = across: u for (degreeU, degreeV, patch.pole), v for the poles with i and j exchanged.
template <class Pole>
double evenSpeedAlong(int along, int across, const Pole& pole) {
    const int m = along;
    if (m < 2) return 0;  // a line runs at even speed in its own parameter
    double sum = 0;
    for (const int j : {0, across}) {
        const Point3 first = projectHomogeneous(pole(0, j)), last = projectHomogeneous(pole(m, j));
        const Point3 chord = last - first;
        const double length2 = chord.squaredNorm();
        if (!(length2 > 0) || !std::isfinite(length2)) return 0;
        const double w0 = pole(0, j)[3], w1 = pole(1, j)[3];
        const double wLast = pole(m, j)[3], wBefore = pole(m - 1, j)[3];
        const double start =
            m * w1 / w0 * (projectHomogeneous(pole(1, j)) - first).dot(chord) / length2;
        const double end =
            m * wBefore / wLast * (last - projectHomogeneous(pole(m - 1, j))).dot(chord) / length2;
        if (!(start > 0) || !(end > 0)) return 0;
        sum += 0.5 * (1 / start - 1 / end);
    }
    const double a = 0.5 * sum;
    return std::isfinite(a) ? std::clamp(a, -0.75, 0.75) : 0.0;
}

// S(alpha(s), t) where alongU, S(s, beta(t)) otherwise; the patch itself where the coefficient
// is 0 or the degree along that direction is.
BezierPatch reparametrizedAlong(const BezierPatch& patch, double a, bool alongU) {
    const int m = alongU ? patch.degreeU() : patch.degreeV();
    if (a == 0 || m == 0) return patch;
    thread_local std::vector<double> coefficients;
    composedBasis(m, a, coefficients);
    const int width = 2 * m + 1;
    const int across = alongU ? patch.degreeV() : patch.degreeU();
    BezierPatch out = alongU ? BezierPatch(2 * m, across) : BezierPatch(across, 2 * m);
    for (int r = 0; r <= 2 * m; ++r)
        for (int j = 0; j <= across; ++j) {
            HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
            for (int i = 0; i <= m; ++i)
                sum += coefficients[i * width + r] * (alongU ? patch.pole(i, j) : patch.pole(j, i));
            (alongU ? out.pole(r, j) : out.pole(j, r)) = sum;
        }
    return out;
}

}  // namespace

BezierPatch reparametrized(const BezierPatch& patch, double a, double b) {
    return reparametrizedAlong(reparametrizedAlong(patch, a, true), b, false);
}

EvenSpeed evenSpeed(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    return {evenSpeedAlong(
                m, n, [&](int i, int j) -> const HomogeneousPoint3& { return patch.pole(i, j); }),
            evenSpeedAlong(
                n, m, [&](int i, int j) -> const HomogeneousPoint3& { return patch.pole(j, i); })};
}

}  // namespace nurbslod
