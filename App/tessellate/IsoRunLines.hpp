#pragma once

#include <array>
#include <polyclipping/clipper.hpp>
#include <vector>

namespace nurbslod {

// The points of a face's boundary (integer polygons in the kd-tree's frame) that lie on its
// runs along an axis: the x values of its horizontal segments' ends and the y values of its
// vertical ones. Such a run is an edge along an iso-line of the face, and its points may be
// another face's: a torus fillet's circle that the cylinder beside it discretised on its own
// kd-tree lines, whose parameters never meet the torus's halvings. A line across the run
// through one of its points adds no point to it; a line anywhere else cuts the run's segment
// at a new point, which both faces of the edge then carry.
// How far from the middle `at` of a cell [lo, hi] a split may move to go through a point it
// adds nothing at: a quarter of the cell (FaceTessellator's throughBoundaryPoint and
// IsoRunLines::nearest).
inline ClipperLib::cInt splitThroughPointWindow(ClipperLib::cInt lo, ClipperLib::cInt hi) {
    return (hi - lo) / 4 + 1;
}

class IsoRunLines {
public:
    explicit IsoRunLines(const ClipperLib::Paths& region);

    // The line across `axis` (0: x = const, 1: y = const) through a run point strictly inside
    // (lo, hi) nearest `at`, within splitThroughPointWindow; `at` where there is none.
    ClipperLib::cInt nearest(int axis, ClipperLib::cInt lo, ClipperLib::cInt hi,
                             ClipperLib::cInt at) const;

private:
    std::array<std::vector<ClipperLib::cInt>, 2> lines_;  // per axis, sorted, unique
};

}  // namespace nurbslod
