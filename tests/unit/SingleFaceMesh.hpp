#pragma once

#include <stdexcept>

#include "lod/FaceLod.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::testing {

// The guaranteed mesh of face `face` (0-based) of the model alone within `tolerance`; throws
// the tessellator's reason when the face fails.
inline Mesh singleFaceMesh(const Model& model, int face, double tolerance) {
    TessellationOptions options;
    options.tolerance = tolerance;
    options.mode = ErrorMode::Guaranteed;
    const TessellationResult result = tessellateModel(gui::singleFaceModel(model, face), options);
    if (!result.failures.empty()) throw std::runtime_error(result.failures.front().reason);
    return result.mesh;
}

}  // namespace nurbslod::testing
