#pragma once

#include <cstddef>
#include <functional>

namespace nurbslod {

enum class ErrorMode {
    Guaranteed,   // conservative bound: the mesh never deviates more than the tolerance
    Approximate,  // the paper's approximate error (section 5.2): fewer triangles
};

struct TessellationOptions {
    double tolerance = 0;  // absolute, in model units; > 0
    ErrorMode mode = ErrorMode::Guaranteed;
    int threads = 0;  // 0: all cores
    // Split a kd-tree cell that the boundary crosses through a boundary point near the middle
    // rather than at the middle, so that the split line cuts no new point into the boundary
    // there, and a cell across an edge that runs along an iso-line through one of that edge's
    // points (FaceTessellator). The display's levels keep the plain halving, on which their
    // normal bound near sloppy poles was checked.
    bool splitThroughBoundaryPoints = true;
    // A face with a free edge gives surface share to its chords (ErrorBudget::withFreeEdges):
    // fewer open edges along the model's own boundary. The display tessellates each face alone,
    // where every edge looks free and none is an open edge anyone counts: it keeps the split.
    bool freeEdgesTakeSurfaceShare = true;
    // A lone face (every edge and vertex its own, one free edge at least) whose region is its
    // whole frame box is tessellated a second time with its free edges' chords on its surface,
    // and the result with fewer open edges kept (tessellateModel). Off only to measure.
    bool retryLoneFaces = true;
    // Bound a full kd-tree cell whose corners make a flat quadrilateral by its distance to the
    // surface (CellErrorBound::planarTwist), not at equal parameters: fewer triangles for the
    // same distance, most on surfaces of revolution. The display keeps the bound at equal
    // parameters: the error of its interpolated normals, measured at equal parameters
    // (InterpolatedNormalError), falls with the tolerance only under that bound.
    bool flatCellsByDistance = true;
    // A face whose edges' faces meet closer than the fixed share gap spends only what they need
    // on it and gives the rest to its surface and chords (ErrorBudget::withNarrowerShareGap).
    // Off only to measure what that saves.
    bool narrowShareGaps = true;
    // A face whose region is its whole frame box cuts its spans into the fewest equal columns
    // that meet the bound, not into a power of two (evenColumnLines). Off only to measure.
    bool evenColumns = true;
    // Such a face's columns graded, each as wide as its place allows, where they are fewer
    // than equal ones (ColumnTest::gradedLines). Off only to measure.
    bool gradedColumns = true;
    // Even columns also where the kd-tree cuts the columns across into rows (a sphere, a torus,
    // a freeform patch; evenColumnLines). The display and the analysis overlays keep their
    // halvings there: they interpolate normals, whose bound was measured on halvings (a
    // sphere's spread pole went 1.09 degrees over its 1-degree bound with these columns, and
    // a G2 joint's zebra stripes kinked by 11.7 degrees).
    bool evenColumnsCutAcross = true;
    // The kd-tree halves a cell in the middle of the direction its bound gives
    // (splitDirectionOfNet). Off, it cuts through the net point farthest from the bilinear
    // patch (the paper's Fig. 3), as the display and the analysis overlays do: their normal
    // bounds were measured on those cuts, and with middle halvings a G2 joint's zebra stripes
    // kinked by 13.2 degrees (6.8 before; the overlay test allows 10).
    bool middleSplits = true;
    // The points that cell sides leave on an open boundary's chords are dropped where the new
    // triangles stay within the face's bound, which counts what each old triangle's cell left
    // of the surface share (Leaf::slack in FaceTessellator, removeOpenBoundaryPoints). Off, only
    // the share gap and openChords: to measure what the slack saves.
    bool openPointsSpendCellSlack = true;
    // Where the new triangles change the old ones by more than that allows, they may be
    // bounded against the surface itself instead (FaceTessellator::triangleBound), guaranteed
    // mode only: fewer points left on free chords (OpenCASCADE's shell1.brep at relative 1e-3:
    // 50 -> 48 open edges, BRepMesh 49; 1,276 -> 1,214 triangles). The display and the analysis
    // overlays keep the plain removal: the larger triangles are within the distance, not within
    // their normal bound (the display's sample model at 2 px took 13,361 triangles with its
    // 1-degree bound instead of 7,926).
    bool openPointsBoundedBySurface = true;
    // Guaranteed mode: after the kd-tree, the face's own inner points are removed wherever every
    // triangle that replaces a point's fan is bounded against the surface within the whole
    // tolerance less the boundary's shares (removeInteriorPoints): the same guarantee with fewer
    // triangles, for more time (over the corpus, the samples and the generated shapes: 0.92x the
    // triangles, 1.8x the tessellation time). Off by default: the time is over BRepMesh's on
    // more models. The command line's --compact, the module's compact=True.
    bool compact = false;
    // A model whose free chords keep many of those points is tessellated again with finer cells
    // at them, and kept where that drops a larger share of its open edges than it adds of
    // triangles (tessellateModel). Off only to measure.
    bool refineAtFreeChords = true;
    // A kd-tree cell whose middle cut would leave a point on a free edge's chord is cut the
    // other way where that lowers its bound nearly as much (FaceTessellator). Off only to
    // measure.
    bool cutsAlongFreeChords = true;
    // That second tessellation takes from the first the work that no refined face changes: the
    // even columns, the edges' chords, and each other face's kd-tree and triangles, wherever
    // their inputs are the same (FirstTessellationMemo in tessellateModel). Off only to
    // measure, and to test that the mesh is the same.
    bool reuseFirstTessellation = true;
    // Keep each face's vertex set (TessellationResult::faceVertices): for benchmarks and tests
    // of the vertex evaluation.
    bool keepFaceVertices = false;
    // Called from worker threads as faces finish: (faces done, faces in all).
    std::function<void(std::size_t, std::size_t)> progress;
};

}  // namespace nurbslod
