#pragma once

#include "tessellate/Mesh.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod::gui {

// Display normals at corners where the surface (nearly) collapses. At a degenerate edge that
// is not quite a point (an edge of 0.0013 mm, as on corpus trj7 faces 170 and 174 before
// CollapsedPoleRows collapses their row of control points for the display), one derivative is about
// 1e-4 of the other, BSplineSurface::normal takes the normal where it is asked, and that is the
// normal of a sliver a hundredth of a millimetre wide in which the surface turns by 85 degrees.
// Drawn at the vertex and interpolated across triangles of several millimetres, it shades them up
// to 70 degrees off (appearance paper, section 4.1), at every level: the tessellator refines for
// distance, which the sliver does not spoil. At a true pole the limit normal is one of many where
// the surface is a cone's tip.
//
// So each triangle gets its own normal at such a corner: of the vertex's normal and the exact
// normals 1/16, 1/8, 1/4 and 1/2 of the way from the corner to the middle of the opposite
// edge, the one whose interpolation across the triangle measures the smallest error
// (InterpolatedNormalSampler), i.e. the normal the triangle's own surface has at the
// triangle's scale. A corner qualifies when its smaller first derivative is below 1e-2 of the
// larger. Adds one normal (with its corner's (u, v)) per changed triangle corner to
// mesh.normals and mesh.parameters and points triangleNormals at it; positions are untouched.
// Returns how many corners changed. A mesh without parameters is left as it is.
int takeCollapsedCornerNormalsInside(Mesh& mesh, const TrimmedSurface& face);

}  // namespace nurbslod::gui
