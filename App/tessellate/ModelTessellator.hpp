#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessellate/Mesh.hpp"
#include "tessellate/Model.hpp"
#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

struct FaceFailure {
    int face = 0;  // 1-based
    std::string reason;
};

// The vertices a face's tessellator evaluated on the face's surface: (u, v) of each, and
// whether its position came from the surface (the face's own points) or from a shared edge
// (where only the normal was wanted).
struct FaceVertexSet {
    std::vector<Point2> uv;
    std::vector<char> needsPosition;
    // the face's own positions, before the mesh welds points closer than its weld distance
    std::vector<Point3> positions;
    // the index in mesh.normals and mesh.parameters of the first vertex; the others follow
    std::uint32_t firstNormal = 0;
};

struct TessellationResult {
    Mesh mesh;
    int faces = 0;
    double seconds = 0;
    double tolerance = 0;
    std::vector<FaceFailure> failures;
    // faces meshed, with a word on their input (TrimmedSurface::warning), in face order
    std::vector<FaceFailure> warnings;
    // per face (index face - 1), filled when TessellationOptions::keepFaceVertices is set
    std::vector<FaceVertexSet> faceVertices;
};

// Tessellates every face of the model within options.tolerance, sharing edge vertices between
// the faces of an edge. A face that cannot be tessellated is listed in failures with its
// reason; the others are still meshed. Throws std::invalid_argument for a tolerance that is
// not a positive finite number.
TessellationResult tessellateModel(const Model& model, const TessellationOptions& options);

}  // namespace nurbslod
