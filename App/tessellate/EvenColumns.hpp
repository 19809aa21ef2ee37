#pragma once

#include <array>

#include "tessellate/ErrorBudget.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// Chooses even columns (KdTreeGrid::setEvenColumns) for a face whose trimmed region is the whole
// box of its kd-tree frame (every trimming curve straight in (u, v) along one of the box's
// sides: a cylinder or cone between two circles, a rectangle of a plane). The kd-tree halves a
// cell, so a span gets a power of two of columns: a half cylinder whose columns may each turn
// 3.9 degrees gets 64 where 47 would do, and its circles carry those points too. Along an axis
// whose cells spanning the other axis's whole spans can meet `target` (the face's surface
// share, bounded as cells the region fills to their sides), each span gets the fewest equal
// columns that do, measured with the kd-tree's own cell bound; an axis where none do keeps
// its halvings. Only the axes in `axes`: the caller leaves out an axis along which an edge of
// the face is shared with a face that cuts it on kd-tree lines of its own (a cylinder's circle
// on a torus), whose halvings would then cut the edge between the columns' points.
// Returns whether any span got even columns.
bool chooseEvenColumns(const TrimmedSurface& face, std::array<KdTreeGrid, 2>& grids, double target,
                       ErrorMode mode, bool flatCellsByDistance, std::array<bool, 2> axes);

}  // namespace nurbslod
