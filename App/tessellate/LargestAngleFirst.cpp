#include "tessellate/LargestAngleFirst.hpp"

#include <algorithm>
#include <cstddef>

namespace nurbslod {

void startAtLargestAngle(Mesh& mesh) {
    const bool withNormals = mesh.triangleNormals.size() == mesh.triangles.size();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        auto& corners = mesh.triangles[t];
        // the side opposite corner k runs between the other two
        double opposite[3];
        for (int k = 0; k < 3; ++k)
            opposite[k] =
                (mesh.positions[corners[(k + 1) % 3]] - mesh.positions[corners[(k + 2) % 3]])
                    .squaredNorm();
        int first = 0;
        if (opposite[1] > opposite[first]) first = 1;
        if (opposite[2] > opposite[first]) first = 2;
        if (first == 0) continue;
        std::rotate(corners.begin(), corners.begin() + first, corners.end());
        if (withNormals) {
            auto& normals = mesh.triangleNormals[t];
            std::rotate(normals.begin(), normals.begin() + first, normals.end());
        }
    }
}

}  // namespace nurbslod
