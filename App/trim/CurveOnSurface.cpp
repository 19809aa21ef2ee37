#include "trim/CurveOnSurface.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <vector>

#include "geometry/BasisFunctions.hpp"
#include "geometry/BitMix.hpp"
#include "geometry/SegmentDistance.hpp"

namespace nurbslod {

namespace {

// Pseudo-inverse of the Bernstein collocation matrix at t_i = i/n (paper section 4: "a linear
// system of equations with a nonsingular matrix", solved by SVD for stability). It depends only
// on the degree, so it is computed once per degree.
const Eigen::MatrixXd& interpolationMatrix(int n) {
    static std::array<Eigen::MatrixXd, kMaxChordDegree + 1> matrices;
    static std::once_flag once;
    std::call_once(once, [] {
        for (int degree = 1; degree <= kMaxChordDegree; ++degree) {
            Eigen::MatrixXd B(degree + 1, degree + 1);
            for (int i = 0; i <= degree; ++i) {
                const double t = static_cast<double>(i) / degree;
                for (int j = 0; j <= degree; ++j)
                    B(i, j) = binomial(degree, j) * std::pow(t, j) * std::pow(1 - t, degree - j);
            }
            Eigen::JacobiSVD<Eigen::MatrixXd> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
            Eigen::VectorXd inverse = svd.singularValues();
            for (int k = 0; k < inverse.size(); ++k) inverse[k] = 1.0 / inverse[k];
            matrices[degree] = svd.matrixV() * inverse.asDiagonal() * svd.matrixU().transpose();
        }
    });
    return matrices[n];
}

// A Bezier curve's control points, at most kMaxChordDegree + 1, held in place: chordBound runs
// for every piece that the edges' subdivision tries, and heap vectors there were a fifth of its
// time.
using ControlPoints = std::array<Point3, kMaxChordDegree + 1>;

// The Bernstein polynomials of degree n at the midpoints (i + 1/2) / n, i < n, where chordBound
// compares the interpolant with the curve: there the interpolant is a fixed sum of its control
// points, (n + 1) products per midpoint instead of de Casteljau's n (n + 1) / 2 (the residual
// was most of chordBound's own time). Each by the recurrence
// B_{k,d} = (1 - t) B_{k,d-1} + t B_{k-1,d-1}: sums of non-negative terms.
using MidpointBernstein = std::array<std::array<double, kMaxChordDegree + 1>, kMaxChordDegree>;
const MidpointBernstein& midpointBernstein(int n) {
    static std::array<MidpointBernstein, kMaxChordDegree + 1> tables;
    static std::once_flag once;
    std::call_once(once, [] {
        for (int degree = 1; degree <= kMaxChordDegree; ++degree)
            for (int i = 0; i < degree; ++i) {
                const double t = (i + 0.5) / degree;
                auto& values = tables[degree][i];
                values.fill(0.0);
                values[0] = 1.0;
                for (int d = 1; d <= degree; ++d) {
                    values[d] = t * values[d - 1];
                    for (int k = d - 1; k >= 1; --k)
                        values[k] = (1 - t) * values[k] + t * values[k - 1];
                    values[0] *= (1 - t);
                }
            }
    });
    return tables[n];
}

}  // namespace

Point3 CurvePoints::operator()(double s) {
    if (std::isnan(s)) return curve_->point(s);
    // 0 and -0 compare equal: one key
    const std::uint64_t key = std::bit_cast<std::uint64_t>(s == 0 ? 0.0 : s);
    if (2 * (points_.size() + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    std::size_t at = mixBits(key) & mask;
    while (slots_[at].key != kEmpty) {
        if (slots_[at].key == key) return points_[slots_[at].index];
        at = (at + 1) & mask;
    }
    // evaluated first: a point that throws leaves no slot behind
    const Point3 point = curve_->point(s);
    slots_[at] = {key, static_cast<std::uint32_t>(points_.size())};
    points_.push_back(point);
    if (evaluations_) ++*evaluations_;
    return points_.back();
}

void CurvePoints::grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : 2 * old.size(), Slot{kEmpty, 0});
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
        if (slot.key == kEmpty) continue;
        std::size_t at = mixBits(slot.key) & mask;
        while (slots_[at].key != kEmpty) at = (at + 1) & mask;
        slots_[at] = slot;
    }
}

ChordBound chordBound(const CurveOnSurface& curve, double s0, double s1) {
    CurvePoints points(curve);
    return chordBound(points, s0, s1);
}

