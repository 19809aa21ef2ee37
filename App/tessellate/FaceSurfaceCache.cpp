#include "tessellate/FaceSurfaceCache.hpp"

#include "tessellate/FaceSurfaceNeed.hpp"

namespace nurbslod {

FaceSurfaceCache::FaceSurfaceCache(const Model& model)
    : model_(&model),
      made_(std::make_unique<std::once_flag[]>(model.faces.size())),
      grids_(model.faces.size()),
      needLocks_(std::make_unique<std::mutex[]>(model.faces.size())),
      needs_(model.faces.size()) {}

std::shared_ptr<const BezierPatchGrid> FaceSurfaceCache::patches(int face) const {
    const auto f = static_cast<std::size_t>(face);
    std::call_once(made_[f], [&] {
        grids_[f] = std::make_shared<const BezierPatchGrid>(model_->faces[f].surface);
    });
    return grids_[f];
}

double FaceSurfaceCache::surfaceNeed(int face, ErrorMode mode, double cap) const {
    const auto f = static_cast<std::size_t>(face);
    const std::lock_guard<std::mutex> lock(needLocks_[f]);
    Need& need = needs_[f];
    if (!need.known || need.mode != mode || need.cap != cap)
        need = {true, mode, cap, faceSurfaceNeed(model_->faces[f], mode, cap, patches(face).get())};
    return need.value;
}

void FaceSurfaceCache::take(int face, const FaceSurfaceCache& other, int otherFace) {
    const auto f = static_cast<std::size_t>(face), o = static_cast<std::size_t>(otherFace);
    std::shared_ptr<const BezierPatchGrid> grid = other.patches(otherFace);
    std::call_once(made_[f], [&] { grids_[f] = std::move(grid); });
    Need known;
    {
        const std::lock_guard<std::mutex> lock(other.needLocks_[o]);
        known = other.needs_[o];
    }
    const std::lock_guard<std::mutex> lock(needLocks_[f]);
    if (!needs_[f].known) needs_[f] = known;
}

}  // namespace nurbslod
