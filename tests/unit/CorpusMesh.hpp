#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::test {

// A corpus model tessellated in guaranteed mode at `relative` of its bounding box's diagonal,
// or none where the corpus is not there (the test then skips).
inline std::optional<TessellationResult> tessellatedCorpusModel(const std::string& name,
                                                                double relative) {
    const auto path = std::filesystem::path(NURBSLOD_CORPUS_DIR) / name;
    if (!std::filesystem::exists(path)) return std::nullopt;
    const Model model = occ::importModel(occ::readShape(path.string()));
    TessellationOptions options;
    options.tolerance = relative * model.boundingBoxDiagonal;
    return tessellateModel(model, options);
}

}  // namespace nurbslod::test
