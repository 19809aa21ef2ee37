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

// Every trimming curve straight in (u, v) and on one side of the frame's box: the region is the
// box, and the kd-tree's cells are all full or filled to their sides.
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

}  // namespace

bool chooseEvenColumns(const TrimmedSurface& face, std::array<KdTreeGrid, 2>& grids, double target,
                       ErrorMode mode, bool flatCellsByDistance, std::array<bool, 2> axes) {
    if (!(target > 0) || !(axes[0] || axes[1]) || !regionIsTheBox(face, grids)) return false;
    const BezierPatchGrid patches(face.surface);
    bool any = false;
    for (int axis = 0; axis < 2; ++axis) {
        if (!axes[axis]) continue;
        const KdTreeGrid& grid = grids[axis];
        const KdTreeGrid& other = grids[1 - axis];
        const std::vector<std::int64_t> intervals = grid.intervals();
        const std::vector<std::int64_t> across = other.intervals();
        // the largest measure of the cells [column c of k] x [each span across], as the kd-tree
        // bounds a cell the region fills to its sides
        auto largestMeasure = [&](std::int64_t a, std::int64_t b, int k, int c) {
            double largest = 0;
            const double c0 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c));
            const double c1 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c + 1));
            for (std::size_t j = 0; j + 1 < across.size(); ++j) {
                const double o0 = other.parameterAt(across[j]);
                const double o1 = other.parameterAt(across[j + 1]);
                const double u0 = axis == 0 ? c0 : o0, u1 = axis == 0 ? c1 : o1;
                const double v0 = axis == 0 ? o0 : c0, v1 = axis == 0 ? o1 : c1;
                const BezierPatch piece =
                    patches.piece(patches.spanIndexU(0.5 * (u0 + u1)),
                                  patches.spanIndexV(0.5 * (v0 + v1)), u0, u1, v0, v1);
                const CellErrorBound bound =
                    cellErrorBound(piece, mode, target, false, flatCellsByDistance);
                largest = std::max(largest, bound.measure(mode, false));
            }
            return largest;
        };
        std::vector<int> counts(intervals.size() - 1, 0);
        for (std::size_t i = 0; i + 1 < intervals.size(); ++i) {
            const std::int64_t a = intervals[i], b = intervals[i + 1];
            const double whole = largestMeasure(a, b, 1, 0);
            if (!(whole > target) || !std::isfinite(whole)) continue;  // no cut, or no bound
            auto meets = [&](int k) {
                for (int c = 0; c < k; ++c)
                    if (!(largestMeasure(a, b, k, c) <= target)) return false;
                return true;
            };
            // From an estimate (a bulge falls with the square of the width; the bound of a wide
            // cell is looser, so it may be high or low), up by quarters until a count meets the
            // target, then the fewest between the last that did not and it.
            int fails = 1;
            int count =
                std::clamp(static_cast<int>(std::ceil(std::sqrt(whole / target))), 2, kMostColumns);
            while (!meets(count)) {
                fails = count;
                if (count == kMostColumns) break;
                count = std::min(kMostColumns, count + std::max(1, count / 4));
            }
            if (fails == count) continue;  // not even the most columns: halvings
            while (count - fails > 1) {
                const int middle = (fails + count) / 2;
                (meets(middle) ? count : fails) = middle;
            }
            counts[i] = count;
        }
        if (std::any_of(counts.begin(), counts.end(), [](int k) { return k >= 2; })) {
            grids[axis].setEvenColumns(counts);
            any = true;
        }
    }
    return any;
}

}  // namespace nurbslod
