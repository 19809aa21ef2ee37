#include "lod/FacetNormalError.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <vector>

namespace nurbslod::gui {

FacetNormalError measureFacetNormalError(const Mesh& mesh, const BSplineSurface& surface,
                                         double tolerance) {
    // Which corners lie on the surface: by normal index, which carries the (u, v).
    const bool hasParameters = mesh.parameters.size() == mesh.normals.size();
    std::vector<signed char> onSurface(mesh.normals.size(), -1);  // -1: not checked yet
    auto cornerOnSurface = [&](std::size_t t, int corner) {
        if (!hasParameters) return false;
        const std::uint32_t normal = mesh.triangleNormals[t][corner];
        signed char& known = onSurface[normal];
        if (known < 0) {
            const Point2& uv = mesh.parameters[normal];
            const Point3& position = mesh.positions[mesh.triangles[t][corner]];
            known = (surface.point(uv.x(), uv.y()) - position).norm() <= 1e-3 * tolerance;
        }
        return known == 1;
    };
    // Corners on the mesh's border (an edge of one triangle only): the trimming loops.
    std::unordered_map<std::uint64_t, int> edgeUses;
    for (const auto& corners : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = corners[k], b = corners[(k + 1) % 3];
            ++edgeUses[(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b)];
        }
    std::vector<char> onBorder(mesh.positions.size(), 0);
    for (const auto& [key, uses] : edgeUses)
        if (uses == 1) onBorder[key >> 32] = onBorder[key & 0xffffffffu] = 1;
    FacetNormalError error;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& corners = mesh.triangles[t];
        const Point3& a = mesh.positions[corners[0]];
        const Vector3 ab = mesh.positions[corners[1]] - a;
        const Vector3 ac = mesh.positions[corners[2]] - a;
        const Vector3 bc = mesh.positions[corners[2]] - mesh.positions[corners[1]];
        const Vector3 facet = ab.cross(ac);
        const double longest =
            std::sqrt(std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()}));
        // twice the area over the longest edge is the smallest altitude; none is a triangle
        // without area, whose facet normal is undefined
        const double altitude = longest > 0 ? facet.norm() / longest : 0;
        if (!(altitude > 0) || altitude < tolerance) continue;
        double largest = 0;
        for (int corner = 0; corner < 3; ++corner) {
            const Vector3& exact = mesh.normals[mesh.triangleNormals[t][corner]];
            // atan2 of |cross| and dot: accurate for small angles, where acos is not
            largest = std::max(largest, std::atan2(facet.cross(exact).norm(), facet.dot(exact)));
        }
        const double degrees = largest * 180.0 / std::numbers::pi;
        error.maxDeg = std::max(error.maxDeg, degrees);
        bool interior = true;
        for (int corner = 0; corner < 3; ++corner)
            interior = interior && !onBorder[corners[corner]] && cornerOnSurface(t, corner);
        if (interior) error.interiorMaxDeg = std::max(error.interiorMaxDeg, degrees);
    }
    return error;
}

}  // namespace nurbslod::gui
