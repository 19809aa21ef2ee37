#pragma once

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

struct TessellationResult {
    Mesh mesh;
    int faces = 0;
    double seconds = 0;
    double tolerance = 0;
    std::vector<FaceFailure> failures;
};

// Tessellates every face of the model within options.tolerance, sharing edge vertices between
// the faces of an edge. A face that cannot be tessellated is listed in failures with its
// reason; the others are still meshed. Throws std::invalid_argument for a tolerance that is
// not a positive finite number.
TessellationResult tessellateModel(const Model& model, const TessellationOptions& options);

}  // namespace nurbslod
