#include "tessellate/FacePatchGrids.hpp"

namespace nurbslod {

FacePatchGrids::FacePatchGrids(const Model& model)
    : model_(&model),
      made_(std::make_unique<std::once_flag[]>(model.faces.size())),
      grids_(model.faces.size()) {}

std::shared_ptr<const BezierPatchGrid> FacePatchGrids::of(int face) const {
    const auto f = static_cast<std::size_t>(face);
    std::call_once(made_[f], [&] {
        grids_[f] = std::make_shared<const BezierPatchGrid>(model_->faces[f].surface);
    });
    return grids_[f];
}

void FacePatchGrids::give(int face, std::shared_ptr<const BezierPatchGrid> grid) {
    const auto f = static_cast<std::size_t>(face);
    std::call_once(made_[f], [&] { grids_[f] = std::move(grid); });
}

}  // namespace nurbslod
