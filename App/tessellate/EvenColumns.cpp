#include "tessellate/EvenColumns.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "trim/CurveOnSurface.hpp"

namespace nurbslod {

namespace {

// At most this many columns a span: beyond, halving is as good.
constexpr int kMostColumns = 64;

}  // namespace

bool regionIsTheBox(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids) {
    double low[2], high[2];
    for (int axis = 0; axis < 2; ++axis) {
        low[axis] = grids[axis].parameterAt(0);
        high[axis] = grids[axis].parameterAt(kKdTreeFrameScale);
    }
    auto near = [&](double value, double side, int axis) {
        return std::abs(value - side) <= 1e-12 * (high[axis] - low[axis]);
    };
    for (const auto& loop : face.loops)
        for (const auto& curve : loop.curves) {
            const CurveOnSurface use(face.surface, curve.pcurve, curve.first, curve.last);
            if (!use.straightInParameterPlane()) return false;
            const Point2 a = use.uv(0), b = use.uv(1);
            bool onSide = false;
            for (int axis = 0; axis < 2 && !onSide; ++axis)
                for (double side : {low[axis], high[axis]})
                    onSide |= near(a[axis], side, axis) && near(b[axis], side, axis);
            if (!onSide) return false;
        }
    return true;
}

double regionShareOfBox(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids) {
    double width[2];
    for (int axis = 0; axis < 2; ++axis)
        width[axis] = grids[axis].parameterAt(kKdTreeFrameScale) - grids[axis].parameterAt(0);
    // each loop's area by the shoelace sum over its curves sampled evenly, in the loop's order;
    // the orientation of loops is not trusted (the tessellator fills by the even-odd rule), so
    // the largest loop is taken as the outer one and the others as holes in it
    constexpr int kSamples = 16;
    std::vector<double> areas;
    for (const auto& loop : face.loops) {
        double twiceArea = 0;
        for (const auto& curve : loop.curves) {
            const CurveOnSurface use(face.surface, curve.pcurve, curve.first, curve.last);
            auto at = [&](int k) {
                const double s = double(k) / kSamples;
                return use.uv(curve.reversed ? 1 - s : s);
            };
            Point2 previous = at(0);
            for (int k = 1; k <= kSamples; ++k) {
                const Point2 next = at(k);
                twiceArea += previous.x() * next.y() - next.x() * previous.y();
                previous = next;
            }
        }
        areas.push_back(0.5 * std::abs(twiceArea));
    }
    if (areas.empty()) return 0;
    std::sort(areas.begin(), areas.end());
    double region = areas.back();
    for (std::size_t k = 0; k + 1 < areas.size(); ++k) region -= areas[k];
    const double box = width[0] * width[1];
    return box > 0 ? std::clamp(region / box, 0.0, 1.0) : 0.0;
}

std::vector<int> evenColumnNeeds(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids,
                                 int axis, double target, ErrorMode mode,
                                 bool flatCellsByDistance) {
    const KdTreeGrid& grid = grids[axis];
    const KdTreeGrid& other = grids[1 - axis];
    const std::vector<std::int64_t> intervals = grid.intervals();
    const std::vector<std::int64_t> across = other.intervals();
    std::vector<int> needs(intervals.size() - 1, 0);
    if (!(target > 0)) return needs;
    const BezierPatchGrid patches(face.surface);
    // the kd-tree's bound of the cell [c0, c1] x [o0, o1] (along and across the axis), filled
    // to its sides
    auto cellBound = [&](double c0, double c1, double o0, double o1) {
        const double u0 = axis == 0 ? c0 : o0, u1 = axis == 0 ? c1 : o1;
        const double v0 = axis == 0 ? o0 : c0, v1 = axis == 0 ? o1 : c1;
        const BezierPatch piece =
            patches.piece(patches.spanIndexU(0.5 * (u0 + u1)), patches.spanIndexV(0.5 * (v0 + v1)),
                          u0, u1, v0, v1);
        return cellErrorBound(piece, mode, target, false, flatCellsByDistance).measure(mode, false);
    };
    auto settles = [&](double c0, double c1, double o0, double o1) {
        return cellBound(c0, c1, o0, o1) <= target;
    };
    auto columnSettles = [&](std::int64_t a, std::int64_t b, int k, int c) {
        const double c0 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c));
        const double c1 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c + 1));
        for (std::size_t j = 0; j + 1 < across.size(); ++j)
            if (!settles(c0, c1, other.parameterAt(across[j]), other.parameterAt(across[j + 1])))
                return false;
        return true;
    };
    for (std::size_t i = 0; i + 1 < intervals.size(); ++i) {
        const std::int64_t a = intervals[i], b = intervals[i + 1];
        if (columnSettles(a, b, 1, 0)) {
            needs[i] = 1;
            continue;
        }
        // The columns of a surface of revolution differ only as its arcs' parameter runs
        // unevenly: the search tries the first, middle and last, and the count found is then
        // checked on every column (one more at a time where one fails).
        auto likelyMeets = [&](int k) {
            for (int c : {0, k / 2, k - 1})
                if (!columnSettles(a, b, k, c)) return false;
            return true;
        };
        // the bound falls about with the square of a column's width
        const double ratio = cellBound(grid.parameterAt(a), grid.parameterAt(b),
                                       other.parameterAt(across[0]), other.parameterAt(across[1])) /
                             target;
        int fails = 1;
        int count = std::isfinite(ratio)
                        ? std::clamp(static_cast<int>(std::ceil(std::sqrt(ratio))), 2, kMostColumns)
                        : 2;
        while (!likelyMeets(count)) {
            fails = count;
            if (count == kMostColumns) break;
            count = std::min(kMostColumns, count + std::max(1, count / 4));
        }
        if (fails == count) continue;  // not even the most columns: halvings
        while (count - fails > 1) {
            const int middle = (fails + count) / 2;
            (likelyMeets(middle) ? count : fails) = middle;
        }
        for (; count <= kMostColumns; ++count) {
            bool all = true;
            for (int c = 0; c < count && all; ++c) all = columnSettles(a, b, count, c);
            if (all) break;
        }
        if (count <= kMostColumns) needs[i] = count;
    }
    return needs;
}

}  // namespace nurbslod
