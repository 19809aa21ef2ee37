#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <polyclipping/clipper.hpp>
#include <stdexcept>
#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CylinderDevelopment.hpp"
#include "tessellate/ErrorBudget.hpp"
#include "tessellate/FaceBoundary.hpp"
#include "tessellate/FaceMesh.hpp"
#include "tessellate/FlatFace.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {

// Thrown when a face's trimming loops enclose no area that the integer grid can resolve.
struct FaceWithoutArea : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// How FaceTessellator's kd-tree cuts and bounds its cells.
struct CellChoices {
    // TessellationOptions' choices of the same names
    bool splitThroughBoundaryPoints = true;
    bool flatCellsByDistance = true;
    bool middleSplits = true;
    bool openPointsSpendCellSlack = true;
    bool openPointsBoundedBySurface = true;
    bool compact = false;
    // The face's free edges (model edge indices, sorted; guaranteed mode, and only where one of
    // the two choices below asks for their chords). A cell whose cut would leave a point on one
    // of their chords is cut the other way where that lowers its bound enough
    // (cutsAlongFreeChords).
    std::vector<int> freeEdges;
    // On a second tessellation, for a face whose free chords kept many points: its cells at
    // those chords take a smaller target (FaceTessellator::kFreeChordTarget; tessellateModel).
    bool finerCellsAtFreeChords = false;
    bool cutsAlongFreeChords = true;
    // A cell the region fills exactly (its boundary along the cell's sides) takes the bound
    // for corners on its sides. Not on a face with free edges: the points its cells leave
    // on their chords are dropped where the triangles change little
    // (removeOpenBoundaryPoints), and larger cells change them more (wing.brep at relative
    // 1e-4: 166 open edges instead of 98, BRepMesh 100). Unless those points go onto the
    // surface (freeEdgesOnSurface): then they stay, and the bound holds.
    bool filledCellsBySides = true;
    // Every chord of the face lies on its surface (ErrorBudget::forChordsOnSurface), free edges'
    // too (ModelTessellator: a free edge as its face's curve use): a point that a cell side cuts
    // on a chord no other face knows goes onto the surface at its (u, v), i.e. onto the curve,
    // not onto the chord, so that the cell's triangles keep the bound for corners on its sides.
    bool freeEdgesOnSurface = false;
    // The face's kd-tree lines with even columns (KdTreeGrid::setEvenColumns), as its edges were
    // discretised on them; used where their frame is this face's.
    std::optional<std::array<KdTreeGrid, 2>> evenColumns;

    bool operator==(const CellChoices&) const = default;
};

// Tessellates one trimmed face (paper sections 5.2 to 8): a kd-tree over the bounding box of
// the trimming polygon, each leaf cut by the trimmed region and triangulated.
//
// The (u, v) plane is mapped to integers (2^30 steps across the boundary's bounding box) so
// that the cutting (Clipper) is exact and every cell corner and split line is one integer.
//
// Two passes keep the mesh closed across edges: findCrossings() builds the kd-tree and returns
// the points where cell sides cut the boundary between its corners; once every face's
// crossings are added to the shared edge polylines (so both faces of an edge have them),
// triangulate() cuts and triangulates the leaves with the completed boundary.
class FaceTessellator {
public:
    // patches: the surface's Bezier patches where the caller has them (FaceSurfaceCache),
    // otherwise made here
    FaceTessellator(const TrimmedSurface& face, const ErrorBudget& budget, ErrorMode mode,
                    const CellChoices& choices = {},
                    std::shared_ptr<const BezierPatchGrid> patches = nullptr);
    ~FaceTessellator();

