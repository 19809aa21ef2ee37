#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/BezierPatch.hpp"
#include "tessellate/ErrorBudget.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "trim/CurveOnSurface.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

class BezierPatchGrid;

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

// The most spans across an axis over which its columns are cut across into rows
// (evenColumnLines); beyond, the kd-tree's halvings.
inline constexpr std::size_t kMostSpansCutAcross = 16;

// An edge of a face that runs along a kd-tree axis of it (an iso-line: a cylinder's circle),
// which ModelTessellator discretises on that face's column lines: its curves on all its faces
// (`own` the one on this face) and its chords' share. Graded columns are each as wide as the
// surface's share allows, and such an edge's chord over one may need more than its own share
// (a plane's trimming share where a cylinder's circle bounds it): the edge then halves the
// column, and the kd-tree cuts the cells through the new points. So each graded column must
// leave these edges one chord too (without, the box less a cylinder of
// tests/bench/generated_shapes.py took 268 triangles at relative 1e-3 instead of 160).
struct ChordsAlong {
    std::vector<CurveOnSurface> uses;
    std::size_t own = 0;
    double approximation = 0;
};

// Whether columns of a face along `axis` settle: each cell [x0, x1] (frame steps along the
// axis) over each span across meets `target` (the face's surface share), bounded as a cell
// filled to its sides, as the kd-tree bounds it.
class ColumnTest {
public:
    // patches: the face's Bezier patches where the caller has them (FaceSurfaceCache), otherwise
    // made here
    ColumnTest(const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids, int axis,
               double target, ErrorMode mode, bool flatCellsByDistance,
               std::vector<ChordsAlong> chords = {},
               std::shared_ptr<const BezierPatchGrid> patches = nullptr);
    ~ColumnTest();
    // as whole cells
    bool settles(std::int64_t x0, std::int64_t x1) const;
    // The rows the kd-tree cuts the column [x0, x1] into across, over every span across, where
    // each settles: it cuts a cell across on the other axis's even lines while the cell holds
    // two of them or more (the grid's columns, as set when the test was made), then halves it
    // while its bound says so, at most kRowDepth times; -1 where a row does not.
    int rowCount(std::int64_t x0, std::int64_t x1) const;
    // the bound of the first span across over the whole interval [a, b], over the target
    double wholeRatio(std::int64_t a, std::int64_t b) const;
    // whether each edge along the axis is one chord over the column [x0, x1] where it runs
    bool chordsSettle(std::int64_t x0, std::int64_t x1) const;
    bool columnAndChordsSettle(std::int64_t x0, std::int64_t x1) const {
        return settles(x0, x1) && chordsSettle(x0, x1);
    }
    // Graded columns over [a, b]: from a, each column the widest that settles as whole cells
    // (to 1/4096 of the interval), the lines from a to b; none where that takes more than
    // `most` columns. Greedy is fewest for a test that holds for every column within one that
    // holds (the bound falls as a cell narrows): a surface of revolution whose arcs run
    // unevenly in their parameter, or a B-spline's span that bends more at one end, takes
    // wide columns where it can.
    std::vector<std::int64_t> gradedLines(std::int64_t a, std::int64_t b, int most) const;
    // About how many graded columns [a, b] takes, from the widest column that settles around
    // each of four places spread over it (found to 1/16 of k equal columns' width, within 1/2
    // to 2 times it): the search above costs several tests per column, this one about 25, and
    // it tells where the need is too even along the span for graded columns to save one (a
    // cylinder whose circles' chords set its columns: bug3883_xr2-ct-214_bolt.stp at relative
    // 1e-4 took 16% more instructions searching them, 2.5% with the estimate first).
    // Infinity, after one test a place, where it cannot reach `enough`.
    double gradedCountEstimate(std::int64_t a, std::int64_t b, int k, double enough) const;

private:
    struct Verdict;
    BezierPatch cellPiece(double c0, double c1, double o0, double o1) const;
    Verdict cellVerdict(double c0, double c1, double o0, double o1) const;
    int rowsOf(double c0, double c1, std::int64_t y0, std::int64_t y1, int depth) const;
    // the greedy columns, none where more than `most`
    std::vector<std::int64_t> greedyLines(std::int64_t a, std::int64_t b, int most) const;

    KdTreeGrid grid_, other_;  // copies: a test outlives the grids it was made with
    std::vector<std::int64_t> across_;
    std::shared_ptr<const BezierPatchGrid> patches_;
    int axis_;
    double target_;
    ErrorMode mode_;
    bool flatCellsByDistance_;
    std::vector<ChordsAlong> chords_;
    mutable std::vector<std::vector<CurvePoints>> chordPoints_;  // per edge, its uses' points
};

// Per interval of `axis` (KdTreeGrid::intervals): the column lines (KdTreeGrid::setColumnLines)
// of the fewest columns whose cells, over each whole span of the other axis, meet `target` (the
// face's surface share, bounded as cells filled to their sides); on a face whose region is its
// whole box, and `graded`, graded ones (ColumnTest::gradedLines, each leaving the edges `chords`
// one chord) where they are fewer than equal ones. The interval's two borders where it needs no
// cut; none where no count up to 256 does. Where a column would need cuts across it too, and
// `cutAcross`, the fewest equal ones (up to 64; 128 over one span across) whose cells meet it once
// the kd-tree has cut them across into rows, taken only where that count is well under the power
// of two the halvings give the neediest rows (kRowColumnsShare): the need of such columns differs
// from row to row (a torus's columns near its axis need fewer than at its rim), and the kd-tree's
// halvings follow that where equal columns cannot (bottle.brep at relative 1e-4: a torus with equal
// columns everywhere took 2,037 triangles instead of 1,758, and the cylinder sharing its circle 434
// instead of 282). Faces that share an edge along the axis take lines that settle on each of them
// (ModelTessellator), so that their kd-trees cut it on the same lines.
std::vector<std::vector<std::int64_t>> evenColumnLines(
    const TrimmedSurface& face, const std::array<KdTreeGrid, 2>& grids, int axis, double target,
    ErrorMode mode, bool flatCellsByDistance, bool cutAcross, bool graded = true,
    std::vector<ChordsAlong> chords = {}, std::shared_ptr<const BezierPatchGrid> patches = nullptr);

}  // namespace nurbslod
