#pragma once

#include <stdexcept>

#include "lod/FaceLod.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::testing {

// The guaranteed mesh of face `face` (0-based) of the model alone within `tolerance`, under the
// display's cell bound (at equal parameters, TessellationOptions::flatCellsByDistance); throws
// the tessellator's reason when the face fails.
inline Mesh singleFaceMesh(const Model& model, int face, double tolerance) {
    TessellationOptions options;
    options.tolerance = tolerance;
    options.mode = ErrorMode::Guaranteed;
    options.flatCellsByDistance = false;  // the display's bound: its normals are measured with it
    const TessellationResult result = tessellateModel(gui::singleFaceModel(model, face), options);
    if (!result.failures.empty()) throw std::runtime_error(result.failures.front().reason);
    return result.mesh;
}

}  // namespace nurbslod::testing
