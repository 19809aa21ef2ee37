#include "tessellate/FoldedPairs.hpp"

#include <algorithm>
#include <map>

namespace nurbslod {

namespace {

// No area: twice the area at most 1e-9 of the longest side squared (a sliver whose middle
// point is a billionth of its length off the line between the others).
bool withoutArea(const Point3& a, const Point3& b, const Point3& c) {
    const double longest2 =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return (b - a).cross(c - a).norm() <= 1e-9 * longest2;
}

}  // namespace

std::vector<char> trianglesOutsideFolds(const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                        const std::vector<Point3>& positions) {
    std::vector<char> kept(triangles.size(), 1);
    // the triangles without area by their sorted points, with the way round they go
    std::map<std::array<std::uint32_t, 3>, std::vector<std::pair<std::size_t, bool>>> byPoints;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const auto& [a, b, c] = triangles[t];
        if (a == b || b == c || a == c) continue;
        if (!withoutArea(positions[a], positions[b], positions[c])) continue;
        std::array<std::uint32_t, 3> sorted = triangles[t];
        std::sort(sorted.begin(), sorted.end());
        // the way round: that of (low, middle, high) or the other one; rotating a triangle
        // keeps it, so it is an even permutation of the sorted points or not
        const std::array<std::array<std::uint32_t, 3>, 3> even = {
            sorted, {sorted[1], sorted[2], sorted[0]}, {sorted[2], sorted[0], sorted[1]}};
        const bool forward = std::find(even.begin(), even.end(), triangles[t]) != even.end();
        byPoints[sorted].push_back({t, forward});
    }
    for (const auto& [points, list] : byPoints) {
        std::vector<std::size_t> forward, backward;
        for (const auto& [t, isForward] : list) (isForward ? forward : backward).push_back(t);
        const std::size_t pairs = std::min(forward.size(), backward.size());
        for (std::size_t k = 0; k < pairs; ++k) kept[forward[k]] = kept[backward[k]] = 0;
    }
    return kept;
}

}  // namespace nurbslod
