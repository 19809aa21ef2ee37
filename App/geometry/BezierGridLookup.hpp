#pragma once

#include <span>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"

namespace nurbslod {

// Where each grid parameter of one direction falls in a BezierPatchGrid: the patch index, the
// local parameter in [0, 1] and its complement, and d(local)/d(global) for the derivatives.
// Computed once per distinct parameter: the precomputed de Casteljau weights of Carriere
// (evaluation paper, section 2.2). Throws std::invalid_argument for a non-finite parameter.
struct BezierGridLookup {
    std::vector<int> patch;
    std::vector<double> local, complement, scale, parameter;

    static BezierGridLookup alongU(const BezierPatchGrid& grid, std::span<const double> us);
    static BezierGridLookup alongV(const BezierPatchGrid& grid, std::span<const double> vs);
};

}  // namespace nurbslod
