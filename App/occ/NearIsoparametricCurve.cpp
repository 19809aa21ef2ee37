#include "occ/NearIsoparametricCurve.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace nurbslod::occ {

double straightenNearIsoparametric(const BSplineSurface& surface, TrimCurve& curve, double within) {
    // samples along the curve; the largest move between them is taken as a tenth more
    constexpr int kSamples = 64;
    constexpr double kBetweenSamples = 1.1;
    constexpr double kEndMove = 1e-2;
    if (!(within > 0) || !std::isfinite(within) || curve.degenerated || curve.seam) return 0;
    const auto& poles = curve.pcurve.poles();
    if (poles.size() < 2) return 0;
    for (const auto& pole : poles)
        if (!(pole.z() > 0) || !pole.allFinite()) return 0;
    const Point2 start = curve.pcurve.point(curve.first), end = curve.pcurve.point(curve.last);
    for (int axis = 0; axis < 2; ++axis) {
        // the line midway between the ends
        const double value = 0.5 * (start[axis] + end[axis]);
        double spread = 0;
        for (const auto& pole : poles)
            spread = std::max(spread, std::abs(pole[axis] / pole.z() - value));
        if (spread == 0) return 0;  // on the line already
        // how far the surface point at uv moves when uv goes onto the line
        auto moveOf = [&](const Point2& uv) {
            Point2 onLine = uv;
            onLine[axis] = value;
            return (surface.point(uv.x(), uv.y()) - surface.point(onLine.x(), onLine.y())).norm();
        };
        // The ends stay where they are, within a hundredth of the tolerance: they sit on the
        // B-rep's vertices, where the neighbouring curves end too (moved ends opened
        // trj7_b1-ec-214.stp at relative 1e-4 along 6 more edges).
        if (!(std::max(moveOf(start), moveOf(end)) <= kEndMove * within)) continue;
        double moved = 0;
        for (int k = 0; k <= kSamples; ++k)
            moved = std::max(moved, moveOf(curve.pcurve.point(
                                        curve.first + (curve.last - curve.first) * k / kSamples)));
        moved *= kBetweenSamples;
        if (!(moved <= within)) continue;
        std::vector<HomogeneousPoint2> straight = poles;
        for (auto& pole : straight) pole[axis] = value * pole.z();
        if (!curve.beforeStraightening) curve.beforeStraightening = curve.pcurve;
        curve.pcurve = BSplineCurve2d(curve.pcurve.knots(), std::move(straight));
        return moved;
    }
    return 0;
}

}  // namespace nurbslod::occ
