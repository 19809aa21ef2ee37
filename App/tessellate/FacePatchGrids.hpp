#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/Model.hpp"

namespace nurbslod {

// The Bezier patches of each face of a model (BezierPatchGrid), made on the first use of a face
// and shared by everything that bounds its cells in a tessellation and the next one of the same
// model: the even-column tests of each of its axes, its surface need and cell estimate, its
// FaceTessellator. A B-spline fitted to a shape (the generated fitted_surface.brep: 2 ms a grid)
// made ten of them at relative 1e-3. Safe to ask from several threads; the model must outlive it
// and its faces' surfaces must not change.
class FacePatchGrids {
public:
    explicit FacePatchGrids(const Model& model);
    FacePatchGrids(const FacePatchGrids&) = delete;
    FacePatchGrids& operator=(const FacePatchGrids&) = delete;

    // Throws what BezierPatchGrid throws for the face's surface (and tries again next time).
    std::shared_ptr<const BezierPatchGrid> of(int face) const;
    // Takes `grid` as the face's, where it has none yet: another model's grid of the same
    // surface (a lone face's retry on a model of its own, loneFaceModel).
    void give(int face, std::shared_ptr<const BezierPatchGrid> grid);

private:
    const Model* model_;
    std::unique_ptr<std::once_flag[]> made_;
    mutable std::vector<std::shared_ptr<const BezierPatchGrid>> grids_;
};

}  // namespace nurbslod