ChordBound chordBound(CurvePoints& curve, double s0, double s1) {
    const int n = std::clamp(curve.curve().bezierDegree(), 1, kMaxChordDegree);
    const Eigen::MatrixXd& inverse = interpolationMatrix(n);
    ControlPoints samples;
    for (int i = 0; i <= n; ++i) samples[i] = curve(s0 + (s1 - s0) * i / n);
    // the interpolant passes through the samples, so the end points are exact
    ControlPoints control;
    control[0] = samples[0];
    control[n] = samples[n];
    for (int i = 1; i < n; ++i) {
        Point3 sum = Point3::Zero();
        for (int j = 0; j <= n; ++j) sum += inverse(i, j) * samples[j];
        control[i] = sum;
    }

    ChordBound result;
    const MidpointBernstein& atMidpoints = midpointBernstein(n);
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        const Point3 exact = curve(s0 + (s1 - s0) * t);
        Point3 interpolant = Point3::Zero();
        for (int j = 0; j <= n; ++j) interpolant += atMidpoints[i][j] * control[j];
        result.residual = std::max(result.residual, (exact - interpolant).norm());
    }
    // The control net of the whole piece stands up to about twice as far from the chord as the
    // curve does (a parabola's middle control point); split into quarters by de Casteljau, each
    // quarter lies in the hull of its own net, which lies in the whole net's hull and hugs the
    // curve 16 times closer. The distance to the chord is convex, so the largest over the
    // quarters' points bounds the curve (for a parabola: its sagitta exactly).
    double hull = 0;
    const Point3 chordStart = control[0], chordEnd = control[n];
    ControlPoints rest = control;
    for (int quarter = 0; quarter < 4; ++quarter) {
        ControlPoints piece;
        if (quarter < 3) {
            // split the rest at the parameter where the next quarter ends
            const double t = 1.0 / (4 - quarter);
            ControlPoints work = rest, right;
            for (int level = 0; level <= n; ++level) {
                piece[level] = work[0];
                right[n - level] = work[n - level];
                for (int i = 0; i < n - level; ++i) work[i] = (1 - t) * work[i] + t * work[i + 1];
            }
            rest = right;
        } else {
            piece = rest;
        }
        for (int i = 0; i <= n; ++i)
            hull = std::max(hull, distanceToSegment(piece[i], chordStart, chordEnd));
    }
    result.bound = hull + result.residual;
    return result;
}

bool CurveOnSurface::straightInParameterPlane() const {
    // The curve lies in the convex hull of its control points (positive weights): collinear
    // control points put it on their line. Control points in order along the line make it run
    // one way: by variation diminishing, no line across it meets the curve more than once.
    std::vector<Point2> points;
    for (const auto& pole : pcurve_->poles()) {
        if (!(pole.z() > 0)) return false;
        points.push_back(projectHomogeneous(pole));
        if (!points.back().allFinite()) return false;
    }
    if (points.size() < 2) return false;
    const Point2 direction = points.back() - points.front();
    const double length = direction.norm();
    if (!(length > 0)) return false;
    const Point2 along = direction / length;
    double last = -std::numeric_limits<double>::infinity();
    for (const Point2& p : points) {
        const Point2 d = p - points.front();
        if (std::abs(along.x() * d.y() - along.y() * d.x()) > 1e-12 * length) return false;
        const double t = along.dot(d);
        if (t < last - 1e-12 * length) return false;
        last = std::max(last, t);
    }
    return true;
}

double CurveOnSurface::parameterWhere(int coordinate, double value, double s0, double s1) const {
    double a = s0, b = s1;
    double fa = uv(a)[coordinate] - value, fb = uv(b)[coordinate] - value;
    if (fa == 0) return a;
    if (fb == 0) return b;
    if ((fa < 0) == (fb < 0)) return std::abs(fa) <= std::abs(fb) ? a : b;
    // regula falsi with the Illinois correction: exact at once where the coordinate is linear
    // in s (a line's pcurve), a few steps where it is rational; every 8th step bisects so that
    // an uneven piece still shrinks
    const double resolution = 1e-15 * (std::abs(fa) + std::abs(fb) + std::abs(value));
    int kept = 0;  // which end the last steps kept (-1: a, 1: b)
    for (int step = 0; step < 100 && b - a > 1e-16 * (1 + std::abs(a)); ++step) {
        double s = step % 8 == 7 ? 0.5 * (a + b) : a - fa * (b - a) / (fb - fa);
        if (!(s > a && s < b)) s = 0.5 * (a + b);
        const double fs = uv(s)[coordinate] - value;
        if (std::abs(fs) <= resolution) return s;
        if ((fs < 0) == (fa < 0)) {
            a = s, fa = fs;
            if (kept == 1) fb *= 0.5;
            kept = 1;
        } else {
            b = s, fb = fs;
            if (kept == -1) fa *= 0.5;
            kept = -1;
        }
    }
    return std::abs(fa) <= std::abs(fb) ? a : b;
}

}  // namespace nurbslod
