#include "tessellate/KdTreeGrid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace nurbslod {

std::vector<std::int64_t> spanBordersInFrame(double low, double scale,
                                             const std::vector<double>& breakpoints) {
    std::vector<std::int64_t> borders;
    for (std::size_t k = 0; k < breakpoints.size(); ++k) {
        const std::int64_t x = std::llround((breakpoints[k] - low) * scale);
        if (!(x > 0 && x < kKdTreeFrameScale)) continue;
        if (k == 0 && x <= kFramePastDomain) continue;
        if (k + 1 == breakpoints.size() && x >= kKdTreeFrameScale - kFramePastDomain) continue;
        borders.push_back(x);
    }
    std::sort(borders.begin(), borders.end());
    return borders;
}

KdTreeGrid::KdTreeGrid(double low, double high, const std::vector<double>& breakpoints)
    : low_(low),
      scale_(static_cast<double>(kKdTreeFrameScale) / (high - low)),
      breaks_(spanBordersInFrame(low_, scale_, breakpoints)) {}

std::optional<double> KdTreeGrid::lineWithin(double c0, double c1) const {
    if (c0 > c1) std::swap(c0, c1);
    const double quarter = 0.25 * (c1 - c0);
    const double first = std::ceil((c0 + quarter - low_) * scale_);
    const double last = std::floor((c1 - quarter - low_) * scale_);
    if (!(first <= last) || first < 1 || last > double(kKdTreeFrameScale - 1)) return std::nullopt;
    const auto lo = static_cast<std::int64_t>(first), hi = static_cast<std::int64_t>(last);
    const std::int64_t middle = lo + (hi - lo) / 2;
    std::optional<std::int64_t> border;
    for (std::int64_t b : breaks_)
        if (b >= lo && b <= hi && (!border || std::abs(b - middle) < std::abs(*border - middle)))
            border = b;
    if (border) return parameterOf(*border);

    // the span around the window, halved as the kd-tree halves a cell (FaceTessellator: the
    // split at 0.5 rounded to a step, kept off the cell's sides)
    const auto [a, b, index] = intervalAround(hi);
    if (hasEvenColumns() && lines_[index].size() >= 3) return evenLineWithin(lines_[index], lo, hi);
    return halvingWithin(a, b, lo, hi);
}

KdTreeGrid::Interval KdTreeGrid::intervalAround(std::int64_t x) const {
    const auto after = std::lower_bound(breaks_.begin(), breaks_.end(), x);
    return {after == breaks_.begin() ? 0 : *(after - 1),
            after == breaks_.end() ? kKdTreeFrameScale : *after,
            static_cast<std::size_t>(after - breaks_.begin())};
}

std::optional<double> KdTreeGrid::evenLineWithin(const std::vector<std::int64_t>& lines,
                                                 std::int64_t lo, std::int64_t hi) const {
    // as FaceTessellator splits: the middle column line while a cell holds two columns or more,
    // then the column's halvings
    std::size_t first = 0, last = lines.size() - 1;
    while (last - first >= 2) {
        const std::size_t middle = (first + last) / 2;
        const std::int64_t x = lines[middle];
        if (x >= lo && x <= hi) return parameterOf(x);
        if (x < lo)
            first = middle;
        else
            last = middle;
    }
    return halvingWithin(lines[first], lines[last], lo, hi);
}

void KdTreeGrid::setColumnLines(std::vector<std::vector<std::int64_t>> lines) {
    const std::vector<std::int64_t> borders = intervals();
    bool any = lines.size() + 1 == borders.size();
    for (std::size_t i = 0; any && i < lines.size(); ++i) {
        auto& own = lines[i];
        if (own.size() < 3) {  // one column: as halvings
            own.clear();
            continue;
        }
        // from the interval's first border to its last, strictly increasing
        any = own.front() == borders[i] && own.back() == borders[i + 1] &&
              std::adjacent_find(own.begin(), own.end(), std::greater_equal<>()) == own.end();
    }
    any = any && std::any_of(lines.begin(), lines.end(), [](const auto& l) { return !l.empty(); });
    if (!any) lines.clear();
    lines_ = std::move(lines);
}

void KdTreeGrid::setEvenColumns(const std::vector<int>& counts) {
    const std::vector<std::int64_t> borders = intervals();
    if (counts.size() + 1 != borders.size()) {
        lines_.clear();
        return;
    }
    std::vector<std::vector<std::int64_t>> lines(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i)
        lines[i] = equalColumnLines(borders[i], borders[i + 1], counts[i]);
    setColumnLines(std::move(lines));
}

std::vector<std::int64_t> KdTreeGrid::equalColumnLines(std::int64_t a, std::int64_t b, int k) {
    std::vector<std::int64_t> lines;
    for (int c = 0; c <= k && k >= 1; ++c) lines.push_back(columnLine(a, b, k, c));
    return lines;
}

const std::vector<std::int64_t>& KdTreeGrid::columnLines(std::size_t i) const {
    static const std::vector<std::int64_t> none;
    return i < lines_.size() ? lines_[i] : none;
}

std::vector<std::int64_t> KdTreeGrid::intervals() const {
    std::vector<std::int64_t> borders{0};
    borders.insert(borders.end(), breaks_.begin(), breaks_.end());
    borders.push_back(kKdTreeFrameScale);
    return borders;
}

std::optional<std::int64_t> KdTreeGrid::evenSplit(std::int64_t x0, std::int64_t x1) const {
    if (!hasEvenColumns() || x1 - x0 < 2) return std::nullopt;
    const auto [a, b, index] = intervalAround(x1);
    const auto& lines = lines_[index];
    if (lines.size() < 3 || x0 < a || x1 > b) return std::nullopt;
    const auto c0 = std::lower_bound(lines.begin(), lines.end(), x0);
    const auto c1 = std::lower_bound(c0, lines.end(), x1);
    if (c0 == lines.end() || c1 == lines.end() || *c0 != x0 || *c1 != x1 || c1 - c0 < 2)
        return std::nullopt;
    return *(c0 + (c1 - c0) / 2);
}

std::optional<double> KdTreeGrid::halvingWithin(std::int64_t a, std::int64_t b, std::int64_t lo,
                                                std::int64_t hi) const {
    while (b - a >= 2) {
        const std::int64_t m =
            std::clamp<std::int64_t>(a + std::llround(0.5 * double(b - a)), a + 1, b - 1);
        if (m >= lo && m <= hi) return parameterOf(m);
        if (m < lo)
            a = m;
        else
            b = m;
    }
    return std::nullopt;
}

}  // namespace nurbslod
