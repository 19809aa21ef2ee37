#include "tessellate/LoneFaces.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "tessellate/EvenColumns.hpp"
#include "tessellate/KdTreeAlignedHalving.hpp"

namespace nurbslod {

std::vector<int> loneBoxFaces(const Model& model, double exactEdgeTolerance) {
    const int faceCount = static_cast<int>(model.faces.size());
    const int edgeCount = static_cast<int>(model.edges.size());
    const int vertexCount = static_cast<int>(model.vertices.size());
    // the face using each edge and each vertex (-2: more than one face), and each edge's uses
    constexpr int kNone = -1, kSeveral = -2;
    std::vector<int> edgeFace(model.edges.size(), kNone), vertexFace(model.vertices.size(), kNone);
    std::vector<int> uses(model.edges.size(), 0);
    std::vector<char> candidate(model.faces.size(), 1);
    auto claim = [](int& owner, int f) { owner = owner == kNone || owner == f ? f : kSeveral; };
    for (int f = 0; f < faceCount; ++f)
        for (const auto& loop : model.faces[f].loops)
            for (const auto& curve : loop.curves) {
                const int e = curve.edge;
                if (e < 0 || e >= edgeCount) {
                    candidate[f] = 0;
                    continue;
                }
                claim(edgeFace[e], f);
                ++uses[e];
                for (const int v : {model.edges[e].firstVertex, model.edges[e].lastVertex})
                    if (v >= 0 && v < vertexCount) claim(vertexFace[v], f);
            }
    std::vector<char> anyFree(model.faces.size(), 0);
    for (int f = 0; f < faceCount; ++f)
        for (const auto& loop : model.faces[f].loops)
            for (const auto& curve : loop.curves) {
                const int e = curve.edge;
                if (!candidate[f] || e < 0 || e >= edgeCount) continue;
                const ModelEdge& edge = model.edges[e];
                if (edgeFace[e] != f) candidate[f] = 0;
                for (const int v : {edge.firstVertex, edge.lastVertex})
                    if (v >= 0 && v < vertexCount && vertexFace[v] != f) candidate[f] = 0;
                if (uses[e] == 1 && !edge.degenerated) {
                    anyFree[f] = 1;
                    if (!(edge.tolerance <= exactEdgeTolerance)) candidate[f] = 0;
                }
            }
    std::vector<int> lone;
    for (int f = 0; f < faceCount; ++f) {
        if (!candidate[f] || !anyFree[f]) continue;
        const FaceKdTreeLines lines = kdTreeLinesBeforeDiscretisation(model.faces[f]);
        const auto grids = lines.forColumns();
        if (lines.both() && grids && regionIsTheBox(model.faces[f], *grids)) lone.push_back(f);
    }
    return lone;
}

Model loneFaceModel(const Model& model, int face) {
    Model alone;
    alone.boundingBoxDiagonal = model.boundingBoxDiagonal;
    alone.origin = model.origin;
    alone.faces.push_back(model.faces[face]);
    alone.faces[0].faceIndex = 1;
    std::map<int, int> edgeIndex, vertexIndex;
    auto vertexOf = [&](int v) {
        if (v < 0) return -1;
        const auto [at, added] = vertexIndex.emplace(v, static_cast<int>(alone.vertices.size()));
        if (added) alone.vertices.push_back(model.vertices[v]);
        return at->second;
    };
    for (auto& loop : alone.faces[0].loops)
        for (auto& curve : loop.curves) {
            if (curve.edge < 0) continue;
            const auto [at, added] =
                edgeIndex.emplace(curve.edge, static_cast<int>(alone.edges.size()));
            if (added) {
                ModelEdge edge = model.edges[curve.edge];
                edge.firstVertex = vertexOf(edge.firstVertex);
                edge.lastVertex = vertexOf(edge.lastVertex);
                alone.edges.push_back(edge);
            }
            curve.edge = at->second;
        }
    return alone;
}

namespace {

// Calls `single(face)` for every side that one triangle alone has among the triangles `take`
// accepts (by index), with that triangle's face. The sides are keyed by their two positions,
// smaller first, and sorted, so such a side is a run of one: a std::map of the sides took a
// tenth of a 50,000-triangle model's tessellation, which counts them twice.
template <typename Take, typename Single>
void forEachSingleSide(const Mesh& mesh, Take take, Single single) {
    std::vector<std::pair<std::uint64_t, std::int32_t>> sides;
    sides.reserve(3 * mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!take(t)) continue;
        const auto& c = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const auto [a, b] = std::minmax(c[k], c[(k + 1) % 3]);
            sides.push_back({(std::uint64_t(a) << 32) | b, mesh.triangleFaces[t]});
        }
    }
    std::sort(sides.begin(), sides.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].first == sides[i].first) ++j;
        if (j == i + 1) single(sides[i].second);
        i = j;
    }
}

}  // namespace

