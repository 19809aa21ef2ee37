#pragma once

#include <TopoDS_Shape.hxx>
#include <filesystem>
#include <optional>
#include <string>

#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod::test {

// A corpus file read and imported, or none where the corpus is not there (the test then skips).
struct CorpusModel {
    TopoDS_Shape shape;
    Model model;
};
inline std::optional<CorpusModel> corpusModel(const std::string& name) {
    const auto path = std::filesystem::path(NURBSLOD_CORPUS_DIR) / name;
    if (!std::filesystem::exists(path)) return std::nullopt;
    const TopoDS_Shape shape = occ::readShape(path.string());
    return CorpusModel{shape, occ::importModel(shape)};
}

// A corpus model tessellated in guaranteed mode at `relative` of its bounding box's diagonal,
// or none where the corpus is not there (the test then skips).
inline std::optional<TessellationResult> tessellatedCorpusModel(const std::string& name,
                                                                double relative) {
    const auto corpus = corpusModel(name);
    if (!corpus) return std::nullopt;
    TessellationOptions options;
    options.tolerance = relative * corpus->model.boundingBoxDiagonal;
    return tessellateModel(corpus->model, options);
}

}  // namespace nurbslod::test
