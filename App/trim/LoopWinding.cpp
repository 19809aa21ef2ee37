#include "trim/LoopWinding.hpp"

#include <algorithm>
#include <cmath>

namespace nurbslod {

std::vector<Point2> loopPolygon(const TrimLoop& loop, int samplesPerCurve) {
    std::vector<Point2> polygon;
    for (const TrimCurve& curve : loop.curves)
        for (int k = 0; k <= samplesPerCurve; ++k) {
            const double s = double(k) / samplesPerCurve;
            const double along = curve.reversed ? 1 - s : s;
            polygon.push_back(curve.pcurve.point(curve.first + along * (curve.last - curve.first)));
        }
    return polygon;
}

double signedArea(const std::vector<Point2>& polygon) {
    double twice = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x() * b.y() - a.y() * b.x();
    }
    return 0.5 * twice;
}

bool insidePolygon(const std::vector<Point2>& polygon, const Point2& p) {
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) &&
            p.x() < a.x() + (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()))
            inside = !inside;
    }
    return inside;
}

namespace {

// A polygon that closes in (u, v) (its last curve ends where its first starts, to a
// thousandth of its extent) and encloses an area that is more than rounding. A loop on a closed
// surface that goes round it without a seam (a circle of a cylinder on its own) does not close
// in (u, v), and has no winding to compare.
bool windingIsMeaningful(const TrimLoop& loop, const std::vector<Point2>& polygon) {
    if (polygon.size() < 3 || loop.curves.empty()) return false;
    Point2 low = polygon.front(), high = polygon.front();
    for (const Point2& p : polygon) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const double extent = (high - low).norm();
    const TrimCurve& last = loop.curves.back();
    const Point2 end = last.pcurve.point(last.reversed ? last.first : last.last);
    return extent > 0 && (end - polygon.front()).norm() <= 1e-3 * extent &&
           std::abs(signedArea(polygon)) > 1e-9 * extent * extent;
}

}  // namespace

std::optional<std::string> loopWindingProblem(const TrimmedSurface& face) {
    const auto outer = std::find_if(face.loops.begin(), face.loops.end(),
                                    [](const TrimLoop& loop) { return loop.outer; });
    if (outer == face.loops.end()) return std::nullopt;
    const std::vector<Point2> outerPolygon = loopPolygon(*outer);
    if (!windingIsMeaningful(*outer, outerPolygon)) return std::nullopt;
    const double outerArea = signedArea(outerPolygon);
    for (size_t l = 0; l < face.loops.size(); ++l) {
        if (face.loops[l].outer) continue;
        const std::vector<Point2> polygon = loopPolygon(face.loops[l]);
        if (!windingIsMeaningful(face.loops[l], polygon)) continue;
        // most of it inside: a hole may touch the outer wire
        const auto inside = std::count_if(polygon.begin(), polygon.end(), [&](const Point2& p) {
            return insidePolygon(outerPolygon, p);
        });
        if (10 * inside >= 9 * static_cast<long>(polygon.size()) &&
            (signedArea(polygon) > 0) == (outerArea > 0))
            return "wire " + std::to_string(l + 1) +
                   " is a hole that runs the same way round as the outer wire (an invalid "
                   "face): meshed as a hole";
    }
    return std::nullopt;
}

}  // namespace nurbslod
