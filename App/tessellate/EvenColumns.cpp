#include "tessellate/EvenColumns.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "trim/CurveOnSurface.hpp"
#include "trim/EdgeDiscretizer.hpp"
#include "trim/LoopWinding.hpp"

namespace nurbslod {

namespace {

// At most this many columns a span that settle as whole cells (wing.brep's faces, one long
// span each, take 65 to 108 at relative 1e-4: 6,657 triangles instead of 7,792 with halvings).
// A cell whose bound is mostly twist (a loft's side whose straight lines turn as it rises)
// halves it only with each halving, so its span may need thousands: with at most 256, a
// twisted loft's sides took 2,048 rows of halvings at relative 1e-4, 16,388 triangles at 0.53 T,
// against 9,124 at 0.95 T with equal ones (EvenColumns.TwistedLoftTakesMoreThan256Columns).
constexpr int kMostColumns = 4096;
// Up to this many whole columns a span are taken whatever power of two the halvings would need.
constexpr int kColumnsAlwaysTaken = 256;
// The least share of the equal columns that graded ones must be estimated to save.
constexpr double kGradedSaving = 0.05;

// At most this many columns a span that the kd-tree cuts across into rows: beyond, halving is
// as good. Up to 256, at relative 1e-4, the loft of tests/bench/generated_shapes.py took 16,336
// triangles instead of 17,950, but the helical sweep 67,322 instead of 49,244 and the revolved
// profile 61,975 instead of 56,575.
constexpr int kMostColumnsCutAcross = 64;
// Up to twice as many where the columns run over one span across, but beyond
// kMostColumnsCutAcross only at most this share of the power of two. The generated sphere
// segment (latitudes -30 to 60 degrees, 270 of longitude) at relative 1e-4 then takes 77 and 65
// equal columns where its rows near the equator take 128 halved ones: 14,994 triangles instead
// of 16,994 (relative 1.2e-4 13,410 -> 12,522, 8e-5 22,046 -> 18,776). With a share of 0.9
// the helical sweep, also one span across, took 110 and 112 columns at relative 1e-4 and 11%
// more triangles (the loft, 106 and more, 2% fewer). Over several spans across, the rows'
// needs differ from span to span and the halvings follow them: the pipe along a spline (9
// spans) took 84 columns and 8.5% more. Nothing else changed over the 70 benchmark models and
// OpenCASCADE's 35 samples at relative 1e-3 and 1e-4 but Ball.brep at 1e-4 (0.998x).
constexpr int kMostColumnsCutAcrossOneSpan = 128;
constexpr double kOneSpanRowColumnsShare = 0.75;

// How many times the kd-tree may halve a column across before the column counts as too wide
// (1,024 rows a span).
constexpr int kRowDepth = 10;

// Columns cut across are taken where their count is at most this share of the next power of
// two. Measured on the 7 corpus files and the 25 generated shapes at relative 1e-3 and 1e-4:
// at 0.85 a sphere at 1e-4 took 33,564 triangles instead of 38,264, a filleted cylinder
// 19,280 instead of 24,344, the loft 4,502 instead of 6,788 at 1e-3 and bug28366_fuselage.stp
// 20,438 instead of 22,096; a torus at 1e-3 4,236 instead of 4,068 and a quarter-torus elbow
// 2,060 instead of 1,964 (their inner rows need far fewer columns than their outer ones).
// 0.9 took more such losses, while a column's rows were counted on halvings whatever lines the
// other axis took. Counted on those lines (rowsOf), a count near its power of two holds in the
// kd-tree too, and 0.95 took fewer: over the 70 models of the benchmarks at both tolerances
// 0.9914x the triangles of 0.85 before, against 0.9935x for 0.85 (the sphere at 1e-3 2,814
// against 3,072, the torus at 1e-4 34,392 against 36,864); over 16 tolerances from relative
// 1e-4 to 1e-3 on twelve spheres, tori, sweeps and lofts 0.939x against 0.952x. 1.0 and 128
// columns a span (kMostColumnsCutAcross) did not do better: the helical sweep at 1e-4 took 11%
// more with 128. Comparing kd-trees simulated both ways, instead, chose about as well and cost
// three times the face's tessellation.
constexpr double kRowColumnsShare = 0.95;

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
    std::vector<double> areas;
    for (const auto& loop : face.loops) areas.push_back(std::abs(signedArea(loopPolygon(loop))));
    if (areas.empty()) return 0;
    std::sort(areas.begin(), areas.end());
    double region = areas.back();
    for (std::size_t k = 0; k + 1 < areas.size(); ++k) region -= areas[k];
    const double box = width[0] * width[1];
    return box > 0 ? std::clamp(region / box, 0.0, 1.0) : 0.0;
}

struct ColumnTest::Verdict {
    bool settles = false;
    int splitDirection = 0;
};

ColumnTest::ColumnTest(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids, int axis,
                       double target, ErrorMode mode, bool flatCellsByDistance,
                       std::vector<ChordsAlong> chords,
                       std::shared_ptr<const BezierPatchGrid> patches)
    : grid_(grids[axis]),
      other_(grids[1 - axis]),
      across_(grids[1 - axis].intervals()),
      patches_(patches ? std::move(patches)
                       : std::make_shared<const BezierPatchGrid>(face.surface)),
      axis_(axis),
      target_(target),
      mode_(mode),
      flatCellsByDistance_(flatCellsByDistance),
      chords_(std::move(chords)) {
    for (const auto& edge : chords_) chordPoints_.push_back(curvePointsOf(edge.uses));
}

bool ColumnTest::chordsSettle(std::int64_t x0, std::int64_t x1) const {
    const double c0 = grid_.parameterAt(x0), c1 = grid_.parameterAt(x1);
    for (std::size_t e = 0; e < chords_.size(); ++e) {
        const CurveOnSurface& own = chords_[e].uses[chords_[e].own];
        const double from = own.uv(0)[axis_], to = own.uv(1)[axis_];
        const double low = std::max(c0, std::min(from, to)),
                     high = std::min(c1, std::max(from, to));
        if (!(high > low)) continue;  // the edge runs elsewhere
        const double s0 = own.parameterWhere(axis_, low, 0, 1);
        const double s1 = own.parameterWhere(axis_, high, 0, 1);
        if (!chordSettles(chordPoints_[e], std::min(s0, s1), std::max(s0, s1),
                          chords_[e].approximation))
            return false;
    }
    return true;
}

ColumnTest::~ColumnTest() = default;

BezierPatch ColumnTest::cellPiece(double c0, double c1, double o0, double o1) const {
    const double u0 = axis_ == 0 ? c0 : o0, u1 = axis_ == 0 ? c1 : o1;
    const double v0 = axis_ == 0 ? o0 : c0, v1 = axis_ == 0 ? o1 : c1;
    return patches_->piece(patches_->spanIndexU(0.5 * (u0 + u1)),
                           patches_->spanIndexV(0.5 * (v0 + v1)), u0, u1, v0, v1);
}

// What the kd-tree decides for the cell [c0, c1] x [o0, o1] (along and across the axis), filled
// to its sides: whether it settles, and where not, the direction it is cut in. As there, a cell
// whose centre is off by more than the target is cut without its bound (the costliest part of
// these searches), in the direction its bound would give in guaranteed mode.
ColumnTest::Verdict ColumnTest::cellVerdict(double c0, double c1, double o0, double o1) const {
    const BezierPatch piece = cellPiece(c0, c1, o0, o1);
    if (mode_ == ErrorMode::Guaranteed && centreBeyond(piece, target_))
        return Verdict{false, preferredSplitDirection(piece)};
    const CellErrorBound bound = cellErrorBound(piece, mode_, target_, false, flatCellsByDistance_);
    return Verdict{bound.measure(mode_, false) <= target_, bound.splitDirection};
}

// The rows the kd-tree cuts the column [c0, c1] over [y0, y1] (frame steps across) into,
// leaving it whole along the axis: 1 where the cell settles, otherwise the halves' rows, cut as
// the kd-tree cuts: on the other axis's middle even line where the cell holds two or more of
// its columns (FaceTessellator cuts along those before across a single column), else in the
// middle; -1 where it would be cut along the axis or deeper than `depth`.
int ColumnTest::rowsOf(double c0, double c1, std::int64_t y0, std::int64_t y1, int depth) const {
    const Verdict verdict = cellVerdict(c0, c1, other_.parameterAt(y0), other_.parameterAt(y1));
    if (verdict.settles) return 1;
    const std::optional<std::int64_t> even = other_.evenSplit(y0, y1);
    if (depth == 0 || y1 - y0 < 2 || (!even && verdict.splitDirection == axis_)) return -1;
    const std::int64_t middle = even ? *even : y0 + (y1 - y0 + 1) / 2;
    const int low = rowsOf(c0, c1, y0, middle, depth - 1);
    if (low < 0) return -1;
    const int high = rowsOf(c0, c1, middle, y1, depth - 1);
    return high < 0 ? -1 : low + high;
}

bool ColumnTest::settles(std::int64_t x0, std::int64_t x1) const {
    const double c0 = grid_.parameterAt(x0), c1 = grid_.parameterAt(x1);
    for (std::size_t j = 0; j + 1 < across_.size(); ++j) {
        const double o0 = other_.parameterAt(across_[j]), o1 = other_.parameterAt(across_[j + 1]);
        if (!cellVerdict(c0, c1, o0, o1).settles) return false;
    }
    return true;
}

int ColumnTest::rowCount(std::int64_t x0, std::int64_t x1) const {
    const double c0 = grid_.parameterAt(x0), c1 = grid_.parameterAt(x1);
    int rows = 0;
    for (std::size_t j = 0; j + 1 < across_.size(); ++j) {
        const int spanRows = rowsOf(c0, c1, across_[j], across_[j + 1], kRowDepth);
        if (spanRows < 0) return -1;
        rows += spanRows;
    }
    return rows;
}

double ColumnTest::wholeRatio(std::int64_t a, std::int64_t b) const {
    const BezierPatch whole =
        cellPiece(grid_.parameterAt(a), grid_.parameterAt(b), other_.parameterAt(across_[0]),
                  other_.parameterAt(across_[1]));
    return cellErrorBound(whole, mode_, target_, false, flatCellsByDistance_)
               .measure(mode_, false) /
           target_;
}

std::vector<std::int64_t> ColumnTest::gradedLines(std::int64_t a, std::int64_t b, int most) const {
    std::vector<std::int64_t> lines = greedyLines(a, b, most);
    const int count = static_cast<int>(lines.size()) - 1;
    if (count < 2) return lines;
    // Balanced: the greedy columns are each at the target but the last, which takes what is
    // left. The lines are drawn towards a by the share that gives the last one the mean
    // width; each column then is narrower than the greedy one near it and about as needy,
    // and kept where every column (and edge) still settles. None is then at the limit of its
    // bound, as equal columns but their neediest are not, which leaves the edges' chords a
    // margin too (wing.brep at relative 1e-4: 6,488 triangles instead of 6,573 unbalanced).
    const double mean = double(b - a) / count;
    const double share = (double(b - a) - mean) / double(lines[count - 1] - a);
    if (!(share < 1)) return lines;
    std::vector<std::int64_t> balanced{a};
    for (int c = 1; c < count; ++c)
        balanced.push_back(a + std::llround(double(lines[c] - a) * share));
    balanced.push_back(b);
    for (int c = 0; c < count; ++c)
        if (balanced[c + 1] <= balanced[c] || !columnAndChordsSettle(balanced[c], balanced[c + 1]))
            return lines;
    return balanced;
}

double ColumnTest::gradedCountEstimate(std::int64_t a, std::int64_t b, int k, double enough) const {
    constexpr int kPlaces = 4;
    const double equal = double(b - a) / k;
    auto centreOf = [&](int p) { return double(a) + (p + 0.5) * double(b - a) / kPlaces; };
    // whether the column of `width` around `centre`, inside the interval, settles
    auto settlesAround = [&](double centre, double width) {
        const double half = std::min({0.5 * width, centre - double(a), double(b) - centre});
        return columnAndChordsSettle(std::llround(centre - half), std::llround(centre + half));
    };
    // The estimate is k times the mean of equal / settled over the places: above `enough` where
    // each place settles less than (b - a) / enough, which one test a place tells (a column
    // within one that settles settles too). bug3883_xr2-ct-214_bolt.stp at relative 1e-3, whose
    // cylinders need their columns evenly, spent 28% of its tessellation's instructions on the
    // estimate's searches.
    bool mayReach = false;
    for (int p = 0; p < kPlaces && !mayReach; ++p)
        mayReach = settlesAround(centreOf(p), double(b - a) / enough);
    if (!mayReach) return std::numeric_limits<double>::infinity();
    double count = 0;
    for (int p = 0; p < kPlaces; ++p) {
        const double centre = centreOf(p);
        auto settlesAt = [&](double width) { return settlesAround(centre, width); };
        double settled = 0.5 * equal, failed = 2 * equal;
        if (!settlesAt(settled)) return std::numeric_limits<double>::infinity();
        if (settlesAt(failed)) settled = failed;
        while (failed - settled > equal / 16) {
            const double middle = 0.5 * (settled + failed);
            (settlesAt(middle) ? settled : failed) = middle;
        }
        count += double(b - a) / kPlaces / settled;
    }
    return count;
}

std::vector<std::int64_t> ColumnTest::greedyLines(std::int64_t a, std::int64_t b, int most) const {
    // a column's end is found to 1/1024 of the interval
    const std::int64_t precision = std::max<std::int64_t>(1, (b - a) >> 10);
    std::vector<std::int64_t> lines{a};
    std::int64_t x = a, width = std::max<std::int64_t>(precision, (b - a) / std::max(most, 1));
    while (x < b) {
        if (static_cast<int>(lines.size()) > most) return {};
        if (columnAndChordsSettle(x, b)) {
            lines.push_back(b);
            break;
        }
        // the farthest end y with [x, y] settling, b failing: grown from the last column's
        // width (a neighbour's need is about the same), then halved down to the precision
        std::int64_t settled = x, failed = b;
        std::int64_t y = std::min(x + width, b - 1);
        if (y > x && columnAndChordsSettle(x, y)) {
            settled = y;
            for (;;) {
                const std::int64_t grown = std::min(x + 2 * (y - x), b);
                if (grown == b) break;
                if (!columnAndChordsSettle(x, grown)) {
                    failed = grown;
                    break;
                }
                settled = y = grown;
            }
        } else if (y > x) {
            failed = y;
        }
        while (failed - settled > precision) {
            const std::int64_t middle = settled + (failed - settled) / 2;
            (columnAndChordsSettle(x, middle) ? settled : failed) = middle;
        }
        if (settled == x) return {};  // not even the narrowest column settles
        width = settled - x;
        lines.push_back(settled);
        x = settled;
    }
    return lines;
}

std::vector<std::vector<std::int64_t>> evenColumnLines(
    const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids, int axis, double target,
    ErrorMode mode, bool flatCellsByDistance, bool cutAcross, bool graded,
    std::vector<ChordsAlong> chords, std::shared_ptr<const BezierPatchGrid> patches) {
    const KdTreeGrid& grid = grids[axis];
    const std::vector<std::int64_t> intervals = grid.intervals();
    std::vector<std::vector<std::int64_t>> lines(intervals.size() - 1);
    if (!(target > 0)) return lines;
    const ColumnTest test(face, grids, axis, target, mode, flatCellsByDistance, std::move(chords),
                          std::move(patches));
    // whether column c of k equal ones over [a, b] settles over each span across as one cell
    auto columnSettles = [&](std::int64_t a, std::int64_t b, int k, int c) {
        return test.settles(KdTreeGrid::columnLine(a, b, k, c),
                            KdTreeGrid::columnLine(a, b, k, c + 1));
    };
    // The fewest equal columns of [a, b] that settle as whole cells over each span across, 0
    // where none up to kMostColumns do. The columns of a surface of revolution differ only as
    // its arcs' parameter runs unevenly: the search tries the first, middle and last, and the
    // count found is then checked on every column (one more at a time where one fails).
    auto fewestColumns = [&](std::int64_t a, std::int64_t b) {
        auto likelyMeets = [&](int k) {
            for (const int c : {0, k / 2, k - 1})
                if (!columnSettles(a, b, k, c)) return false;
            return true;
        };
        // the bound falls about with the square of a column's width
        const double ratio = test.wholeRatio(a, b);
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
        // Beyond kColumnsAlwaysTaken, only where the three columns above already ask for more,
        // and well under the power of two that the halvings reach (kRowColumnsShare of it):
        // checking every one of hundreds of columns costs more than the few it saves, and a
        // count that grows past it only in the check has a column elsewhere that needs far more,
        // which the halvings follow (the ruled face between a circle and an ellipse of
        // tests/bench/generated_shapes.py at relative 1e-3 grew from about 250 to 509 columns,
        // and its tessellation took 60 ms instead of 45).
        const double most =
            count > kColumnsAlwaysTaken
                ? kRowColumnsShare * double(std::bit_ceil(static_cast<unsigned>(count)))
                : double(kColumnsAlwaysTaken);
        while (count <= most) {
            bool all = true;
            for (int c = 0; c < count && all; ++c) all = columnSettles(a, b, count, c);
            if (all) return count;
            count += std::max(1, count / 64);
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
    const std::size_t spansAcross = grids[1 - axis].intervals().size() - 1;
    auto columnsCutAcross = [&](std::int64_t a, std::int64_t b) {
        // (k, c): the rows of column c of k, -1 where one fails
        std::map<std::pair<int, int>, int> rowsTested;
        auto rowsOf = [&](int k, int c) {
            auto [known, fresh] = rowsTested.try_emplace({k, c}, 0);
            if (fresh)
                known->second = test.rowCount(KdTreeGrid::columnLine(a, b, k, c),
                                              KdTreeGrid::columnLine(a, b, k, c + 1));
            return known->second;
        };
        auto meets = [&](int k, std::initializer_list<int> columns) {
            for (const int c : columns)
                if (rowsOf(k, c) < 0) return false;
            return true;
        };
        auto spreadMeet = [&](int k) { return meets(k, {k / 2, 0, k / 4, 3 * k / 4, k - 1}); };
        // where halvings need at most 4 columns, equal ones save at most one
        if (meets(4, {2})) return 0;
        const int mostPower =
            spansAcross == 1 ? kMostColumnsCutAcrossOneSpan : kMostColumnsCutAcross;
        auto shareOf = [](int power) {
            return power > kMostColumnsCutAcross ? kOneSpanRowColumnsShare : kRowColumnsShare;
        };
        int power = 8;
        while (power <= mostPower && !meets(power, {power / 2})) power *= 2;
        for (; power <= mostPower; power *= 2) {
            const int most = static_cast<int>(shareOf(power) * power);
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
    // Graded columns only where the region is the whole box: where trimming curves cross the
    // columns, the kd-tree cuts their cells through the curves' points, wherever the lines
    // fall, and graded columns there took more triangles (the crossed cylinders of
    // tests/bench/generated_shapes.py at relative 1e-4: 1,966 instead of 1,788).
    graded = graded && regionIsTheBox(face, grids);
    // Columns cut across into rows only over a few spans across: each test of a column cuts it
    // into rows over every span across, and over many the halvings follow the spans' differing
    // needs better than equal columns. OpenCASCADE's MAT.brep (77 x 80 spans) at relative 1e-4
    // took 82,056 triangles in 2.0 s with them, 80,187 in 0.84 s without; its terrain.brep
    // 177,484 in 2.4 s, 176,247 in 1.1 s. Nothing else changed on the corpus, the 32 generated
    // shapes, OpenCASCADE's other samples and 21 FreeCAD shapes but Motor-c.brep at 1e-4
    // (30,492 -> 30,500); with 8 spans the pipe along a spline and Bottom.brep changed too
    // (-2.6% and +0.2%).
    cutAcross = cutAcross && spansAcross <= kMostSpansCutAcross;
    for (std::size_t i = 0; i + 1 < intervals.size(); ++i) {
        const std::int64_t a = intervals[i], b = intervals[i + 1];
        if (columnSettles(a, b, 1, 0)) {
            lines[i] = {a, b};  // one column
            continue;
        }
        const int count = fewestColumns(a, b);
        // Searched where the estimate says they may save a column, and at least
        // kGradedSaving of the equal ones: the search walks every column (about seven tests
        // each) before it knows, and a count it misses by a hair it rarely reaches. The
        // generated twisted loft's four faces, estimated at 113.2 of 115 columns at relative
        // 1e-3 and 1,122.5 of 1,140 at 1e-4, each walked past 114 (1,139) and took the equal
        // ones: 796 of the 1,000 column tests a face made at 1e-3 (its tessellation took 13 ms
        // instead of 6). Over the corpus, the generated shapes, OpenCASCADE's and the IDF
        // samples at both tolerances, 56 searches saved columns and 123 did not; of those left
        // out now only three on bearing.iges at 1e-4 saved one (29 -> 28), and its mesh is the
        // same (the lines its column groups take).
        const double enough = std::min(count - 1.0, (1 - kGradedSaving) * count);
        const double estimate = count >= 3 && graded ? test.gradedCountEstimate(a, b, count, enough)
                                                     : std::numeric_limits<double>::infinity();
        if (estimate <= enough) {
            std::vector<std::int64_t> own = test.gradedLines(a, b, count - 1);
            if (!own.empty()) {
                lines[i] = std::move(own);
                continue;
            }
        }
        if (count > 0)
            lines[i] = KdTreeGrid::equalColumnLines(a, b, count);
        else if (cutAcross)
            lines[i] = KdTreeGrid::equalColumnLines(a, b, columnsCutAcross(a, b));
    }
    return lines;
}

}  // namespace nurbslod
