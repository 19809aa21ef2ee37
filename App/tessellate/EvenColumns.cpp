#include "tessellate/EvenColumns.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "trim/CurveOnSurface.hpp"

namespace nurbslod {

namespace {

// At most this many columns a span that settle as whole cells (wing.brep's faces, one long
// span each, take 65 to 108 at relative 1e-4: 6,657 triangles instead of 7,792 with halvings).
constexpr int kMostColumns = 256;

// At most this many columns a span that the kd-tree cuts across into rows: beyond, halving is
// as good. Up to 256 the loft of tests/bench/generated_shapes.py took 18,756 triangles instead
// of 47,520 at relative 1e-4, and twice the instructions; the helical sweep 760 more, a sphere
// segment 516 more.
constexpr int kMostColumnsCutAcross = 64;

// How many times the kd-tree may halve a column across before the column counts as too wide
// (1,024 rows a span).
constexpr int kRowDepth = 10;

// Columns cut across are taken where their count is at most this share of the next power of
// two. Measured on the 7 corpus files and the 25 generated shapes at relative 1e-3 and 1e-4:
// at 0.85 a sphere at 1e-4 takes 33,564 triangles instead of 38,264, a filleted cylinder
// 19,280 instead of 24,344, the loft 4,502 instead of 6,788 at 1e-3 and bug28366_fuselage.stp
// 20,438 instead of 22,096; a torus at 1e-3 4,236 instead of 4,068 and a quarter-torus elbow
// 2,060 instead of 1,964 (their inner rows need far fewer columns than their outer ones).
// 0.9 took more such losses. Comparing kd-trees simulated both ways, instead, chose about as
// well and cost three times the face's tessellation.
constexpr double kRowColumnsShare = 0.85;

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
                                 int axis, double target, ErrorMode mode, bool flatCellsByDistance,
                                 bool cutAcross) {
    const KdTreeGrid& grid = grids[axis];
    const KdTreeGrid& other = grids[1 - axis];
    const std::vector<std::int64_t> intervals = grid.intervals();
    const std::vector<std::int64_t> across = other.intervals();
    std::vector<int> needs(intervals.size() - 1, 0);
    if (!(target > 0)) return needs;
    const BezierPatchGrid patches(face.surface);
    // What the kd-tree decides for the cell [c0, c1] x [o0, o1] (along and across the axis),
    // filled to its sides: whether it settles, and where not, the direction it is cut in. As
    // there, a cell whose centre is off by more than the target is cut without its bound (the
    // costliest part of these searches), in the direction its bound would give in guaranteed
    // mode (the farthest control point's).
    struct Verdict {
        bool settles = false;
        int splitDirection = 0;
    };
    auto cellPiece = [&](double c0, double c1, double o0, double o1) {
        const double u0 = axis == 0 ? c0 : o0, u1 = axis == 0 ? c1 : o1;
        const double v0 = axis == 0 ? o0 : c0, v1 = axis == 0 ? o1 : c1;
        return patches.piece(patches.spanIndexU(0.5 * (u0 + u1)),
                             patches.spanIndexV(0.5 * (v0 + v1)), u0, u1, v0, v1);
    };
    auto cellVerdict = [&](double c0, double c1, double o0, double o1) {
        const BezierPatch piece = cellPiece(c0, c1, o0, o1);
        if (mode == ErrorMode::Guaranteed && centreBeyond(piece, target))
            return Verdict{false, preferredSplit(piece).direction};
        const CellErrorBound bound =
            cellErrorBound(piece, mode, target, false, flatCellsByDistance);
        return Verdict{bound.measure(mode, false) <= target, bound.splitDirection};
    };
    // Whether the kd-tree leaves the column [c0, c1] over [o0, o1] whole along the axis: the
    // cell settles, or it is cut across (halving [o0, o1]) and each half does.
    std::function<bool(double, double, double, double, int)> rowsSettle =
        [&](double c0, double c1, double o0, double o1, int depth) {
            const Verdict verdict = cellVerdict(c0, c1, o0, o1);
            if (verdict.settles) return true;
            if (depth == 0 || verdict.splitDirection == axis) return false;
            const double middle = 0.5 * (o0 + o1);
            return rowsSettle(c0, c1, o0, middle, depth - 1) &&
                   rowsSettle(c0, c1, middle, o1, depth - 1);
        };
    // whether column c of k equal ones over [a, b] settles over each span across: as one cell,
    // or (byRows) as the cells the kd-tree cuts it into across
    auto columnSettles = [&](std::int64_t a, std::int64_t b, int k, int c, bool byRows) {
        const double c0 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c));
        const double c1 = grid.parameterAt(KdTreeGrid::columnLine(a, b, k, c + 1));
        for (std::size_t j = 0; j + 1 < across.size(); ++j) {
            const double o0 = other.parameterAt(across[j]), o1 = other.parameterAt(across[j + 1]);
            if (byRows ? !rowsSettle(c0, c1, o0, o1, kRowDepth)
                       : !cellVerdict(c0, c1, o0, o1).settles)
                return false;
        }
        return true;
    };
    // The fewest equal columns of [a, b] that settle as whole cells over each span across, 0
    // where none up to kMostColumns do. The columns of a surface of revolution differ only as
    // its arcs' parameter runs unevenly: the search tries the first, middle and last, and the
    // count found is then checked on every column (one more at a time where one fails).
    auto fewestColumns = [&](std::int64_t a, std::int64_t b) {
        auto likelyMeets = [&](int k) {
            for (const int c : {0, k / 2, k - 1})
                if (!columnSettles(a, b, k, c, false)) return false;
            return true;
        };
        // the bound falls about with the square of a column's width
        const BezierPatch whole =
            cellPiece(grid.parameterAt(a), grid.parameterAt(b), other.parameterAt(across[0]),
                      other.parameterAt(across[1]));
        const double ratio =
            cellErrorBound(whole, mode, target, false, flatCellsByDistance).measure(mode, false) /
            target;
        int fails = 1;
        int count = std::isfinite(ratio)
                        ? std::clamp(static_cast<int>(std::ceil(std::sqrt(ratio))), 2, kMostColumns)
                        : 2;
        while (!likelyMeets(count)) {
            fails = count;
            if (count == kMostColumns) return 0;  // not even the most columns: halvings
            count = std::min(kMostColumns, count + std::max(1, count / 4));
        }
        while (count - fails > 1) {
            const int middle = (fails + count) / 2;
            (likelyMeets(middle) ? count : fails) = middle;
        }
        for (; count <= kMostColumns; ++count) {
            bool all = true;
            for (int c = 0; c < count && all; ++c) all = columnSettles(a, b, count, c, false);
            if (all) return count;
        }
        return 0;
    };
    // Columns the kd-tree cuts across into rows (a sphere's, a torus's, a freeform patch's):
    // their need differs from row to row, and the kd-tree's halvings follow that where equal
    // columns cannot, so they are taken only where their count is well under the power of two
    // P that the halvings give the neediest rows (kRowColumnsShare). Each test cuts a column
    // into its rows, the costliest part, and a test that passes must visit every row, so most
    // tests take the middle column alone and none is run twice: an interval the halvings give
    // at most 4 columns is dropped after one test, P is found on the middle column, and an
    // interval whose share of P does not meet there is dropped after one more. The fewest
    // count is searched below that share on the middle column and checked on five columns
    // spread over the span, one more at a time while the share itself meets on the five. Where
    // it does not, another column needs more (a B-spline's uneven spans): the halvings give it
    // 2P, and the search goes on there. Over the 7 corpus files and the 25 generated shapes at
    // relative 1e-3 and 1e-4 these searches took 0.29 s of 2.6 s of tessellation (0.48 s when
    // the five were checked before the count was searched and every cell's bound was made).
    auto columnsCutAcross = [&](std::int64_t a, std::int64_t b) {
        std::map<std::pair<int, int>, bool> tested;
        auto meets = [&](int k, std::initializer_list<int> columns) {
            for (const int c : columns) {
                auto [it, fresh] = tested.try_emplace({k, c}, false);
                if (fresh) it->second = columnSettles(a, b, k, c, true);
                if (!it->second) return false;
            }
            return true;
        };
        auto spreadMeet = [&](int k) { return meets(k, {k / 2, 0, k / 4, 3 * k / 4, k - 1}); };
        // where halvings need at most 4 columns, equal ones save at most one
        if (meets(4, {2})) return 0;
        int power = 8;
        while (power <= kMostColumnsCutAcross && !meets(power, {power / 2})) power *= 2;
        for (; power <= kMostColumnsCutAcross; power *= 2) {
            const int most = static_cast<int>(kRowColumnsShare * power);
            if (!meets(most, {most / 2})) return 0;
            int fails = power / 2, count = most;
            while (count - fails > 1) {
                const int middle = (fails + count) / 2;
                (meets(middle, {middle / 2}) ? count : fails) = middle;
            }
            for (; count <= most; ++count) {
                if (spreadMeet(count)) return count;
                if (!spreadMeet(most)) break;  // a column elsewhere needs more: halvings give it 2P
            }
        }
        return 0;
    };
    for (std::size_t i = 0; i + 1 < intervals.size(); ++i) {
        const std::int64_t a = intervals[i], b = intervals[i + 1];
        if (columnSettles(a, b, 1, 0, false)) {
            needs[i] = 1;
            continue;
        }
        needs[i] = fewestColumns(a, b);
        if (needs[i] == 0 && cutAcross) needs[i] = columnsCutAcross(a, b);
    }
    return needs;
}

}  // namespace nurbslod
