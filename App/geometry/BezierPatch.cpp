#include "geometry/BezierPatch.hpp"

#include <type_traits>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

namespace {

// The degrees point() sums on the stack: a surface's (kMaxDegree) and its difference patch's
// one more (CellErrorBound's degree elevation).
constexpr int kMostPointDegree = kMaxDegree + 1;

}  // namespace

BezierPatch::BezierPatch(int degreeU, int degreeV)
    : degreeU_(degreeU),
      degreeV_(degreeV),
      poles_(static_cast<size_t>((degreeU + 1) * (degreeV + 1)), HomogeneousPoint3::Zero()) {}

namespace {

// Keep the left part [0, t] of the curve: after de Casteljau at t the left control points are
// the first point of each level. `width` curves side by side (control point i of curve w at
// pts[i * stride + w]) are cut together, a run of adjacent points per step: the same
// operations on each point as curve by curve.
template <class Width = std::integral_constant<int, 1>>
void keepLeft(HomogeneousPoint3* pts, int degree, int stride, double t, Width width = {}) {
    for (int level = 1; level <= degree; ++level)
        for (int i = degree; i >= level; --i) {
            HomogeneousPoint3 *to = pts + i * stride, *before = pts + (i - 1) * stride;
            for (int w = 0; w < width; ++w) to[w] = (1 - t) * before[w] + t * to[w];
        }
}

// Keep the right part [t, 1]: the last point of each level.
template <class Width = std::integral_constant<int, 1>>
void keepRight(HomogeneousPoint3* pts, int degree, int stride, double t, Width width = {}) {
    for (int level = 1; level <= degree; ++level)
        for (int i = 0; i <= degree - level; ++i) {
            HomogeneousPoint3 *to = pts + i * stride, *after = pts + (i + 1) * stride;
            for (int w = 0; w < width; ++w) to[w] = (1 - t) * to[w] + t * after[w];
        }
}

// Both halves at 1/2 from one de Casteljau triangle: the left half into pts, the right half
// into right (same stride), which holds a copy of pts on entry. Each triangle value is (1 - t)
// left + t right of the level above, the expression of keepLeft and keepRight, so the halves
// are theirs to the last bit. `width` curves side by side, as keepLeft takes them.
template <class Width = std::integral_constant<int, 1>>
void splitInHalves(HomogeneousPoint3* pts, HomogeneousPoint3* right, int degree, int stride,
                   Width width = {}) {
    constexpr double t = 0.5;
    // keepRight in `right`, taking the left half's points off its first slot
    for (int level = 1; level <= degree; ++level) {
        for (int i = 0; i <= degree - level; ++i) {
            HomogeneousPoint3 *to = right + i * stride, *after = right + (i + 1) * stride;
            for (int w = 0; w < width; ++w) to[w] = (1 - t) * to[w] + t * after[w];
        }
        for (int w = 0; w < width; ++w) pts[level * stride + w] = right[w];
    }
}

}  // namespace

std::array<BezierPatch, 2> BezierPatch::halves(int direction) const {
    std::array<BezierPatch, 2> out{*this, *this};
    const int stride = degreeV_ + 1;
    if (direction == 0) {
        // every column at once, a whole row of the net per step (as restricted() cuts along u)
        splitInHalves(out[0].poles_.data(), out[1].poles_.data(), degreeU_, stride, stride);
    } else {
        for (int i = 0; i <= degreeU_; ++i)
            splitInHalves(&out[0].poles_[i * stride], &out[1].poles_[i * stride], degreeV_, 1);
    }
    return out;
}

std::array<BezierPatch, 4> BezierPatch::quarters() const {
    // u first, as restricted() cuts: the halves along u, then each half along v
    const auto alongU = halves(0);
    auto low = alongU[0].halves(1), high = alongU[1].halves(1);
    return {std::move(low[0]), std::move(low[1]), std::move(high[0]), std::move(high[1])};
}

void restrictBezierCurve(HomogeneousPoint3* pts, int degree, int stride, double a, double b,
                         int width) {
    // one curve, the hot case of the v direction, with its width known to the compiler
    auto cut = [&](auto curves) {
        if (b < 1.0) keepLeft(pts, degree, stride, b, curves);
        if (a > 0.0 && b > 0.0) keepRight(pts, degree, stride, a / b, curves);
    };
    if (width == 1)
        cut(std::integral_constant<int, 1>{});
    else
        cut(width);
}

