#pragma once

#include "tessellate/Mesh.hpp"

namespace nurbslod {

// Turns each triangle's corners round (keeping its winding, and its normals with them) so that
// the first is at its largest angle, opposite its longest side.
//
// Why: the usual closest-point-on-triangle test (Ericson, Real-Time Collision Detection 5.1.5,
// which Embree-based tools such as Open3D run in single precision) works from the first corner
// along its two sides. Where that corner is a needle's sharp tip, both sides are long and
// nearly parallel, and the barycentric sums cancel: a point lying on a triangle 21,980 long and
// 62 wide (hammer.iges at relative 1e-4, a ruled face's columns) reads 78 away from it in
// single precision; started at a corner of its short side, 0.003. The mesh is the same surface
// either way; only its readers' rounding changes. A triangle with one angle near 180 degrees
// stays poor whichever corner comes first (about 3 for a cap 1,000 long and 0.1 high), though
// least so from its wide angle.
void startAtLargestAngle(Mesh& mesh);

}  // namespace nurbslod
