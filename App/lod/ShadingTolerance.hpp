#pragma once

#include "trim/TrimmedSurface.hpp"

namespace nurbslod::gui {

// Appearance-preserving tessellation (paper appearance, section 4.1): the normal error of the
// drawn mesh is bounded as well as its distance to the surface. The paper estimates the
// shading error from the maximum curvature, max(c_u, c_v): the normal turns fastest, and a
// chord deviates most in normal, along the direction of maximum curvature. Per face, the
// angle bound becomes a distance tolerance through that curvature, and a level of the face's
// LOD cache that meets the tolerance meets the angle bound too.

// The largest absolute principal curvature of the face, 1 / model units, estimated from the
// exact curvature (SurfaceCurvature) sampled over the part of the parameter domain its
// trimming loops enclose. 0 for a plane. Throws std::invalid_argument naming the face when
// the surface has no finite curvature anywhere sampled (NaN poles, weights <= 0).
double maximumCurvature(const TrimmedSurface& face);

// The largest distance between a chord and the surface that keeps the facet normal within
// normalErrorRadians of the exact normals at the chord's ends, where the surface bends with
// curvature `curvature` (see the .cpp for the derivation). Infinity when the bound is off
// (normalErrorRadians == 0) or the surface is flat (curvature == 0). Throws
// std::invalid_argument for an angle outside [0, pi/2) or a negative or non-finite curvature.
double shadingTolerance(double normalErrorRadians, double curvature);

}  // namespace nurbslod::gui
