#include "tessellate/AnalysisMesh.hpp"

#include <tbb/parallel_for.h>

#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/SurfaceCurvature.hpp"

namespace nurbslod {

AnalysisMesh analysisMesh(const Model& model, const Mesh& mesh) {
    if (mesh.parameters.size() != mesh.normals.size())
        throw std::invalid_argument(
            "the mesh has no (u, v) for its normals: " + std::to_string(mesh.parameters.size()) +
            " for " + std::to_string(mesh.normals.size()));
    if (mesh.triangleNormals.size() != mesh.triangles.size() ||
        mesh.triangleFaces.size() != mesh.triangles.size())
        throw std::invalid_argument("the mesh's triangle lists differ in length");

    // A normal belongs to exactly one (vertex, face) pair: it is the analysis vertex.
    constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> vertexOfNormal(mesh.normals.size(), unused);
    AnalysisMesh out;
    out.triangles.reserve(mesh.triangles.size());
    out.triangleFaces = mesh.triangleFaces;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int face = mesh.triangleFaces[t];
        if (face < 1 || face > static_cast<int>(model.faces.size()))
            throw std::invalid_argument("triangle " + std::to_string(t) + " names face " +
                                        std::to_string(face) + ", which the model does not have");
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t normal = mesh.triangleNormals[t][k];
            const std::uint32_t position = mesh.triangles[t][k];
            if (normal >= mesh.normals.size() || position >= mesh.positions.size())
                throw std::invalid_argument("triangle " + std::to_string(t) +
                                            " has an index out of range");
            if (vertexOfNormal[normal] == unused) {
                vertexOfNormal[normal] = static_cast<std::uint32_t>(out.points.size());
                out.points.push_back(mesh.positions[position]);
                out.normals.push_back(mesh.normals[normal]);
                out.parameters.push_back(mesh.parameters[normal]);
            }
            triangle[k] = vertexOfNormal[normal];
        }
        out.triangles.push_back(triangle);
    }

    // the face of each vertex: any triangle that uses it
    const std::size_t n = out.points.size();
    std::vector<std::int32_t> faceOfVertex(n, 0);
    for (std::size_t t = 0; t < out.triangles.size(); ++t)
        for (const std::uint32_t v : out.triangles[t]) faceOfVertex[v] = out.triangleFaces[t];

    out.gaussian.resize(n);
    out.mean.resize(n);
    out.minimum.resize(n);
    out.maximum.resize(n);
    std::atomic<std::size_t> singular{0};
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
        const TrimmedSurface& face = model.faces[faceOfVertex[v] - 1];
        const Point2& uv = out.parameters[v];
        const auto exact = curvatureAt(face.surface, uv.x(), uv.y());
        if (!exact) ++singular;
        const SurfaceCurvature c = exact ? *exact : displayCurvature(face.surface, uv.x(), uv.y());
        // SurfaceCurvature is signed against du x dv, positive where the surface bends towards
        // it. The display's normal is the face's outward one (du x dv reversed for a reversed
        // face), and designers read a convex bump as positive: flip once for the convention
        // and once more for a reversed face.
        const double sign = face.reversed ? 1.0 : -1.0;
        out.gaussian[v] = c.gaussian;
        out.mean[v] = sign * c.mean;
        out.minimum[v] = sign > 0 ? c.minimum : -c.maximum;
        out.maximum[v] = sign > 0 ? c.maximum : -c.minimum;
    });
    out.singularVertices = singular;
    return out;
}

}  // namespace nurbslod
