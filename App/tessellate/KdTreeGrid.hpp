#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace nurbslod {

// Integer steps across a face's boundary box in FaceTessellator's frame: 2^30 keeps Clipper in
// its fast 64-bit range, and 1e-9 of a face is far below any tolerance a user asks for.
inline constexpr std::int64_t kKdTreeFrameScale = std::int64_t(1) << 30;

// The Bezier span borders that a face's kd-tree cuts on first, in frame steps, sorted: the
// breakpoints that round strictly inside the frame, whose step 0 is at `low` and which has
// `scale` steps per unit of the parameter. The surface's own ends (its first and last
// breakpoints) lie inside the frame where a trimming curve runs past the surface's domain;
// they count only where it runs past by more than kFramePastDomain steps. A pcurve that a
// conversion left a hair past its surface's end (1e-8 of the domain on an offset surface
// made into a NURBS) would otherwise cut a column that thin along the face's border, whose
// cells fan between the border's points and their own; the weld then joins each point to
// its neighbour across the column and leaves a pair of triangles on the same three points,
// one each way round. Without that border, the last span's cell reaches past the domain by
// at most 2^-20 of the frame, and its surface piece (clamped to the span) is stretched over
// it by no more.
inline constexpr std::int64_t kFramePastDomain = kKdTreeFrameScale >> 20;
std::vector<std::int64_t> spanBordersInFrame(double low, double scale,
                                             const std::vector<double>& breakpoints);

// The lines along one parameter axis on which a face's kd-tree can cut, in FaceTessellator's
// integer frame over [low, high] (the boundary's box): the Bezier span borders, which it cuts
// first, and the halvings of each span, which it cuts where a cell's bound says "split in the
// middle" (every cell of a cylinder or a cone across its circles).
//
// An edge whose points lie on these lines is cut by no kd-tree line between its own points
// (FaceTessellator splits through a boundary point near the middle, and here is one exactly
// there); an edge halved in its own parameter gets a point from each cut as well: on a cylinder
// whose two circles are parameterised unlike each other, both circles carry both sets.
class KdTreeGrid {
public:
    KdTreeGrid(double low, double high, const std::vector<double>& breakpoints);

    // The coarsest line strictly within the middle half of the interval between c0 and c1
    // (either order), as a parameter value: a span border there if any (the one nearest the
    // middle), otherwise the first halving of the span around it that lands there. None where
    // the interval is below the frame's resolution or outside the frame.
    std::optional<double> lineWithin(double c0, double c1) const;

    // Even columns: the kd-tree may cut an interval between span borders into columns rather
    // than halve it (a half cylinder whose bound allows 47 columns gets 47, not 64). It then
    // splits a cell of several columns at the column line in its middle, by count, and a
    // single column in halves. lines[i] holds the lines of interval i (intervals()) from its
    // first border to its last, in frame steps and increasing, or nothing for halvings: equal
    // columns (setEvenColumns, counts[i] of them) or graded ones, as wide as each place allows
    // (EvenColumns.hpp).
    void setColumnLines(std::vector<std::vector<std::int64_t>> lines);
    void setEvenColumns(const std::vector<int>& counts);
    bool hasEvenColumns() const { return !lines_.empty(); }
    // interval i's column lines (empty: halvings)
    const std::vector<std::int64_t>& columnLines(std::size_t i) const;
    // The borders of the intervals, in frame steps: 0, the span borders, kKdTreeFrameScale.
    std::vector<std::int64_t> intervals() const;
    // Line c of an interval [a, b] of k equal columns, in frame steps.
    static std::int64_t columnLine(std::int64_t a, std::int64_t b, int k, int c) {
        return a + std::llround(double(b - a) * c / k);
    }
    // The k + 1 lines of k equal columns over [a, b], from a to b; none for k < 1.
    static std::vector<std::int64_t> equalColumnLines(std::int64_t a, std::int64_t b, int k);
    // Where the kd-tree cuts a cell [x0, x1] (frame steps) that lies in one interval of even
    // columns with both sides on its column lines and at least two columns wide: the column
    // line in its middle. None otherwise (the cell is halved).
    std::optional<std::int64_t> evenSplit(std::int64_t x0, std::int64_t x1) const;

    // The same frame and span borders as `other`: the same lines, and the same columns for the
    // same counts.
    bool sameFrame(const KdTreeGrid& other) const {
        return hasFrame(other.low_, other.scale_, other.breaks_);
    }
    // The same span borders, in steps, and ends within a step of `other`'s: two faces' frames of
    // one edge, made from pcurve ends that differ in the last bits.
    bool nearlySameFrame(const KdTreeGrid& other) const {
        return breaks_ == other.breaks_ &&
               framesWithinAStep(other.low_, other.parameterOf(kKdTreeFrameScale));
    }
    // Step 0 at `low`, `scale` steps per unit of the parameter and these span borders
    // (spanBordersInFrame): the same lines, and the same columns for the same counts.
    bool hasFrame(double low, double scale, const std::vector<std::int64_t>& borders) const {
        return low_ == low && scale_ == scale && breaks_ == borders;
    }
    // Whether [low, high] (a face's boundary box along the axis) is this frame's but for less
    // than a frame step at each end: the boundary's points are evaluated otherwise than the
    // pcurves' ends the frame was made from, or moved onto their edges' shared points, and may
    // differ from them in the last bits (FaceTessellator then takes this frame).
    bool framesWithinAStep(double low, double high) const {
        const double step = 1 / scale_;
        return std::abs(low - low_) <= step &&
               std::abs(high - parameterOf(kKdTreeFrameScale)) <= step;
    }
    double low() const { return low_; }
    double scale() const { return scale_; }
    double parameterAt(std::int64_t step) const { return parameterOf(step); }

    bool operator==(const KdTreeGrid&) const = default;

private:
    // the first halving of [a, b] (frame steps) that lands in [lo, hi], halving towards it
    std::optional<double> halvingWithin(std::int64_t a, std::int64_t b, std::int64_t lo,
                                        std::int64_t hi) const;
    double parameterOf(std::int64_t x) const { return low_ + static_cast<double>(x) / scale_; }

    std::int64_t stepOf(double value) const { return std::llround((value - low_) * scale_); }

    double low_ = 0, scale_ = 1;
    // The interval between span borders (or the frame's ends) that ends at or after x: its
    // borders a, b and its index in intervals().
    struct Interval {
        std::int64_t a, b;
        std::size_t index;
    };
    Interval intervalAround(std::int64_t x) const;
    // the coarsest of the column `lines` that lands in [lo, hi] (frame steps)
    std::optional<double> evenLineWithin(const std::vector<std::int64_t>& lines, std::int64_t lo,
                                         std::int64_t hi) const;

    std::vector<std::int64_t> breaks_;  // span borders strictly inside, in frame steps, sorted
    // column lines per interval (each empty for halvings), empty: none anywhere
    std::vector<std::vector<std::int64_t>> lines_;
};

}  // namespace nurbslod
