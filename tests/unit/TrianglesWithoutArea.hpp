#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "tessellate/Mesh.hpp"

namespace nurbslod::test {

// The mesh's triangles without area as the verifier counts them: twice the area at most 1e-12
// of the largest triangle's.
inline std::size_t trianglesWithoutArea(const Mesh& mesh) {
    double largest = 0;
    std::vector<double> areas;
    for (const auto& t : mesh.triangles) {
        const Point3& p = mesh.positions[t[0]];
        areas.push_back((mesh.positions[t[1]] - p).cross(mesh.positions[t[2]] - p).norm());
        largest = std::max(largest, areas.back());
    }
    return static_cast<std::size_t>(std::count_if(
        areas.begin(), areas.end(), [&](double area) { return area <= 1e-12 * largest; }));
}

}  // namespace nurbslod::test
