#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "tessellate/FaceMesh.hpp"
#include "tessellate/LeastBoundRing.hpp"

namespace nurbslod {

// Removes the face's own points from the chords of its open boundary (a free edge, or a sloppy
// edge whose faces keep separate polylines): a kd-tree cell side that crosses such a chord
// leaves a vertex on it that no other face shares, and every such vertex is one more open edge
// of the mesh. All such vertices of one chord go at once: the union of their fans is
// re-triangulated without them when the new triangles are valid in (u, v) and the new surface is
// within `allowance` of the first one, less the share budget that the ring's shared vertices
// already spend (sharedOffsets, by shared id), plus what the old triangles' cells leave of the
// surface share (slack, by triangle: the surface share less the cell's bound): the new
// triangles then stay within the face's bound, as those were the parts of it left unspent.
// Where that fails, each half of the chord's vertices is tried, then each vertex alone; a
// re-triangulation of triangles an earlier one made counts that one's change too. Works in
// (u, v) counter-clockwise order, before any reversal of the face. Returns how many points were
// removed.
//
// Where the new triangles change the first ones by more than that, they may still be bounded
// against the surface itself: `triangleBound`, where given, bounds how far a triangle of the
// face's vertices (by index) is from the surface, both ways, and a re-triangulation whose every
// triangle is within `surfaceShare` plus the allowance that way is taken too.
std::size_t removeOpenBoundaryPoints(FaceMesh& mesh, const std::vector<double>& sharedOffsets,
                                     const std::vector<double>& slack, double allowance,
                                     const TriangleBound& triangleBound = nullptr,
                                     double surfaceShare = 0);

}  // namespace nurbslod
