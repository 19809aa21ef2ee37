#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "tessellate/Mesh.hpp"

namespace nurbslod::test {

// The open edges (used by one triangle) of a mesh welded as meshjudge welds it, on a grid of
// max(tolerance * 1e-3, 1e-9) (numpy rounds half to even, as nearbyint does), whose middle
// satisfies `where`: a test counts the ones that lie where the model has no free edge (verify
// counts them all).
template <class Where>
int weldedOpenEdgesWhere(const std::vector<Point3>& positions,
                         const std::vector<std::array<std::uint32_t, 3>>& triangles,
                         double tolerance, Where where) {
    const double quantum = std::max(tolerance * 1e-3, 1e-9);
    std::map<std::array<std::int64_t, 3>, std::uint32_t> cellIds;
    std::vector<std::uint32_t> welded(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        std::array<std::int64_t, 3> key;
        for (int axis = 0; axis < 3; ++axis)
            key[axis] = static_cast<std::int64_t>(std::nearbyint(positions[i][axis] / quantum));
        welded[i] = cellIds.emplace(key, static_cast<std::uint32_t>(cellIds.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, Point3>> uses;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = welded[t[k]], b = welded[t[(k + 1) % 3]];
            if (a == b) continue;
            auto& use = uses[{std::min(a, b), std::max(a, b)}];
            ++use.first;
            use.second = 0.5 * (positions[t[k]] + positions[t[(k + 1) % 3]]);
        }
    int count = 0;
    for (const auto& [edge, use] : uses) count += use.first == 1 && where(use.second);
    return count;
}

template <class Where>
int weldedOpenEdgesWhere(const Mesh& mesh, double tolerance, Where where) {
    return weldedOpenEdgesWhere(mesh.positions, mesh.triangles, tolerance, where);
}

}  // namespace nurbslod::test