BezierPatch BezierPatch::restricted(double u0, double u1, double v0, double v1) const {
    BezierPatch out = *this;
    const int stride = degreeV_ + 1;
    // every column at once along u, a whole row of the net per step
    if (u0 > 0.0 || u1 < 1.0)
        restrictBezierCurve(out.poles_.data(), degreeU_, stride, u0, u1, stride);
    if (v0 > 0.0 || v1 < 1.0)
        for (int i = 0; i <= degreeU_; ++i)
            restrictBezierCurve(&out.poles_[i * stride], degreeV_, 1, v0, v1);
    return out;
}

namespace {

// Bernstein polynomials B_{k,degree}(s), k = 0..degree, by the recurrence
// B_{k,d} = (1 - s) B_{k,d-1} + s B_{k-1,d-1}: sums of non-negative terms, no cancellation.
void bernstein(int degree, double s, double* values) {
    values[0] = 1.0;
    for (int d = 1; d <= degree; ++d) {
        values[d] = s * values[d - 1];
        for (int k = d - 1; k >= 1; --k) values[k] = (1 - s) * values[k] + s * values[k - 1];
        values[0] *= (1 - s);
    }
}

}  // namespace

Point3 BezierPatch::point(double s, double t) const {
    // (m + 1)(n + 1) products of poles by Bernstein values, where de Casteljau takes
    // (m + 1) n^2 / 2 blends (and two buffers): the kd-tree's centre tests evaluate a patch of
    // degree 8 x 11 at one point each (trj7_b1-ec-214.stp's domes)
    if (degreeU_ > kMostPointDegree || degreeV_ > kMostPointDegree)
        return gridPointsAt({s}, {t}).front();
    double basisU[kMostPointDegree + 1], basisV[kMostPointDegree + 1];
    bernstein(degreeU_, s, basisU);
    bernstein(degreeV_, t, basisV);
    HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
    for (int i = 0; i <= degreeU_; ++i) {
        HomogeneousPoint3 row = HomogeneousPoint3::Zero();
        for (int j = 0; j <= degreeV_; ++j) row += basisV[j] * pole(i, j);
        sum += basisU[i] * row;
    }
    return projectHomogeneous(sum);
}

std::vector<Point3> BezierPatch::gridPoints(int segmentsU, int segmentsV) const {
    std::vector<double> us(static_cast<size_t>(segmentsU + 1)),
        vs(static_cast<size_t>(segmentsV + 1));
    for (int i = 0; i <= segmentsU; ++i)
        us[i] = segmentsU > 0 ? static_cast<double>(i) / segmentsU : 0.0;
    for (int j = 0; j <= segmentsV; ++j)
        vs[j] = segmentsV > 0 ? static_cast<double>(j) / segmentsV : 0.0;
    return gridPointsAt(us, vs);
}

std::vector<Point3> BezierPatch::gridPointsAt(const std::vector<double>& us,
                                              const std::vector<double>& vs) const {
    const int m = degreeU_, n = degreeV_;
    const int countU = static_cast<int>(us.size()), countV = static_cast<int>(vs.size());
    std::vector<double> basisV(static_cast<size_t>(countV * (n + 1)));
    for (int j = 0; j < countV; ++j) bernstein(n, vs[j], &basisV[j * (n + 1)]);
    // rows[j * (m + 1) + i] = sum over l of B_l(t_j) P_il: the patch's u-curve at t_j
    std::vector<HomogeneousPoint3> rows(static_cast<size_t>(countV * (m + 1)),
                                        HomogeneousPoint3::Zero());
    for (int j = 0; j < countV; ++j)
        for (int i = 0; i <= m; ++i)
            for (int l = 0; l <= n; ++l)
                rows[j * (m + 1) + i] += basisV[j * (n + 1) + l] * pole(i, l);
    std::vector<Point3> points(static_cast<size_t>(countU * countV));
    std::vector<double> basisU(static_cast<size_t>(m + 1));
    for (int i = 0; i < countU; ++i) {
        bernstein(m, us[i], basisU.data());
        for (int j = 0; j < countV; ++j) {
            HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
            for (int k = 0; k <= m; ++k) sum += basisU[k] * rows[j * (m + 1) + k];
            points[i * countV + j] = projectHomogeneous(sum);
        }
    }
    return points;
}

}  // namespace nurbslod
