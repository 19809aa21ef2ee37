#include "tessellate/KdTreeGrid.hpp"

#include <algorithm>
#include <cmath>

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
    if (hasEvenColumns() && counts_[index] >= 2)
        return evenLineWithin(a, b, counts_[index], lo, hi);
    return halvingWithin(a, b, lo, hi);
}

KdTreeGrid::Interval KdTreeGrid::intervalAround(std::int64_t x) const {
    const auto after = std::lower_bound(breaks_.begin(), breaks_.end(), x);
    return {after == breaks_.begin() ? 0 : *(after - 1),
            after == breaks_.end() ? kKdTreeFrameScale : *after,
            static_cast<std::size_t>(after - breaks_.begin())};
}

std::optional<double> KdTreeGrid::evenLineWithin(std::int64_t a, std::int64_t b, int k,
                                                 std::int64_t lo, std::int64_t hi) const {
    // as FaceTessellator splits: the middle column line while a cell holds two columns or more,
    // then the column's halvings
    int first = 0, last = k;
    while (last - first >= 2) {
        const int middle = (first + last) / 2;
        const std::int64_t x = columnLine(a, b, k, middle);
        if (x >= lo && x <= hi) return parameterOf(x);
        if (x < lo)
            first = middle;
        else
            last = middle;
    }
    return halvingWithin(columnLine(a, b, k, first), columnLine(a, b, k, last), lo, hi);
}

void KdTreeGrid::setEvenColumns(std::vector<int> counts) {
    const bool any = std::any_of(counts.begin(), counts.end(), [](int k) { return k >= 2; });
    if (!any || counts.size() != breaks_.size() + 1) counts.clear();
    counts_ = std::move(counts);
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
    const int k = counts_[index];
    if (k < 2 || x0 < a || x1 > b) return std::nullopt;
    auto indexOf = [&](std::int64_t x) -> std::optional<int> {
        const auto c = static_cast<int>(std::llround(double(x - a) * k / double(b - a)));
        if (c < 0 || c > k || columnLine(a, b, k, c) != x) return std::nullopt;
        return c;
    };
    const auto c0 = indexOf(x0), c1 = indexOf(x1);
    if (!c0 || !c1 || *c1 - *c0 < 2) return std::nullopt;
    return columnLine(a, b, k, (*c0 + *c1) / 2);
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
