#include "lod/FaceLod.hpp"

#include <Standard_Failure.hxx>
#include <algorithm>
#include <exception>
#include <limits>
#include <unordered_map>

#include "lod/CollapsedCornerNormals.hpp"
#include "lod/CollapsedPoleRows.hpp"
#include "lod/InterpolatedNormalError.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::gui {

Model singleFaceModel(const Model& model, int faceIndex) {
    Model single;
    single.boundingBoxDiagonal = model.boundingBoxDiagonal;
    single.origin = model.origin;
    TrimmedSurface face = model.faces.at(static_cast<std::size_t>(faceIndex));
    std::unordered_map<int, int> edgeOf, vertexOf;
    auto vertex = [&](int v) {
        if (v < 0 || v >= static_cast<int>(model.vertices.size())) return -1;
        auto [it, added] = vertexOf.try_emplace(v, static_cast<int>(single.vertices.size()));
        if (added) single.vertices.push_back(model.vertices[static_cast<std::size_t>(v)]);
        return it->second;
    };
    for (TrimLoop& loop : face.loops) {
        for (TrimCurve& curve : loop.curves) {
            if (curve.edge < 0 || curve.edge >= static_cast<int>(model.edges.size())) {
                curve.edge = -1;  // the tessellator names the problem
                continue;
            }
            auto [it, added] =
                edgeOf.try_emplace(curve.edge, static_cast<int>(single.edges.size()));
            if (added) {
                ModelEdge edge = model.edges[static_cast<std::size_t>(curve.edge)];
                edge.firstVertex = vertex(edge.firstVertex);
                edge.lastVertex = vertex(edge.lastVertex);
                single.edges.push_back(edge);
            }
            curve.edge = it->second;
        }
    }
    single.faces.push_back(std::move(face));
    return single;
}

namespace {

// The tessellator's mesh indexes positions and normals separately (a crease keeps two
// normals); client arrays want one index per vertex: one vertex per (position, normal) pair.
std::shared_ptr<FaceLod> toFaceLod(Mesh& mesh, double tolerance, const TrimmedSurface& face) {
    auto lod = std::make_shared<FaceLod>();
    lod->tolerance = tolerance;
    takeCollapsedCornerNormalsInside(mesh, face);
    lod->maxNormalErrorDeg = measureInterpolatedNormalError(mesh, face).maxDeg;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOfPair;
    std::fill(lod->boxMin, lod->boxMin + 3, std::numeric_limits<float>::max());
    std::fill(lod->boxMax, lod->boxMax + 3, std::numeric_limits<float>::lowest());
    lod->indices.reserve(mesh.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t position = mesh.triangles[t][corner];
            const std::uint32_t normal = mesh.triangleNormals[t][corner];
            const std::uint64_t key = (std::uint64_t{position} << 32) | normal;
            auto [it, added] = vertexOfPair.try_emplace(
                key, static_cast<std::uint32_t>(lod->positions.size() / 3));
            if (added) {
                for (int k = 0; k < 3; ++k) {
                    const auto p = static_cast<float>(mesh.positions[position][k]);
                    lod->positions.push_back(p);
                    lod->normals.push_back(static_cast<float>(mesh.normals[normal][k]));
                    lod->boxMin[k] = std::min(lod->boxMin[k], p);
                    lod->boxMax[k] = std::max(lod->boxMax[k], p);
                }
            }
            lod->indices.push_back(it->second);
        }
    }
    // Border segments: mesh edges (by position, so split normals do not split an edge) that
    // one triangle uses.
    std::unordered_map<std::uint64_t, std::pair<int, std::size_t>> edgeUses;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t a = mesh.triangles[t][corner];
            const std::uint32_t b = mesh.triangles[t][(corner + 1) % 3];
            const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            auto [it, added] = edgeUses.try_emplace(key, 0, 3 * t + corner);
            ++it->second.first;
        }
    }
    for (const auto& [key, use] : edgeUses) {
        if (use.first != 1) continue;
        const std::size_t first = use.second;
        const std::size_t second = first - first % 3 + (first % 3 + 1) % 3;
        lod->borderLines.push_back(lod->indices[first]);
        lod->borderLines.push_back(lod->indices[second]);
    }
    return lod;
}

}  // namespace

FaceLodResult tessellateFaceLod(const Model& model, int faceIndex, double tolerance) {
    FaceLodResult result;
    try {
        const Model single = singleFaceModel(model, faceIndex);
        TessellationOptions options;
        options.tolerance = tolerance;
        options.mode = ErrorMode::Guaranteed;  // the screen-space error is a bound, not a guess
        options.splitThroughBoundaryPoints = false;
        options.freeEdgesTakeSurfaceShare = false;   // the face alone: its edges are not free
        options.flatCellsByDistance = false;         // normals are measured at equal parameters
        options.evenColumnsCutAcross = false;        // its normal bound was measured on halvings
        options.middleSplits = false;                // and on the paper's cuts
        options.openPointsBoundedBySurface = false;  // and on triangles near the first ones
        TessellationResult tessellation = tessellateModel(single, options);
        if (!tessellation.failures.empty()) {
            result.failure = tessellation.failures.front().reason;
        } else if (tessellation.mesh.triangles.empty()) {
            result.failure = "no triangles";
        } else {
            // Normals (drawn and measured) of the face as the B-rep declares it: a pole where a
            // degenerated edge ends it, though the file's surface row is spread a little.
            int collapsedRows = 0;
            const TrimmedSurface shaded =
                withPoleRowsCollapsed(single, single.faces.front(), &collapsedRows);
            Mesh& mesh = tessellation.mesh;
            if (collapsedRows > 0 && mesh.parameters.size() == mesh.normals.size()) {
                const double outwards = shaded.reversed ? -1.0 : 1.0;
                for (std::size_t k = 0; k < mesh.normals.size(); ++k)
                    mesh.normals[k] = outwards * shaded.surface.normal(mesh.parameters[k].x(),
                                                                       mesh.parameters[k].y());
            }
            result.lod = toFaceLod(mesh, tolerance, shaded);
        }
    } catch (const Standard_Failure& failure) {
        result.failure = std::string("OpenCASCADE failed: ") + failure.GetMessageString();
    } catch (const std::exception& error) {
        result.failure = error.what();
    } catch (...) {
        result.failure = "unknown error";
    }
    return result;
}

}  // namespace nurbslod::gui
