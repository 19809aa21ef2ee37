#pragma once

#include <vector>

#include "tessellate/FaceBoundary.hpp"
#include "tessellate/FaceMesh.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// The triangles of a face too thin for the kd-tree cells to find any area inside its loops (a
// sliver whose area is below the integer grid's resolution or tolerance^2): each boundary
// polygon triangulated over the shared edge vertices only, so that the face is never missing
// from the mesh and stays joined to its neighbours. The ears with the shortest diagonals go
// first, so that the triangles zip the sliver's sides together and lie between the face's
// edges, whose polylines already carry the trimming error bound. (Not measured against the
// surface: a sliver's surface between its sides is within about the chords' bound.)
FaceMesh fanOverBoundary(const TrimmedSurface& face, const std::vector<BoundaryLoop>& loops,
                         const std::vector<Point3>& sharedPositions);

}  // namespace nurbslod
