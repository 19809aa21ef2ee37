#pragma once

#include <array>
#include <vector>

#include "tessellate/ErrorBudget.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// Even columns (KdTreeGrid::setEvenColumns). The kd-tree halves a cell, so a span gets a power
// of two of columns: a half cylinder whose columns may each turn 3.9 degrees gets 64 where 47
// would do, and its circles carry those points too. A face can take equal columns instead where
// every cell of its kd-tree is full or filled to its sides, i.e. where its trimmed region is
// the whole box of its frame: every trimming curve straight in (u, v) along one of the box's
// sides (a cylinder, cone or torus between circles, a rectangle of a plane). A face whose
// region covers most of the box takes them too (kEvenColumnsRegionShare).
bool regionIsTheBox(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids);

// The share of the face's frame box that its trimmed region covers, in (u, v): 1 for a whole
// box. Loops are sampled (16 points a curve), so it is an estimate, good for a choice only.
double regionShareOfBox(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids);

// A face whose region is not the whole box takes even columns too where it covers at least this
// share of it: most of its cells are then full, and its trimmed cells split further within their
// columns as their bound says, so the columns stay correct, only less useful where the boundary
// runs. The crossed cylinders of tests/bench/generated_shapes.py (the larger one: share 0.88,
// holes where the other meets it; halvings gave it 16 columns a 120-degree span) at relative
// 1e-3 / 1e-4 take 632 / 1,788 triangles instead of 716 / 1,988, bottle.brep's cylinder face 1
// 411 instead of 465 at 1e-3. Below it the kd-tree's halvings follow the region better:
// bug33398.step's half cones cut by a B-spline (share 0.55) took 48 triangles with columns, 42
// without. Tried: 0.5, 0.7, 0.8, 0.9.
inline constexpr double kEvenColumnsRegionShare = 0.8;

// Per interval of `axis` (KdTreeGrid::intervals): the fewest equal columns whose cells, over
// each whole span of the other axis, meet `target` (the face's surface share, bounded as cells
// filled to their sides). 1 where the interval needs no cut; 0 where no count up to 256 does.
// Where a column would need cuts across it too, and `cutAcross`, the fewest (up to 64) whose
// cells meet it once the kd-tree has cut them across into rows, taken only where that count
// is well under the power of two the halvings give the neediest rows (kRowColumnsShare): the
// need of such columns differs from row to row (a torus's columns near its axis need fewer
// than at its rim), and the kd-tree's halvings follow that where equal columns cannot (bottle.brep
// at relative 1e-4: a torus with equal columns everywhere took 2,037 triangles instead of 1,758,
// and the cylinder sharing its circle 434 instead of 282). Faces that share an edge along the axis
// take the largest of their needs (ModelTessellator), so that their kd-trees cut it on the same
// lines.
std::vector<int> evenColumnNeeds(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids,
                                 int axis, double target, ErrorMode mode, bool flatCellsByDistance,
                                 bool cutAcross);

}  // namespace nurbslod
