#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/Model.hpp"
#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

// What a tessellation measures of each face's surface on its own, made on the first use of a
// face and kept for the model's second tessellation and the lone faces' retries:
//  - its Bezier patches (BezierPatchGrid), which its even-column tests, its surface need and cell
//    estimate and its FaceTessellator all read. A B-spline fitted to a shape (the generated
//    fitted_surface.brep: 2 ms a grid) made ten of them at relative 1e-3;
//  - its surface need (faceSurfaceNeed), measured over every one of those patches: a fifth of
//    that fitted surface's tessellation, three times.
// Safe to ask from several threads; the model must outlive it and its faces must not change.
class FaceSurfaceCache {
public:
    explicit FaceSurfaceCache(const Model& model);
    FaceSurfaceCache(const FaceSurfaceCache&) = delete;
    FaceSurfaceCache& operator=(const FaceSurfaceCache&) = delete;

    // Throws what BezierPatchGrid throws for the face's surface (and tries again next time).
    std::shared_ptr<const BezierPatchGrid> patches(int face) const;
    // faceSurfaceNeed(face, mode, cap) over patches(face), kept for the last mode and cap asked.
    double surfaceNeed(int face, ErrorMode mode, double cap) const;
    // Takes what `other` has of its face `otherFace` as this face's, where this one has nothing
    // yet: the same face on a model of its own (a lone face's retry, loneFaceModel). Throws
    // where the other cannot make the face's patches (nothing is taken then).
    void take(int face, const FaceSurfaceCache& other, int otherFace);

private:
    struct Need {
        bool known = false;
        ErrorMode mode = ErrorMode::Guaranteed;
        double cap = 0, value = 0;
    };
    const Model* model_;
    std::unique_ptr<std::once_flag[]> made_;
    mutable std::vector<std::shared_ptr<const BezierPatchGrid>> grids_;
    std::unique_ptr<std::mutex[]> needLocks_;
    mutable std::vector<Need> needs_;
};

}  // namespace nurbslod
