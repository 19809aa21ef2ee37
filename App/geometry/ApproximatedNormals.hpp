#pragma once

#include "geometry/Point.hpp"

namespace nurbslod {

// How the facet normals around a vertex are combined (evaluation paper, section 3).
enum class NormalWeighting {
    Uniform,      // unit facet normals, summed
    Area,         // facet cross products summed as they are: weights by area, no normalising
    InverseArea,  // larger weight to smaller facets (Max 1999)
    Angle,        // weight by the facet's angle at the vertex (Thurmer and Wuthrich 1998)
};

const char* toString(NormalWeighting weighting);

// How a boundary vertex gets its normal from the interior along its iso-parametric line.
enum class BoundaryExtrapolation {
    // The paper's (section 3, figure 1): the last interior normal reflected across the plane
    // perpendicular to the chord to the boundary vertex. Exact on a circle; it cannot follow a
    // rotation of the normal about the chord (the surface's twist across the line), an O(h)
    // error.
    Reflection,
    // Beyond the paper: the last two interior normals extrapolated linearly, 2 N_1 - N_2,
    // normalised: follows bending and twist alike, O(h^2). Needs 4 points along the line (the
    // reflection is used on shorter lines).
    Linear,
};

// Approximated unit normals of a grid of points (rows x columns, row-major, the layout of the
// grid evaluators) from its facets: at an interior vertex the four triangles it forms with its
// four grid neighbours, weighted as asked. A boundary vertex gets its normal extrapolated from
// the interior along its iso-parametric line (section 3): no neighbouring surface needed;
// boundary rows are extrapolated after the boundary columns, so corners come from the already
// extrapolated column ends. A degenerate facet (a
// pole, coincident points) contributes nothing; a vertex left without any normal gets (0, 0, 1).
// The grid needs at least 3 x 3 points (std::invalid_argument otherwise).
void approximateGridNormals(
    const Point3* points, int rows, int columns, NormalWeighting weighting, Vector3* normals,
    BoundaryExtrapolation extrapolation = BoundaryExtrapolation::Reflection);

}  // namespace nurbslod
