#include "trim/EdgeDiscretizer.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/SegmentDistance.hpp"

namespace nurbslod {

namespace {

// Deep enough for any real edge (2^-24 of its length); a broken edge (a pcurve that jumps, a
// NaN) would otherwise split for ever: past kMaxPoints the remaining pieces are taken as they are.
constexpr int kMaxDepth = 24;
constexpr size_t kMaxPoints = 4096;

bool flatEnough(std::vector<CurvePoints>& uses, double s0, double s1, double eps) {
    // The curve's middle point farther than eps from the chord rules the piece out at the cost
    // of one point: the bound below is at least that far, and the pieces of the first levels
    // of a subdivision are all ruled out so (chordBound took most of the edges' time).
    const double middle = 0.5 * (s0 + s1);
    for (auto& use : uses)
        if (distanceToSegment(use(middle), use(s0), use(s1)) > eps) return false;
    for (auto& use : uses) {
        const ChordBound b = chordBound(use, s0, s1);
        // a large residual means the interpolant does not yet represent the piece: its hull
        // bound would not be trustworthy, so subdivide
        if (b.bound > eps || b.residual > 0.25 * eps) return false;
    }
    return true;
}

}  // namespace

bool chordSettles(std::vector<CurvePoints>& uses, double s0, double s1, double approximation) {
    return flatEnough(uses, s0, s1, approximation);
}

std::vector<CurvePoints> curvePointsOf(const std::vector<CurveOnSurface>& uses) {
    std::vector<CurvePoints> points;
    for (const auto& use : uses) points.emplace_back(use);
    return points;
}

std::vector<double> discretizeEdgeByLongestChords(const std::vector<CurveOnSurface>& uses,
                                                  double approximation, double simplification) {
    std::vector<CurvePoints> curves = curvePointsOf(uses);
    const double bound = approximation + std::max(0.0, simplification);
    const double shortest = std::ldexp(1.0, -kMaxDepth);
    std::vector<double> params{0.0};
    double start = 0, step = 1;
    while (start < 1) {
        const double left = 1 - start;
        auto flat = [&](double length) {
            return length <= shortest || params.size() >= kMaxPoints ||
                   flatEnough(curves, start, length >= left ? 1.0 : start + length, bound);
        };
        double good = 0, bad = 0;  // a length that is flat, and one that is not (0: none known)
        double trial = std::min(step, left);
        while (true) {
            if (flat(trial)) {
                good = trial;
                if (trial >= left) break;
                trial = std::min(2 * trial, left);
            } else {
                bad = trial;
                if (good > 0) break;
                trial *= 0.5;
            }
        }
        for (int i = 0; i < 6 && bad > 0 && good < left; ++i) {
            const double middle = 0.5 * (good + bad);
            if (flat(middle))
                good = middle;
            else
                bad = middle;
        }
        if (good >= left) {
            params.push_back(1.0);
            break;
        }
        start += good;
        params.push_back(start);
        step = good;
    }
    return params;
}

std::vector<double> discretizeEdge(const std::vector<CurveOnSurface>& uses, double approximation,
                                   double simplification, const PieceHalving& halving,
                                   std::vector<CurvePoints>* points) {
    std::vector<CurvePoints> own;
    std::vector<CurvePoints>& curves = points ? *points : (own = curvePointsOf(uses));
    std::vector<double> params{0.0};
    // depth-first over [s0, s1] so that the parameters come out in increasing order
    std::vector<std::pair<std::pair<double, double>, int>> stack{{{0.0, 1.0}, 0}};
    while (!stack.empty()) {
        auto [interval, depth] = stack.back();
        stack.pop_back();
        auto [s0, s1] = interval;
        if (depth < kMaxDepth && params.size() + stack.size() < kMaxPoints &&
            !flatEnough(curves, s0, s1, approximation)) {
            double mid = 0.5 * (s0 + s1);
            if (halving) {
                // anything but a point strictly inside would loop or reorder the parameters
                const double at = halving(s0, s1);
                if (at > s0 && at < s1) mid = at;
            }
            stack.push_back({{mid, s1}, depth + 1});
            stack.push_back({{s0, mid}, depth + 1});
            continue;
        }
        params.push_back(s1);
    }
    if (params.size() <= 2 || simplification <= 0) return params;

    // Douglas-Peucker on the 3D polylines of all uses at once: a point goes only if every
    // face's polyline stays within `simplification` of the simplified one.
    std::vector<std::vector<Point3>> polylines(uses.size());
    for (size_t k = 0; k < uses.size(); ++k)
        for (double s : params) polylines[k].push_back(curves[k](s));
    std::vector<char> keep(params.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<size_t, size_t>> ranges{{0, params.size() - 1}};
    while (!ranges.empty()) {
        auto [a, b] = ranges.back();
        ranges.pop_back();
        if (b <= a + 1) continue;
        double worst = -1;
        size_t worstIndex = a + 1;
        for (size_t i = a + 1; i < b; ++i) {
            double d = 0;
            for (const auto& polyline : polylines)
                d = std::max(d, distanceToSegment(polyline[i], polyline[a], polyline[b]));
            if (d > worst) worst = d, worstIndex = i;
        }
        // a closed edge (start == end) has a zero chord; never collapse it below 3 points
        bool closedChord = false;
        for (const auto& polyline : polylines)
            closedChord |= (polyline[a] - polyline[b]).norm() <= 1e-12;
        if (worst > simplification || (closedChord && a == 0 && b == params.size() - 1)) {
            keep[worstIndex] = 1;
            ranges.push_back({a, worstIndex});
            ranges.push_back({worstIndex, b});
        }
    }
    std::vector<double> simplified;
    for (size_t i = 0; i < params.size(); ++i)
        if (keep[i]) simplified.push_back(params[i]);
    return simplified;
}

std::vector<double> mergeChords(const std::vector<CurveOnSurface>& uses,
                                const std::vector<double>& params, double approximation,
                                double simplification, std::vector<CurvePoints>* points) {
    if (params.size() < 3) return params;
    std::vector<CurvePoints> own;
    std::vector<CurvePoints>& curves = points ? *points : (own = curvePointsOf(uses));
    const double bound = approximation + std::max(0.0, simplification);
    std::vector<double> merged{params.front()};
    for (size_t i = 0; i + 1 < params.size();) {
        size_t j = i + 1;
        while (j + 1 < params.size() && flatEnough(curves, params[i], params[j + 1], bound)) ++j;
        merged.push_back(params[j]);
        i = j;
    }
    return merged;
}

}  // namespace nurbslod
