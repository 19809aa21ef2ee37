#include "tessellate/AnalysisMesh.hpp"

#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

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

    // A normal belongs to exactly one (vertex, face) pair: that is the analysis vertex,
    // except on a knot line where the surface is less than C2. There the curvature (and below
    // C1 the normal) has a value on each side, so the vertex is split by the side of the
    // triangle that uses it, and each copy is evaluated on its own side: the map then shows
    // the jump at the joint instead of smearing it over the triangles next to it.
    std::vector<std::vector<double>> jointsU(model.faces.size()), jointsV(model.faces.size());
    auto jointsOf = [](const KnotVector& knots) {
        std::vector<double> joints;
        const auto& values = knots.knots();
        const int degree = knots.degree();
        for (std::size_t i = 0; i < values.size();) {
            std::size_t j = i;
            while (j < values.size() && values[j] == values[i]) ++j;
            const int multiplicity = static_cast<int>(j - i);
            if (values[i] > knots.first() && values[i] < knots.last() && multiplicity > degree - 2)
                joints.push_back(values[i]);
            i = j;
        }
        return joints;
    };
    for (std::size_t f = 0; f < model.faces.size(); ++f) {
        const BSplineSurface& surface = model.faces[f].surface;
        if (surface.problem()) continue;
        jointsU[f] = jointsOf(surface.knotsU());
        jointsV[f] = jointsOf(surface.knotsV());
    }
    // -1, 0 or 1: the side of the joint through t that the triangle (centre c) lies on
    auto sideOf = [](const std::vector<double>& joints, double t, double c, double range) {
        for (const double joint : joints)
            if (std::abs(t - joint) <= 1e-9 * range) return c < joint ? -1 : 1;
        return 0;
    };

    struct Origin {
        std::uint32_t normal;
        int sideU, sideV;
    };
    std::vector<Origin> origins;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOfKey;
    AnalysisMesh out;
    out.triangles.reserve(mesh.triangles.size());
    out.triangleFaces = mesh.triangleFaces;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int face = mesh.triangleFaces[t];
        if (face < 1 || face > static_cast<int>(model.faces.size()))
            throw std::invalid_argument("triangle " + std::to_string(t) + " names face " +
                                        std::to_string(face) + ", which the model does not have");
        for (int k = 0; k < 3; ++k)
            if (mesh.triangleNormals[t][k] >= mesh.normals.size() ||
                mesh.triangles[t][k] >= mesh.positions.size())
                throw std::invalid_argument("triangle " + std::to_string(t) +
                                            " has an index out of range");
        const BSplineSurface& surface = model.faces[face - 1].surface;
        Point2 centre = Point2::Zero();
        for (int k = 0; k < 3; ++k) centre += mesh.parameters[mesh.triangleNormals[t][k]] / 3.0;
        const double rangeU = surface.knotsU().knots().empty()
                                  ? 1.0
                                  : surface.knotsU().last() - surface.knotsU().first();
        const double rangeV = surface.knotsV().knots().empty()
                                  ? 1.0
                                  : surface.knotsV().last() - surface.knotsV().first();
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t normal = mesh.triangleNormals[t][k];
            const Point2& uv = mesh.parameters[normal];
            const int sideU = sideOf(jointsU[face - 1], uv.x(), centre.x(), rangeU);
            const int sideV = sideOf(jointsV[face - 1], uv.y(), centre.y(), rangeV);
            const std::uint64_t key =
                std::uint64_t{normal} * 9 + static_cast<std::uint64_t>((sideU + 1) * 3 + sideV + 1);
            auto [it, inserted] =
                vertexOfKey.emplace(key, static_cast<std::uint32_t>(out.points.size()));
            if (inserted) {
                origins.push_back({normal, sideU, sideV});
                out.points.push_back(mesh.positions[mesh.triangles[t][k]]);
                out.normals.push_back(mesh.normals[normal]);
                out.parameters.push_back(uv);
            }
            triangle[k] = it->second;
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
        // on a joint, a step of 1e-9 of the domain into the triangle's side: the one-sided
        // limit to well within the display's precision
        const Origin& origin = origins[v];
        const KnotVector& knotsU = face.surface.knotsU();
        const KnotVector& knotsV = face.surface.knotsV();
        const double u =
            out.parameters[v].x() + origin.sideU * 1e-9 * (knotsU.last() - knotsU.first());
        const double w =
            out.parameters[v].y() + origin.sideV * 1e-9 * (knotsV.last() - knotsV.first());
        const auto exact = curvatureAt(face.surface, u, w);
        if (!exact) ++singular;
        const SurfaceCurvature c = exact ? *exact : displayCurvature(face.surface, u, w);
        if (exact && (origin.sideU != 0 || origin.sideV != 0))  // a C0 joint has two normals
            out.normals[v] = face.reversed ? Vector3(-exact->normal) : exact->normal;
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