    // Throws std::runtime_error with the reason when the face cannot be tessellated.
    std::vector<BoundaryCrossing> findCrossings(const std::vector<BoundaryLoop>& loops);
    // sharedOffsets: how far each shared position may be off this face's surface (the share
    // budget it spends), so that the face's own points on open chords are dropped only where
    // the rest of that budget allows.
    FaceMesh triangulate(const std::vector<BoundaryLoop>& loops,
                         const std::vector<Point3>& sharedPositions,
                         const std::vector<double>& sharedOffsets);
    // Whether the face has its kd-tree: findCrossings builds it, but for a face in a plane or
    // on a cylinder whose loops need none; triangulate then builds it only where the completed
    // loops still need one, and changes nothing else. So a face that had its kd-tree after
    // findCrossings, or has none still, is as findCrossings left it, whatever was triangulated.
    bool hasKdTree() const { return !leaves_.empty(); }

private:
    // the kd-tree over the region (both orders of the even lines where that matters)
    void buildLeaves(const ClipperLib::Paths& region, bool simpleRegion);
    struct Leaf;
    struct Frame;
    void setFrame(const std::vector<BoundaryLoop>& loops);
    std::vector<std::vector<ClipperLib::IntPoint>> integerBoundary(
        const std::vector<BoundaryLoop>& loops) const;
    ClipperLib::Paths regionOf(const std::vector<BoundaryLoop>& loops) const;
    // oneSimpleRing: the region is one ring that visits no point twice (the one-pass clip's
    // case, simpleRingPiece)
    // decisions: what the bounds said of the cells, kept by one build for the next
    struct CellDecisions;
    void buildKdTree(const ClipperLib::Paths& region, bool oneSimpleRing, CellDecisions& decisions);
    // The bound of a cell across span borders (breaksX, breaksY inside it) as one cell
    // (cellErrorBoundAcrossSpans; cell = x0, y0, x1, y1 in frame steps), for the kd-tree, which
    // cuts it at its span borders where the bound is above `target`. Infinite where a quick test
    // already finds it above, or where the cell holds more than kMostSpansInCell spans.
    static constexpr std::size_t kMostSpansInCell = 1024;
    // How far a triangle with these corners (parameters, positions) may be from the surface,
    // both ways (triangleDeviation over its pieces in the spans, its corners on the surface's
    // domain; affineDeviation over the pieces of its box where the degrees are too high;
    // removeOpenBoundaryPoints, removeInteriorPoints). A value above `target` only tells that the
    // triangle is not within it: the search stops at the first surface point or piece beyond.
    // `sampleFirst` false skips the surface points (a caller that has sampled them already).
    double triangleBound(const std::array<Point2, 3>& uv, const std::array<Point3, 3>& position,
                         double target, bool sampleFirst = true) const;
    double boundAcrossSpans(const std::array<ClipperLib::cInt, 4>& cell,
                            const std::vector<ClipperLib::cInt>& breaksX,
                            const std::vector<ClipperLib::cInt>& breaksY, double target,
                            bool trimmedCell, double pieceFraction) const;
    // visit(leaf, piece, oneSimpleRing): the piece of the region that the leaf is cut from,
    // and whether it is known to be one simple ring
    void forEachLeaf(
        const ClipperLib::Paths& region, bool oneSimpleRing,
        const std::function<void(const Leaf&, const ClipperLib::Paths&, bool)>& visit) const;

    const TrimmedSurface& face_;
    ErrorBudget budget_;
    ErrorMode mode_;
    CellChoices choices_;
    std::shared_ptr<const BezierPatchGrid> patches_;
    std::optional<FacePlane> plane_;  // where the surface lies in a plane (triangulate)
    // where the surface is a cylinder (and not a plane): its face may be triangulated unrolled
    std::optional<CylinderFrame> cylinder_;
    // The triangles of a face in a plane or on a cylinder over its loops' points at `positions`
    // (FlatFace, CylinderDevelopment); none where it has neither, or they make no polygon there
    // within the bounds.
    std::optional<std::vector<std::array<std::uint32_t, 3>>> developedTriangles(
        const std::vector<std::vector<Point3>>& positions) const;
    // What a triangle of a face on a cylinder may spend (its unrolled bound)
    double unrolledShare() const;
    // The points a face on a cylinder needs on its boundary chords for its unrolled triangles to
    // keep the bound, as cuts of its edges; nothing where that takes `fewerThan` points or more,
    // or the loops do not unroll. `rings`: the loops' points on the surface; `first`: their
    // unrolled triangles.
    std::optional<std::vector<BoundaryCrossing>> unrolledCrossings(
        const std::vector<BoundaryLoop>& loops, const std::vector<std::vector<Point3>>& rings,
        const UnrolledTriangles& first, std::size_t fewerThan) const;
    // A cell of a face with free edges that touches one of their chords is bounded to this
    // share of the surface share: the points its sides leave on the chord are then dropped
    // more often, as its triangles leave the rest to that removal (Leaf::slack).
    static constexpr double kFreeChordTarget = 0.5;
    // A cut along a free chord instead of across it must leave halves bounded to this share of
    // the cell's bound (buildKdTree).
    static constexpr double kAlongFreeChordGain = 0.75;
    // The chords of the face's free edges in the frame (setFreeChords), and whether a cell
    // (x0, y0, x1, y1) meets one of them (a cell of no width: a segment).
    std::vector<std::array<ClipperLib::IntPoint, 2>> freeChords_;
    void setFreeChords(const std::vector<BoundaryLoop>& loops);
    bool touchesFreeChord(const std::array<ClipperLib::cInt, 4>& cell) const;
    std::unique_ptr<Frame> frame_;
    std::vector<Leaf> leaves_;
    bool toleranceReached_ = true;
    bool evenLinesFirst_ = false;
    bool evenOrderMatters_ = false;
};

}  // namespace nurbslod
