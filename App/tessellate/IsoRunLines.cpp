#include "tessellate/IsoRunLines.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>

namespace nurbslod {

using ClipperLib::cInt;

IsoRunLines::IsoRunLines(const ClipperLib::Paths& region) {
    for (const ClipperLib::Path& path : region)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const ClipperLib::IntPoint& a = path[i];
            const ClipperLib::IntPoint& b = path[(i + 1) % path.size()];
            if (a.Y == b.Y && a.X != b.X) lines_[0].insert(lines_[0].end(), {a.X, b.X});
            if (a.X == b.X && a.Y != b.Y) lines_[1].insert(lines_[1].end(), {a.Y, b.Y});
        }
    for (auto& lines : lines_) {
        std::sort(lines.begin(), lines.end());
        lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    }
}

cInt IsoRunLines::nearest(int axis, cInt lo, cInt hi, cInt at) const {
    const std::vector<cInt>& lines = lines_[axis];
    cInt best = at, bestDistance = splitThroughPointWindow(lo, hi);
    auto consider = [&](std::vector<cInt>::const_iterator line) {
        if (line == lines.end() || *line <= lo || *line >= hi) return;
        if (const cInt distance = std::abs(*line - at); distance < bestDistance)
            best = *line, bestDistance = distance;
    };
    const auto after = std::lower_bound(lines.begin(), lines.end(), at);
    consider(after);
    if (after != lines.begin()) consider(std::prev(after));
    return best;
}

}  // namespace nurbslod
