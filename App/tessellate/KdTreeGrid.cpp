#include "tessellate/KdTreeGrid.hpp"

#include <algorithm>
#include <cmath>

namespace nurbslod {

KdTreeGrid::KdTreeGrid(double low, double high, const std::vector<double>& breakpoints)
    : low_(low), scale_(static_cast<double>(kKdTreeFrameScale) / (high - low)) {
    // as FaceTessellator::setFrame rounds them
    for (double b : breakpoints) {
        const std::int64_t x = stepOf(b);
        if (x > 0 && x < kKdTreeFrameScale) breaks_.push_back(x);
    }
    std::sort(breaks_.begin(), breaks_.end());
}

std::optional<double> KdTreeGrid::lineWithin(double c0, double c1) const {
    if (c0 > c1) std::swap(c0, c1);
    const double quarter = 0.25 * (c1 - c0);
    const double first = std::ceil((c0 + quarter - low_) * scale_);
    const double last = std::floor((c1 - quarter - low_) * scale_);
    if (!(first <= last) || first < 1 || last > double(kKdTreeFrameScale - 1)) return std::nullopt;
    const auto lo = static_cast<std::int64_t>(first), hi = static_cast<std::int64_t>(last);

    if (!bordersFirst_) return halvingWithin(0, kKdTreeFrameScale, lo, hi);
    const std::int64_t middle = lo + (hi - lo) / 2;
    std::optional<std::int64_t> border;
    for (std::int64_t b : breaks_)
        if (b >= lo && b <= hi && (!border || std::abs(b - middle) < std::abs(*border - middle)))
            border = b;
    if (border) return parameterOf(*border);

    // the span around the window, halved as the kd-tree halves a cell (FaceTessellator: the
    // split at 0.5 rounded to a step, kept off the cell's sides)
    const auto after = std::lower_bound(breaks_.begin(), breaks_.end(), hi);
    return halvingWithin(after == breaks_.begin() ? 0 : *(after - 1),
                         after == breaks_.end() ? kKdTreeFrameScale : *after, lo, hi);
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

KdTreeGrid KdTreeGrid::halvingsOnly() const {
    KdTreeGrid grid = *this;
    grid.bordersFirst_ = false;
    return grid;
}

std::size_t KdTreeGrid::bordersBetween(const std::vector<double>& values) const {
    if (values.empty()) return 0;
    std::vector<std::int64_t> steps;
    for (double value : values) steps.push_back(stepOf(value));
    std::sort(steps.begin(), steps.end());
    std::size_t count = 0;
    for (std::int64_t b : breaks_)
        count += b > steps.front() && b < steps.back() &&
                 !std::binary_search(steps.begin(), steps.end(), b);
    return count;
}

}  // namespace nurbslod
