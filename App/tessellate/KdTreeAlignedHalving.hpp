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

// A face's kd-tree lines along each axis (u, then v) as far as they are known before its
// edges are discretised. FaceTessellator frames the box of the boundary points; along an axis
// where every trimming curve lies within the box of the curves' end points (its control points
// do: cylinders, cones, the bands between two helices), that box is it, whatever the points in
// between. None along an axis where a curve may bulge past it: the frame then waits for the
// points. A sloppy band's side that wanders a hair past its iso-line leaves the other axis
// known (bottle.brep's thread flanks: their columns are known, their rows are not).
struct FaceKdTreeLines {
    std::array<std::optional<KdTreeGrid>, 2> axes;
    // the box of the curves' end points, per axis (0 where unknown)
    std::array<double, 2> extent{0, 0};

    // Along an axis that is not known because a curve bulges past the ends' box by more than
    // kNarrowBand of it, a grid framed on the box of the curves' control points, which holds
    // the trimmed region. The even columns along the other, known axis are tested over this
    // one's spans within it (forColumns): the smaller of two crossed cylinders, whose circle
    // gives its columns' frame while the curve where the larger meets it bulges past its ends
    // (tests/bench/generated_shapes.py: 632 -> 560 triangles at relative 1e-3, its end discs
    // 46 -> 28 each; BRepMesh_IncrementalMesh 416, its discs 29).
    std::array<std::optional<KdTreeGrid>, 2> hull;

    bool operator==(const FaceKdTreeLines&) const = default;

    // both axes, as FaceTessellator's even columns need them
    std::optional<std::array<KdTreeGrid, 2>> both() const;
    // Both axes where known, otherwise the hull's grid in place of the one that is not (only
    // the known axis can take columns: the other's frame waits for the boundary's points); none
    // where neither is known.
    std::optional<std::array<KdTreeGrid, 2>> forColumns() const;
};
FaceKdTreeLines kdTreeLinesBeforeDiscretisation(const TrimmedSurface& face);

// Which curves that are not straight in (u, v) take a face's lines along an axis they run one
// way along (their control points in order: by variation diminishing no line across meets
// them twice):
//  - narrowBand: those within a band across the axis of at most kNarrowBand of the face's
//    extent there: a sloppy band's side, a hair off its iso-line, which the face's columns cut
//    as they cut the iso-line (bottle.brep's thread flanks, whose long sides wander 0.8% of the
//    flank's width);
//  - onRuledSurface: also those of any width on a surface straight across the axis (degree 1
//    there, bent along it), whose kd-tree cuts only along the bent axis for error, as for a
//    straight curve across it (a sloppy helix on a cylinder).
// Narrow bands first: a band's two long sides then share its columns, which the other face of
// a side would otherwise take (bottle.brep's helices, on the thread's flanks and on the
// cylinder they wind around).
enum class BentCurves { narrowBand, onRuledSurface };
inline constexpr double kNarrowBand = 0.125;
// The axis `curve` runs along under `rule`, -1: none.
int axisAlong(const CurveOnSurface& curve, const std::array<double, 2>& faceExtent,
              BentCurves rule);

// Discretises an edge (discretizeEdge) with its pieces halved on kd-tree lines of the face of
// uses[use]: at the coarsest line crossing the middle half of a piece, along the axis the
// kd-tree cuts that curve on. The points then fall where that face's kd-tree cuts, and its
// cells add none between them. The axis is the one varying along an iso-parameter line, or the
// bent one across a straight curve on a surface straight the other way (a helix on a
// cylinder: u), or the one a bent curve runs along (axisAlong, under `rule`).
// Without `lines` (a face whose frame waits for its points) the lines are those of a kd-tree
// over the curve's own range, for an iso-parameter line: that at least puts a face's curves of
// one range (a cylinder's two circles) on one grid. None where no axis is clear (a diagonal on
// a plane, whose kd-tree does not cut for error) or its lines are not known.
std::optional<std::vector<double>> discretizeEdgeOnKdTreeLines(
    const std::vector<CurveOnSurface>& uses, std::size_t use, const FaceKdTreeLines* lines,
    double approximation, double simplification, std::vector<CurvePoints>* points = nullptr,
    BentCurves rule = BentCurves::narrowBand);

}  // namespace nurbslod
