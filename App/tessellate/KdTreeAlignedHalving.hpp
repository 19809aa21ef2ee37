#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "tessellate/KdTreeGrid.hpp"
#include "trim/CurveOnSurface.hpp"
#include "trim/EdgeDiscretizer.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// A face's kd-tree lines (u, then v) as far as they are known before its edges are
// discretised. FaceTessellator frames the box of the boundary points; where every trimming
// curve lies within the box of the curves' end points (its control points do: cylinders,
// cones, the bands between two helices), that box is it, whatever the points in between.
// None where a curve may bulge past it: the frame then waits for the points.
std::optional<std::array<KdTreeGrid, 2>> kdTreeGridsBeforeDiscretisation(
    const TrimmedSurface& face);

// Discretises an edge (discretizeEdge) with its pieces halved on kd-tree lines of the face of
// uses[use]: at the coarsest line crossing the middle half of a piece, along the axis the
// kd-tree cuts that curve on. The points then fall where that face's kd-tree cuts, and its
// cells add none between them. The axis is the one varying along an iso-parameter line, or the
// bent one across a straight curve on a surface straight the other way (a helix on a
// cylinder: u). Without `grids` (a face whose frame waits for its points) the lines are those
// of a kd-tree over the curve's own range, for an iso-parameter line: that at least puts a
// face's curves of one range (a cylinder's two circles) on one grid. None where the curve is
// not straight in (u, v) or no axis is clear (a diagonal on a plane, whose kd-tree does not
// cut for error).
std::optional<std::vector<double>> discretizeEdgeOnKdTreeLines(
    const std::vector<CurveOnSurface>& uses, std::size_t use,
    const std::optional<std::array<KdTreeGrid, 2>>& grids, double approximation,
    double simplification, std::vector<CurvePoints>* points = nullptr);

}  // namespace nurbslod