std::size_t faceOpenEdges(const Mesh& mesh, int face) {
    std::size_t open = 0;
    forEachSingleSide(
        mesh, [&](std::size_t t) { return mesh.triangleFaces[t] == face; },
        [&](std::int32_t) { ++open; });
    return open;
}

std::vector<std::size_t> meshOpenEdgesByFace(const Mesh& mesh, std::size_t faces) {
    std::vector<std::size_t> open(faces, 0);
    forEachSingleSide(
        mesh, [](std::size_t) { return true; },
        [&](std::int32_t face) {
            if (face >= 1 && static_cast<std::size_t>(face) <= faces) ++open[face - 1];
        });
    return open;
}

void replaceFaceTriangles(Mesh& mesh, int face, const Mesh& alone) {
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    Mesh result;
    std::vector<std::uint32_t> position(mesh.positions.size(), kNone),
        normal(mesh.normals.size(), kNone);
    auto keepPosition = [&](std::uint32_t i) {
        if (position[i] == kNone) {
            position[i] = static_cast<std::uint32_t>(result.positions.size());
            result.positions.push_back(mesh.positions[i]);
        }
        return position[i];
    };
    auto keepNormal = [&](std::uint32_t i) {
        if (normal[i] == kNone) {
            normal[i] = static_cast<std::uint32_t>(result.normals.size());
            result.normals.push_back(mesh.normals[i]);
            result.parameters.push_back(mesh.parameters[i]);
        }
        return normal[i];
    };
    auto addAlone = [&] {
        const auto positionBase = static_cast<std::uint32_t>(result.positions.size());
        const auto normalBase = static_cast<std::uint32_t>(result.normals.size());
        result.positions.insert(result.positions.end(), alone.positions.begin(),
                                alone.positions.end());
        result.normals.insert(result.normals.end(), alone.normals.begin(), alone.normals.end());
        result.parameters.insert(result.parameters.end(), alone.parameters.begin(),
                                 alone.parameters.end());
        for (std::size_t t = 0; t < alone.triangles.size(); ++t) {
            std::array<std::uint32_t, 3> corners = alone.triangles[t],
                                         normals = alone.triangleNormals[t];
            for (auto& i : corners) i += positionBase;
            for (auto& i : normals) i += normalBase;
            result.triangles.push_back(corners);
            result.triangleNormals.push_back(normals);
            result.triangleFaces.push_back(face);
        }
    };
    bool added = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.triangleFaces[t] == face) {
            if (!added) addAlone();
            added = true;
            continue;
        }
        std::array<std::uint32_t, 3> corners, normals;
        for (int k = 0; k < 3; ++k) {
            corners[k] = keepPosition(mesh.triangles[t][k]);
            normals[k] = keepNormal(mesh.triangleNormals[t][k]);
        }
        result.triangles.push_back(corners);
        result.triangleNormals.push_back(normals);
        result.triangleFaces.push_back(mesh.triangleFaces[t]);
    }
    if (!added) addAlone();
    mesh = std::move(result);
}

}  // namespace nurbslod
