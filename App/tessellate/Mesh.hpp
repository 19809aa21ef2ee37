#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// A triangle mesh of a model. Positions are shared where faces meet (a closed solid gives a
// closed mesh); normals are per face, so a crease keeps one normal on each side.
struct Mesh {
    std::vector<Point3> positions;
    std::vector<Vector3> normals;
    std::vector<Point2> parameters;  // (u, v) on its face of each normal's vertex, like normals
    std::vector<std::array<std::uint32_t, 3>> triangles;        // indices into positions
    std::vector<std::array<std::uint32_t, 3>> triangleNormals;  // indices into normals
    std::vector<std::int32_t> triangleFaces;                    // 1-based B-rep face index
};

}  // namespace nurbslod
