#pragma once

#include <cstddef>

#include "tessellate/FaceMesh.hpp"
#include "tessellate/LeastBoundRing.hpp"

namespace nurbslod {

// Removes the face's own inner points wherever the triangles that then replace their fans are
// each bounded within `limit` of the surface (TessellationOptions::compact, guaranteed mode).
// The kd-tree's cells hold their triangles to the surface share with a bound for any triangles
// over the cell, and halve; a triangle bounded on its own (FaceTessellator::triangleBound, its
// affine map against the surface) may take the whole tolerance less the other shares where it
// has no side on the face's boundary, since only the surface is then between it and the face.
// A point goes where its fan is a closed disk of at most 8 triangles, no side of the disk's ring
// is on the boundary, and a triangulation of the ring has every triangle within the limit:
//  - `lowerBound` is at most the deviation of every triangle (the surface's distance from it at
//    a few points); a point is tried first against its own distance from every triangle of the
//    ring's points that holds it in (u, v) (no surface point), then by the least triangulation
//    under `lowerBound`, and that one is taken where `bound` holds for each of its triangles,
//    else the least triangulation under `bound` is searched; `bound` is asked only of triangles
//    whose `lowerBound` is within the limit (it need not sample the surface again), and each
//    of the two at most once per triangle of a ring;
//  - the ring is re-triangulated as the removal of open boundary points does
//    (leastBoundTriangulation: valid in (u, v), facing the surface's normals as the old
//    triangles did, no edge twice).
// Points are visited once, in index order; a point whose fan an earlier removal grew is tried
// with its fan as it is then. Works in (u, v) counter-clockwise order, before any reversal of
// the face. Returns how many points were removed.
std::size_t removeInteriorPoints(FaceMesh& mesh, const TriangleBound& lowerBound,
                                 const TriangleBound& bound, double limit);

}  // namespace nurbslod
