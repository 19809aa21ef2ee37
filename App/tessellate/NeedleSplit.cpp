#include "tessellate/NeedleSplit.hpp"

#include <cstddef>
#include <unordered_map>

namespace nurbslod {

std::vector<TriangleOrigin> splitNeedles(
    std::vector<std::array<std::uint32_t, 3>>& triangles,
    const std::function<const Point3&(std::uint32_t)>& position) {
    std::vector<TriangleOrigin> origins(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        origins[i].triangle = static_cast<std::uint32_t>(i);
        for (int k = 0; k < 3; ++k) origins[i].corners[k] = {static_cast<std::uint32_t>(i), k};
    }
    auto isNeedle = [&](const std::array<std::uint32_t, 3>& t, int& longest) {
        double longestLength = -1;
        for (int k = 0; k < 3; ++k) {
            const double l = (position(t[(k + 1) % 3]) - position(t[k])).squaredNorm();
            if (l > longestLength) longestLength = l, longest = k;
        }
        const Vector3 n = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
        return n.norm() <= 1e-9 * longestLength;
    };
    auto edgeKey = [](std::uint32_t from, std::uint32_t to) {
        return (std::uint64_t{from} << 32) | to;
    };
    std::unordered_map<std::uint64_t, std::size_t> triangleOfEdge;
    triangleOfEdge.reserve(triangles.size() * 3);
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            triangleOfEdge[edgeKey(triangles[i][k], triangles[i][(k + 1) % 3])] = i;
    std::vector<char> removed(triangles.size(), 0);
    // each split removes one needle; a split can make a new needle of a neighbour, so the
    // passes are bounded by the number of triangles that were there at the start
    const std::size_t maxSplits = triangles.size();
    std::size_t splits = 0;
    for (std::size_t i = 0; i < triangles.size() && splits < maxSplits; ++i) {
        int longest = 0;
        if (removed[i] || !isNeedle(triangles[i], longest)) continue;
        const auto needle = triangles[i];
        const std::uint32_t a = needle[longest], b = needle[(longest + 1) % 3];
        const std::uint32_t c = needle[(longest + 2) % 3];
        // the neighbour runs the long edge the other way: b -> a
        auto it = triangleOfEdge.find(edgeKey(b, a));
        if (it == triangleOfEdge.end() || removed[it->second]) continue;
        const std::size_t j = it->second;
        const auto other = triangles[j];
        int at = 0;
        while (!(other[at] == b && other[(at + 1) % 3] == a)) ++at;
        const std::uint32_t d = other[(at + 2) % 3];
        if (d == c) continue;
        // (b, a, d) becomes (b, c, d) and (c, a, d); the needle goes
        const CornerOrigin fromB = origins[j].corners[at], fromA = origins[j].corners[(at + 1) % 3];
        const CornerOrigin fromD = origins[j].corners[(at + 2) % 3];
        const CornerOrigin fromC = origins[i].corners[(longest + 2) % 3];
        ++splits;
        removed[i] = 1;
        triangles[j] = {b, c, d};
        origins[j].corners = {fromB, fromC, fromD};
        triangles.push_back({c, a, d});
        origins.push_back({{fromC, fromA, fromD}, origins[j].triangle});
        removed.push_back(0);
        for (const std::size_t index : {j, triangles.size() - 1})
            for (int k = 0; k < 3; ++k)
                triangleOfEdge[edgeKey(triangles[index][k], triangles[index][(k + 1) % 3])] = index;
    }
    std::size_t out = 0;
    for (std::size_t i = 0; i < triangles.size(); ++i)
        if (!removed[i]) {
            triangles[out] = triangles[i];
            origins[out] = origins[i];
            ++out;
        }
    triangles.resize(out);
    origins.resize(out);
    return origins;
}

}  // namespace nurbslod
