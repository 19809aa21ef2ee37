#pragma once

#include <vector>

#include "tessellate/FaceBoundary.hpp"
#include "tessellate/FaceMesh.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// The triangles of a face too thin for the kd-tree cells to find any area inside its loops (a
// sliver whose area is below the integer grid's resolution or tolerance^2): a fan over each
// boundary polygon, made of the shared edge vertices only, so that the face is never missing
// from the mesh and stays joined to its neighbours. Its triangles lie between the face's
// edges, whose polylines already carry the trimming error bound.
FaceMesh fanOverBoundary(const TrimmedSurface& face, const std::vector<BoundaryLoop>& loops,
                         const std::vector<Point3>& sharedPositions);

}  // namespace nurbslod
