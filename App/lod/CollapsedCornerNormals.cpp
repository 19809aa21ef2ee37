#include "lod/CollapsedCornerNormals.hpp"

#include <algorithm>
#include <vector>

#include "lod/InterpolatedNormalError.hpp"

namespace nurbslod::gui {

namespace {
// Below this ratio of the first derivatives the surface counts as (nearly) collapsed.
constexpr double nearlyCollapsed = 1e-2;
// Where inside the triangle the candidate normals are taken: fractions of the way from the
// corner to the middle of the opposite edge.
constexpr double candidateSteps[] = {1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2};
}  // namespace

int takeCollapsedCornerNormalsInside(Mesh& mesh, const TrimmedSurface& face) {
    if (mesh.parameters.size() != mesh.normals.size()) return 0;
    const BSplineSurface& surface = face.surface;
    const double outwards = face.reversed ? -1.0 : 1.0;
    const std::size_t original = mesh.normals.size();
    std::vector<signed char> nearPole(original, -1);  // -1: not yet known
    auto isNearPole = [&](std::uint32_t normal) {
        signed char& known = nearPole[normal];
        if (known < 0) {
            const Point2& uv = mesh.parameters[normal];
            const auto d = surface.derivatives(uv.x(), uv.y());
            known = std::min(d.du.norm(), d.dv.norm()) <
                    nearlyCollapsed * std::max(d.du.norm(), d.dv.norm());
        }
        return known == 1;
    };
    const InterpolatedNormalSampler sampler(mesh, face);
    int changed = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t normal = mesh.triangleNormals[t][k];
            if (normal >= original || !isNearPole(normal)) continue;
            const Point2 corner = mesh.parameters[normal];
            const Vector3 vertexNormal = mesh.normals[normal];
            const Point2 opposite = 0.5 * (mesh.parameters[mesh.triangleNormals[t][(k + 1) % 3]] +
                                           mesh.parameters[mesh.triangleNormals[t][(k + 2) % 3]]);
            // the triangle's own normal at this corner, tried in place
            mesh.normals.push_back(vertexNormal);
            mesh.parameters.push_back(corner);
            mesh.triangleNormals[t][k] = static_cast<std::uint32_t>(mesh.normals.size() - 1);
            Vector3 best = vertexNormal;
            double bestDeg = sampler.triangleMaxDeg(t);
            for (double step : candidateSteps) {
                const Point2 inside = corner + step * (opposite - corner);
                mesh.normals.back() = outwards * surface.normal(inside.x(), inside.y());
                const double deg = sampler.triangleMaxDeg(t);
                if (deg < bestDeg) bestDeg = deg, best = mesh.normals.back();
            }
            if (best == vertexNormal) {  // the vertex's own normal is best: share it
                mesh.normals.pop_back();
                mesh.parameters.pop_back();
                mesh.triangleNormals[t][k] = normal;
                continue;
            }
            mesh.normals.back() = best;
            ++changed;
        }
    }
    return changed;
}

}  // namespace nurbslod::gui
