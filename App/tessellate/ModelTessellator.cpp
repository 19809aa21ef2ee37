#include "tessellate/ModelTessellator.hpp"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include "tessellate/BoundaryFan.hpp"
#include "tessellate/ErrorBudget.hpp"
#include "tessellate/EvenColumns.hpp"
#include "tessellate/FaceSurfaceCache.hpp"
#include "tessellate/FaceSurfaceNeed.hpp"
#include "tessellate/FaceTessellator.hpp"
#include "tessellate/FoldedPairs.hpp"
#include "tessellate/KdTreeAlignedHalving.hpp"
#include "tessellate/LargestAngleFirst.hpp"
#include "tessellate/LoneFaces.hpp"
#include "tessellate/NeedleSplit.hpp"
#include "tessellate/PointWeld.hpp"
#include "tessellate/SurfaceMeeting.hpp"
#include "tessellate/SurfaceProjection.hpp"
#include "trim/EdgeDiscretizer.hpp"

namespace nurbslod {

namespace {

// A grid's column lines, interval by interval, each after a -1 (an interval of halvings: the -1
// alone), onto `out`: a key for what the lines decide.
template <class Number>
void appendColumnLines(std::vector<Number>& out, const KdTreeGrid& grid) {
    const std::size_t intervals = grid.intervals().size() - 1;
    for (std::size_t i = 0; i < intervals; ++i) {
        out.push_back(Number(-1));
        for (const std::int64_t line : grid.columnLines(i)) out.push_back(Number(line));
    }
}

// An edge whose B-rep tolerance is below this fraction of the tolerance is exact for the
// budget: a point on one face's curve is on the other's within it (lost in the 0.05 slack).
constexpr double kExactEdge = 1e-3;

// One face's use of an edge: which face, loop and trimming curve.
struct EdgeUse {
    int face, loop, curve;
};

// An edge's shared polyline: parameters, and per use the (u, v) and vertex id of each point,
// plus the points that faces' cell sides added inside segments.
struct EdgePolyline {
    std::vector<double> params;
    std::vector<std::vector<Point2>> uv;               // [use][k]
    std::vector<std::vector<std::uint32_t>> vertices;  // [use][k]
    struct Inserted {
        double lambda;
        std::vector<std::uint32_t> vertices;  // per use
    };
    std::vector<std::vector<Inserted>> inserted;  // [segment]
};

Point3 centroid(const std::vector<Point3>& points) {
    Point3 c = Point3::Zero();
    for (const auto& p : points) c += p;
    return c / static_cast<double>(points.size());
}

double farthest(const std::vector<Point3>& points, const Point3& from) {
    double d = 0;
    for (const auto& p : points) d = std::max(d, (p - from).norm());
    return d;
}

double spread(const std::vector<Point3>& points) {
    double d = 0;
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j)
            d = std::max(d, (points[i] - points[j]).norm());
    return d;
}

// The even columns of a model's column groups (assignColumns in tessellateOnce) by what they
// depend on: the members' faces and axes, surface shares, frames and the chords along them. The
// second tessellation of a model (finer cells at its free chords) asks for the same columns as
// the first, and their search can be most of a B-spline face of many spans: the generated
// fitted surface (57 x 57 spans) at relative 1e-4 spent 0.16 s of each 0.18 s tessellation on
// it.
struct ColumnMemo {
    std::mutex mutex;
    std::map<std::vector<double>, std::vector<std::vector<std::int64_t>>> lines;
};

// Each face's kd-tree and the cuts of its cell sides with its boundary (step 3 of
// tessellateOnce) from a model's first tessellation, with what they depend on: the face's
// budget, cell choices and boundary loops; and its triangles (step 5), with their loops and
// the positions and offsets of the loops' points. The second tessellation refines a few faces
// at their free chords and asks the others for the same kd-trees and mostly the same triangles
// again, which are most of a tessellation: OpenCASCADE's bearing.iges at relative 1e-4 refines
// 3 faces of 213, and its second tessellation took as long as its first (0.32 s). A face whose
// inputs differ in any of those builds its kd-tree, or its triangles, anew.
struct FaceTreeMemo {
    struct Face {
        ErrorBudget budget;
        CellChoices choices;
        std::vector<BoundaryLoop> loops;
        std::vector<BoundaryCrossing> crossings;
        std::unique_ptr<FaceTessellator> tessellator;  // none: not kept
        bool kdTreeAfterCrossings = false;
        // the last triangulation (none where the face was fanned or failed)
        std::optional<FaceMesh> mesh;
        std::vector<BoundaryLoop> meshLoops;
        std::vector<Point3> meshPositions;  // of the loops' points, in order
        std::vector<double> meshOffsets;
    };
    std::vector<Face> faces;
};

// Each edge's chords (the parameters of step 1's discretisations) from a model's first
// tessellation, with what they depend on: the edge's chord and simplification shares, its
// curve use and the kd-tree lines of its faces. The second tessellation discretises every edge
// again the same way: bearing.iges at relative 1e-4 took 0.030 s of its 0.045 s before the
// kd-trees on that.
struct EdgeMemo {
    struct Discretisation {
        double approximation = 0, simplification = 0;
        int curveUse = -1;
        std::vector<FaceKdTreeLines> lines;  // by use
        std::vector<double> params;
    };
    std::vector<std::vector<Discretisation>> edges;  // by edge, as many as were asked
};

// What a model's first tessellation keeps for its second (tessellateModel), which refines a
// few faces at their free chords and asks for the rest as the first did.
struct FirstTessellationMemo {
    ColumnMemo columns;  // filled and taken by either
    EdgeMemo edges;
    FaceTreeMemo trees;
    bool kept = false;  // filled by a tessellation, to be taken by the next one
};

// The loops' points' positions (or offsets) by shared vertex, in loop order.
template <typename T>
std::vector<T> ofLoopPoints(const std::vector<BoundaryLoop>& loops,
                            const std::vector<T>& byVertex) {
    std::vector<T> values;
    for (const auto& loop : loops)
        for (const auto& point : loop.points) values.push_back(byVertex[point.vertex]);
    return values;
}

// Where `loops` are the kept face's mesh loops but for the ids of their shared vertices (the
// same points, cuts and origins, at the same positions and offsets, the ids one to one), the
// kept mesh with its shared ids renamed to theirs; none otherwise. A tessellation numbers the
// points that cell sides cut on shared chords in the order of the edges, so a face whose
// boundary is unchanged can see other ids for its points where another face cut more.
std::optional<FaceMesh> keptMeshRenamed(const FaceTreeMemo::Face& kept,
                                        const std::vector<BoundaryLoop>& loops,
                                        const std::vector<Point3>& positions,
                                        const std::vector<double>& offsets) {
    if (!kept.mesh || loops.size() != kept.meshLoops.size()) return std::nullopt;
    std::unordered_map<std::uint32_t, std::uint32_t> renamed, back;
    std::size_t k = 0;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const BoundaryLoop& now = loops[l];
        const BoundaryLoop& then = kept.meshLoops[l];
        if (now.points.size() != then.points.size() || now.origins != then.origins)
            return std::nullopt;
        for (std::size_t i = 0; i < now.points.size(); ++i, ++k) {
            const BoundaryPoint& a = now.points[i];
            const BoundaryPoint& b = then.points[i];
            if (a.uv != b.uv || a.exact != b.exact || a.x != b.x || a.y != b.y ||
                positions[a.vertex] != kept.meshPositions[k] ||
                offsets[a.vertex] != kept.meshOffsets[k])
                return std::nullopt;
            const auto [to, newName] = renamed.emplace(b.vertex, a.vertex);
            const auto [from, newBack] = back.emplace(a.vertex, b.vertex);
            if (to->second != a.vertex || from->second != b.vertex) return std::nullopt;
        }
    }
    FaceMesh mesh = *kept.mesh;
    for (auto& vertex : mesh.vertices)
        if (vertex.shared) {
            const auto name = renamed.find(vertex.sharedId);
            if (name == renamed.end()) return std::nullopt;
            vertex.sharedId = name->second;
        }
    return mesh;
}

// Why a face meshed without a failure has no triangle after the weld and the folds went.
constexpr const char* kNoTriangleLeft =
    "no triangle left: its boundary encloses no area on its surface";

// One tessellation of the model (tessellateModel). freeEdgesAsCurveUses: a free edge may be its
// face's curve use (see boxRegion below); tessellateModel asks for it on lone faces only, with
// openEdgeLimit the open edges of the face's first mesh (0: none). refineFreeChords (by face,
// empty: none): the face's cells at its free edges' chords take a smaller target
// (CellChoices::freeEdges). freeSegments, where given, gets the number of each face's free
// edges' segments. The memo, where given, keeps work for the model's next tessellation, or
// gives the kept work of its last one.
TessellationResult tessellateOnce(const Model& model, const TessellationOptions& options,
                                  bool freeEdgesAsCurveUses, std::size_t openEdgeLimit = 0,
                                  const std::vector<char>& refineFreeChords = {},
                                  std::vector<std::size_t>* freeSegments = nullptr,
                                  FirstTessellationMemo* memo = nullptr,
                                  const FaceSurfaceCache* surfaces = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<FaceSurfaceCache> ownSurfaces;
    const FaceSurfaceCache& surfaceCache = surfaces ? *surfaces : ownSurfaces.emplace(model);
    std::unique_ptr<tbb::global_control> threads;
    if (options.threads > 1)
        threads = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, options.threads);
    // With one thread the loops run in order on the calling thread, without oneTBB: its
    // global_control and its first parallel_for in a process start its scheduler, about 0.6 ms
    // together, a quarter of a small model's tessellation (bug3883_xr2-ct-214_bolt.stp at
    // relative 1e-3 took 2.5 ms). Each loop's iterations write only their own results, so the
    // order does not change them.
    const bool oneThread = options.threads == 1;
    auto forEachIndex = [oneThread](auto first, auto last, const auto& body) {
        if (oneThread)
            for (auto i = first; i < last; ++i) body(i);
        else
            tbb::parallel_for(first, last, body);
    };
    // the fixed split: the share gap, and the surface share a face needing more is held to
    const ErrorBudget budget = ErrorBudget::of(options.tolerance, options.mode);
    const int faceCount = static_cast<int>(model.faces.size());

    TessellationResult result;
    result.faces = faceCount;
    result.tolerance = options.tolerance;
    std::vector<std::string> failure(faceCount);

    // faces that can take part: imported, valid surface and trimming curves
    for (int f = 0; f < faceCount; ++f) {
        const auto& face = model.faces[f];
        if (!face.error.empty()) {
            failure[f] = face.error;
            continue;
        }
        if (auto p = face.surface.problem()) {
            failure[f] = "invalid surface: " + *p;
            continue;
        }
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves)
                if (auto p = curve.pcurve.problem(); p && failure[f].empty())
                    failure[f] = *p;
                else if (failure[f].empty() &&
                         (curve.edge < 0 || curve.edge >= int(model.edges.size())))
                    failure[f] = "a trimming curve names no edge of the model";
    }

    // edges and their uses
    std::vector<std::vector<EdgeUse>> uses(model.edges.size());
    for (int f = 0; f < faceCount; ++f) {
        if (!failure[f].empty()) continue;
        const auto& face = model.faces[f];
        for (int l = 0; l < int(face.loops.size()); ++l)
            for (int c = 0; c < int(face.loops[l].curves.size()); ++c)
                uses[face.loops[l].curves[c].edge].push_back({f, l, c});
    }
    // where each use sits in its edge's list of uses
    std::map<std::tuple<int, int, int>, int> useIndex;
    for (size_t e = 0; e < uses.size(); ++e)
        for (size_t u = 0; u < uses[e].size(); ++u)
            useIndex[{uses[e][u].face, uses[e][u].loop, uses[e][u].curve}] = static_cast<int>(u);
    // an edge of one face alone (not a pole)
    auto isFreeEdge = [&](std::size_t e) {
        return uses[e].size() == 1 && !model.edges[e].degenerated;
    };
    // only a model with a free edge is tessellated a second time (tessellateModel): the others
    // neither key nor keep their columns
    bool anyFreeEdge = false;
    for (size_t e = 0; e < uses.size() && !anyFreeEdge; ++e) anyFreeEdge = isFreeEdge(e);
    if (!anyFreeEdge) memo = nullptr;
    // which the memo fills, which it gives
    const bool keep = memo && !memo->kept, take = memo && memo->kept;
    ColumnMemo* const columnMemo = memo ? &memo->columns : nullptr;
    FaceTreeMemo* const treeMemo = memo ? &memo->trees : nullptr;

    auto curveOf = [&](const EdgeUse& u) -> const TrimCurve& {
        return model.faces[u.face].loops[u.loop].curves[u.curve];
    };
    auto curveOnSurface = [&](const EdgeUse& u) {
        const TrimCurve& c = curveOf(u);
        return CurveOnSurface(model.faces[u.face].surface, c.pcurve, c.first, c.last);
    };

    // A point that a sloppy edge's faces share (see shareVertices below): each face takes its
    // foot's (u, v), so the shared vertex is at most the edge's half share gap off each surface
    // (the share budget), and the face's boundary moves inside its surface by no more than the
    // edge's own tolerance (how far the B-rep itself places the edge, which meshjudge and the
    // verifier allow at a face's boundary).
    struct CommonPoint {
        Point3 point;
        std::vector<Point2> uv;  // per use
        double offset = 0;       // the largest distance to a foot
    };
    // The first iterate within halfGap of every surface, else the nearest one found (offset
    // infinite if none stays within reach): with halfGap 0 it measures how far apart the
    // faces are there.
    auto commonPointOf = [&](std::size_t e, const std::vector<Point3>& own,
                             const std::vector<Point2>& start, double halfGap, double reach) {
        const std::size_t useCount = uses[e].size();
        CommonPoint best{Point3::Zero(), {}, std::numeric_limits<double>::infinity()};
        CommonPoint common{centroid(own), std::vector<Point2>(useCount)};
        std::vector<Point3> feet(useCount);
        for (int iteration = 0; iteration < 8; ++iteration) {
            bool near = true;
            common.offset = 0;
            for (std::size_t u = 0; u < useCount; ++u) {
                const SurfaceFoot foot = projectOntoSurface(model.faces[uses[e][u].face].surface,
                                                            common.point, start[u]);
                common.uv[u] = foot.uv;
                feet[u] = foot.point;
                common.offset = std::max(common.offset, (foot.point - common.point).norm());
                near &= (foot.point - own[u]).norm() <= reach;
            }
            if (near && common.offset < best.offset) best = common;
            if (near && common.offset <= halfGap) return common;
            common.point = centroid(feet);
        }
        return best;
    };

    // The points a shared point is held near, at the edge's normalized parameter s: each face's
    // own point, or the file's where the importer straightened the curve
    // (TrimCurve::beforeStraightening), so that the boundary stays within the edge's tolerance of
    // where the B-rep puts it.
    auto anchorsOf = [&](std::size_t e, double s, std::vector<Point3> own) {
        for (std::size_t u = 0; u < uses[e].size(); ++u) {
            const TrimCurve& c = curveOf(uses[e][u]);
            if (!c.beforeStraightening) continue;
            const Point2 uv = c.beforeStraightening->point(c.first + s * (c.last - c.first));
            own[u] = model.faces[uses[e][u].face].surface.point(uv.x(), uv.y());
        }
        return own;
    };

    // Where the surfaces meet (SurfaceMeeting: Newton steps onto their tangent planes) if that
    // is within halfGap of every surface and within the edge's tolerance of each face's own
    // point; else the averaged projections of commonPointOf, held within the edge's tolerance
    // and within the curves' spread plus `gap` of the own points (a broken file may give an
    // edge a tolerance of kilometres). Where the Newton steps end farther off (faces that run
    // side by side end them midway between the faces), the projections still find some points:
    // bug33398.step's edge 762 (faces 0.68 T apart) leaves 6 more open edges at relative 1e-4
    // without them.
    auto nearestCommonPoint = [&](std::size_t e, const std::vector<Point3>& own,
                                  const std::vector<Point2>& start, double halfGap, double gap) {
        const std::size_t useCount = uses[e].size();
        std::vector<const BSplineSurface*> surfaces(useCount);
        for (std::size_t u = 0; u < useCount; ++u)
            surfaces[u] = &model.faces[uses[e][u].face].surface;
        const double tolerance = model.edges[e].tolerance;
        const SurfaceMeeting meeting = findSurfaceMeeting(surfaces, centroid(own), start);
        bool near = meeting.offset <= halfGap;
        for (std::size_t u = 0; u < useCount; ++u)
            near &= (meeting.feet[u] - own[u]).norm() <= tolerance;
        if (near) return CommonPoint{meeting.point, meeting.uv, meeting.offset};
        return commonPointOf(e, own, start, halfGap, std::min(tolerance, spread(own) + gap));
    };

    // each face's share of the tolerance: what its surface does not need goes to its trimming
    // curves (ErrorBudget::forFace)
    std::vector<ErrorBudget> faceBudgets(faceCount, budget);
    forEachIndex(0, faceCount, [&](int f) {
        if (!failure[f].empty()) return;
        try {
            faceBudgets[f] =
                ErrorBudget::forFace(options.tolerance, options.mode,
                                     surfaceCache.surfaceNeed(f, options.mode, budget.surface));
        } catch (const std::exception&) {
            // the kd-tree reports what is wrong with the face; until then the fixed split
        }
    });

    // Which B-rep vertex sits at which end of the edge's parameter range is read from the
    // geometry: the importer's notion of first and last follows orientation flags that sloppy
    // files do not always keep.
    std::vector<std::pair<int, int>> endVertices(model.edges.size());
    for (size_t e = 0; e < model.edges.size(); ++e) {
        const ModelEdge& edge = model.edges[e];
        endVertices[e] = {edge.firstVertex, edge.lastVertex};
        if (uses[e].empty() || edge.firstVertex < 0 || edge.lastVertex < 0) continue;
        const auto curve = curveOnSurface(uses[e].front());
        const Point3 start = curve.point(0.0), end = curve.point(1.0);
        const Point3& first = model.vertices[edge.firstVertex].point;
        const Point3& last = model.vertices[edge.lastVertex].point;
        if ((start - last).norm() + (end - first).norm() <
            (start - first).norm() + (end - last).norm())
            std::swap(endVertices[e].first, endVertices[e].second);
    }
    // Where a curve's end at B-rep vertex `vertex` (-1: none) goes, from (u, v) `uv` on the
    // face's surface: a sloppy file may stop a trimming curve short of its B-rep vertex (by up
    // to the vertex's tolerance) while the exact face reaches the vertex, so an end more than
    // 1e-3 T but at most twice the vertex's tolerance from it moves to the vertex's foot on the
    // surface (where that is nearer), and the faces that meet there end at nearly the same
    // point. `uv` is updated; returns the point.
    auto endAtVertex = [&](const BSplineSurface& surface, int vertex, Point2& uv) {
        const Point3 point = surface.point(uv.x(), uv.y());
        if (vertex < 0) return point;
        const ModelVertex& brepVertex = model.vertices[vertex];
        const double gap = (point - brepVertex.point).norm();
        if (!(gap > 1e-3 * options.tolerance) || gap > 2 * brepVertex.tolerance) return point;
        const SurfaceFoot foot = projectOntoSurface(surface, brepVertex.point, uv);
        if (!((foot.point - brepVertex.point).norm() < gap)) return point;
        // A foot a tenth of the domain away in (u, v) is a slide along a pole's row, not the
        // end moved onto its vertex: the chord from it would cut across the face.
        // shell1.brep of OpenCASCADE's samples: face 39's pole is its corner, and an edge's end
        // there slid from u = 1 to 0.5; the points later put on that edge's chord in (u, v)
        // lay inside the face, 0.33 off the next face (40 T at relative 1e-4).
        const auto& knotsU = surface.knotsU();
        const auto& knotsV = surface.knotsV();
        if (std::abs(foot.uv.x() - uv.x()) > 0.1 * (knotsU.last() - knotsU.first()) ||
            std::abs(foot.uv.y() - uv.y()) > 0.1 * (knotsV.last() - knotsV.first()))
            return point;
        uv = foot.uv;
        return foot.point;
    };
    // Per-edge share gap (ErrorBudget::withShareGap). Along each shared edge, the faces' gap is
    // measured as the vertices are placed below (commonPointOf) at evenly spaced parameters;
    // where it is over the fixed share gap and every face of the edge can give the difference
    // out of its other shares, the edge takes it, with a margin of 1.2 for the points between
    // the samples, and its faces spend that much. A point of the edge found farther off than
    // its gap still stays one per face (shareVertices): the guarantee never rests on the
    // samples.
    // The same samples, and the ends of the curves at each B-rep vertex, give every face the
    // gap its shared points need (narrowGap); where that is below the fixed share gap, the face
    // narrows its gap to it further down (ErrorBudget::withNarrowerShareGap).
    std::vector<double> edgeShareGap(model.edges.size(), budget.shareGap);
    std::vector<double> narrowGap(faceCount, 0);
    constexpr double margin = 1.2;
    const double largestGap = 2 * 0.95 * options.tolerance;
    // whether each face of edge e can give share gap `gap` out of its other shares
    auto everyFaceAffords = [&](size_t e, double gap) {
        for (const auto& u : uses[e])
            if (!(gap <= faceBudgets[u.face].largestShareGap(options.tolerance, options.mode)))
                return false;
        return true;
    };
    if (options.mode == ErrorMode::Guaranteed) {
        constexpr int samples = 32;
        std::vector<double> needed(model.edges.size(), 0), sharedNeed(model.edges.size(), 0);
        forEachIndex(size_t(0), model.edges.size(), [&](size_t e) {
            if (uses[e].size() < 2 || model.edges[e].degenerated) return;
            std::vector<CurveOnSurface> curves;
            for (const auto& u : uses[e]) curves.push_back(curveOnSurface(u));
            double farthestOffset = 0, nearestOffset = 0;
            std::vector<Point3> own(curves.size());
            std::vector<Point2> start(curves.size());
            for (int i = 1; i < samples && farthestOffset < largestGap; ++i) {
                const double s = double(i) / samples;
                for (size_t k = 0; k < curves.size(); ++k) {
                    start[k] = curves[k].uv(s);
                    own[k] = curves[k].surface().point(start[k].x(), start[k].y());
                }
                if (spread(own) <= budget.shareGap) {  // shared as before, midway
                    nearestOffset = std::max(nearestOffset, farthest(own, centroid(own)));
                    continue;
                }
                // a point with no common point within reach stays one per face whatever the
                // gap; one where the surfaces meet within the fixed gap needs no more
                if (const double offset = nearestCommonPoint(e, anchorsOf(e, s, own), start,
                                                             0.5 * budget.shareGap, largestGap)
                                              .offset;
                    std::isfinite(offset))
                    farthestOffset = std::max(farthestOffset, offset);
            }
            needed[e] = 2 * margin * farthestOffset;
            sharedNeed[e] = 2 * margin * std::max(nearestOffset, farthestOffset);
        });
        std::vector<double> faceGap(faceCount, budget.shareGap);
        for (size_t e = 0; e < model.edges.size(); ++e) {
            if (!(needed[e] > budget.shareGap)) continue;
            if (!everyFaceAffords(e, needed[e])) continue;
            edgeShareGap[e] = needed[e];
            for (const auto& u : uses[e]) faceGap[u.face] = std::max(faceGap[u.face], needed[e]);
        }
        for (int f = 0; f < faceCount; ++f)
            faceBudgets[f] =
                faceBudgets[f].withShareGap(faceGap[f], options.tolerance, options.mode);

        // The gap each face's shared points need: its shared edges' samples, and the curves'
        // ends at its B-rep vertices where step 2 puts them (endAtVertex; with the margin too).
        // Measured at the curves' own ends, trj7_b1-ec-214.stp at relative 1e-4 narrowed faces
        // 229 and 284 to 0.0085 T where their feet at a vertex came out 0.028 T apart: one point
        // each, an open crack. At least 0.005 T: the edges' own points are checked against it
        // once they are placed (step 1a), and a floor of 0.02 T kept
        // bug3883_xr2-ct-214_bolt.stp's cylinders at relative 1e-3 one halving finer (308
        // triangles; 252 with this one).
        constexpr double kNarrowestGap = 0.005;
        std::fill(narrowGap.begin(), narrowGap.end(), kNarrowestGap * options.tolerance);
        std::map<int, std::vector<std::pair<int, Point3>>> ends;  // B-rep vertex: (face, point)
        for (size_t e = 0; e < model.edges.size(); ++e) {
            if (uses[e].size() >= 2 && !model.edges[e].degenerated)
                for (const auto& u : uses[e])
                    narrowGap[u.face] = std::max(narrowGap[u.face], sharedNeed[e]);
            for (const auto& u : uses[e]) {
                const CurveOnSurface curve = curveOnSurface(u);
                const BSplineSurface& surface = model.faces[u.face].surface;
                for (const auto& [vertex, s] :
                     {std::pair{endVertices[e].first, 0.0}, std::pair{endVertices[e].second, 1.0}})
                    if (vertex >= 0) {
                        Point2 uv = curve.uv(s);
                        ends[vertex].push_back({u.face, endAtVertex(surface, vertex, uv)});
                    }
            }
        }
        for (const auto& [vertex, list] : ends) {
            std::vector<Point3> points;
            for (const auto& [face, p] : list) points.push_back(p);
            const double need = 2 * margin * farthest(points, centroid(points));
            for (const auto& [face, p] : list) narrowGap[face] = std::max(narrowGap[face], need);
        }
    }
    // An edge's share gap is at most each of its faces' (every face's sum must hold): `gap`
    // held to the smallest of its faces' share gaps.
    auto holdEdgeGapToFaces = [&](size_t e, double gap) {
        for (const auto& u : uses[e]) gap = std::min(gap, faceBudgets[u.face].shareGap);
        edgeShareGap[e] = gap;
    };
    // a face's budget after a change of its other shares: its share gap kept where it can be,
    // and its edges' gaps held to what it keeps
    auto rebudget = [&](int f, const ErrorBudget& base) {
        faceBudgets[f] =
            base.withShareGap(faceBudgets[f].shareGap, options.tolerance, options.mode);
        const auto& face = model.faces[f];
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves)
                holdEdgeGapToFaces(curve.edge, edgeShareGap[curve.edge]);
    };

    // The use of an edge whose chords its face's cells bound (a curve straight in (u, v), see
    // CurveOnSurface::straightInParameterPlane): the points that cell sides add to the edge's
    // segments go onto that face's surface, i.e. onto the curve, so that its triangles are all
    // within its surface share. Its chords then do not limit the edge's share. At most one use
    // per edge: a point is on one surface's curve at the (u, v) it has there, not on two.
    // Only a shared edge (but see freeEdgesAsCurveUses below): a free one keeps the points cell
    // sides add on its chords; and not one with a widened share gap, whose shared points are off
    // every surface.
    // Where two faces of an edge that is not exact both have every curve straight, only one of
    // them can have all its chords on its surface (chordsOnSurface, below): the edge goes to
    // the face whose surface that saves more kd-tree cells (surfaceCellEstimate at its share
    // against the whole tolerance's), and a face that loses one of its edges gives up the
    // others, which then go to their other faces. The first straight use took them before
    // (at relative 1e-3: bottle.brep 3,756 -> 3,618 triangles, hammer.iges 1,762 -> 1,726).
    const auto exactEdge = [&](int e) {
        return model.edges[e].tolerance <= kExactEdge * options.tolerance;
    };
    // The kd-tree lines of each face whose frame is known before its edges are discretised
    // (KdTreeAlignedHalving; used below for the edges and the even columns).
    std::vector<FaceKdTreeLines> faceLines(faceCount);
    forEachIndex(0, faceCount, [&](int f) {
        if (failure[f].empty()) faceLines[f] = kdTreeLinesBeforeDiscretisation(model.faces[f]);
    });
    // With freeEdgesAsCurveUses, a free edge can be its face's curve use too, where the face's
    // region is its whole frame box (every curve straight along one of the box's sides: an open
    // cylinder's circles, a bent rectangle) and the edge is exact: the points that cell sides
    // add to its chords then go onto the surface, i.e. onto the curve (CellChoices::
    // freeEdgesOnSurface), and the face spends no trimming share (forChordsOnSurface). Those
    // points stay, where removeOpenBoundaryPoints drops the ones on a chord: fewer open edges
    // or more, as the face's columns fall along its free edges (tessellateModel keeps the
    // better of the two for a lone face).
    std::vector<char> boxRegion(faceCount, 0);
    if (options.mode == ErrorMode::Guaranteed)
        forEachIndex(0, faceCount, [&](int f) {
            const auto grids = faceLines[f].forColumns();
            boxRegion[f] = freeEdgesAsCurveUses && failure[f].empty() && faceLines[f].both() &&
                           grids && regionIsTheBox(model.faces[f], *grids);
        });
    std::vector<std::vector<char>> straightUse(model.edges.size());
    for (size_t e = 0; e < model.edges.size(); ++e)
        if ((uses[e].size() >= 2 && edgeShareGap[e] <= budget.shareGap) ||
            (isFreeEdge(e) && boxRegion[uses[e][0].face] && exactEdge(int(e))))
            for (const auto& use : uses[e])
                straightUse[e].push_back(curveOnSurface(use).straightInParameterPlane());
    auto curveStraight = [&](int f, int l, int c) {
        const int e = model.faces[f].loops[l].curves[c].edge;
        for (size_t k = 0; k < straightUse[e].size(); ++k)
            if (uses[e][k].face == f && uses[e][k].loop == l && uses[e][k].curve == c)
                return straightUse[e][k] != 0;
        return curveOnSurface({f, l, c}).straightInParameterPlane();
    };
    // whether `holds` holds for every curve of face f (a face with curves, not failed)
    auto everyCurve = [&](int f, const auto& holds) {
        if (!failure[f].empty() || model.faces[f].loops.empty()) return false;
        const auto& loops = model.faces[f].loops;
        for (int l = 0; l < int(loops.size()); ++l)
            for (int c = 0; c < int(loops[l].curves.size()); ++c)
                if (!holds(l, c)) return false;
        return true;
    };
    std::vector<char> candidate(faceCount, 0);
    if (options.mode == ErrorMode::Guaranteed)
        for (int f = 0; f < faceCount; ++f)
            candidate[f] = everyCurve(f, [&](int l, int c) { return curveStraight(f, l, c); });
    const double wholeSurface =
        ErrorBudget::forChordsOnSurface(options.tolerance, options.mode).surface;
    std::vector<double> savedCells(faceCount, std::numeric_limits<double>::quiet_NaN());
    auto saved = [&](int f) {
        if (std::isnan(savedCells[f]))
            savedCells[f] =
                surfaceCellEstimate(model.faces[f], options.mode, faceBudgets[f].surface,
                                    surfaceCache.patches(f).get()) -
                surfaceCellEstimate(model.faces[f], options.mode, wholeSurface,
                                    surfaceCache.patches(f).get());
        return savedCells[f];
    };
    std::vector<int> curveUse(model.edges.size(), -1);
    // the chord of face f's curve (l, c) lies on its surface: see chordsOnSurface below
    auto chordOnSurface = [&](int f, int l, int c) {
        const int e = model.faces[f].loops[l].curves[c].edge;
        const bool exact = exactEdge(e);
        return curveStraight(f, l, c) &&
               ((curveUse[e] >= 0 && (uses[e][curveUse[e]].face == f || exact)) ||
                (model.edges[e].degenerated && exact));
    };
    for (bool changed = true; changed;) {
        for (size_t e = 0; e < model.edges.size(); ++e) {
            int best = -1;
            for (size_t k = 0; k < straightUse[e].size(); ++k) {
                if (!straightUse[e][k]) continue;
                const int f = uses[e][k].face;
                if (best < 0 ||
                    (!exactEdge(int(e)) && candidate[f] &&
                     (!candidate[uses[e][best].face] || saved(f) > saved(uses[e][best].face))))
                    best = static_cast<int>(k);
            }
            curveUse[e] = best;
        }
        changed = false;
        for (int f = 0; f < faceCount; ++f)
            if (candidate[f] &&
                !everyCurve(f, [&](int l, int c) { return chordOnSurface(f, l, c); }))
                candidate[f] = 0, changed = true;
    }

    // A face has no trimming error at all (ErrorBudget::forChordsOnSurface) where every curve
    // of it is straight in (u, v) and the points added to it lie on its surface: it is its
    // edge's curve use, or the edge is exact and its curve use is another face's (a line
    // between two cylinders), or an exact pole (a sphere's or a cone's tip: every point added to
    // it is the pole itself). The larger cells there put hanging points on a meridian next to
    // the pole; FaceTessellator triangulates such a cell with the pole side collapsed
    // (triangulateCellAtPole), so that no triangle joins the pole to two points of one meridian
    // (flat in space, against the surface's normal).
    std::vector<char> chordsOnSurface(faceCount, 0);
    if (options.mode == ErrorMode::Guaranteed)
        for (int f = 0; f < faceCount; ++f) {
            if (!everyCurve(f, [&](int l, int c) { return chordOnSurface(f, l, c); })) continue;
            chordsOnSurface[f] = 1;
            faceBudgets[f] = ErrorBudget::forChordsOnSurface(options.tolerance, options.mode);
        }
    // A face with a free edge gives surface share to its chords and to dropping the points
    // cell sides leave on them (ErrorBudget::withFreeEdges): each segment of a free edge is an
    // open edge of the mesh. Not a face whose cells bound all its chords: it has no trimming.
    auto hasFreeEdge = [&](int f) {
        for (const auto& loop : model.faces[f].loops)
            for (const auto& curve : loop.curves)
                if (isFreeEdge(curve.edge)) return true;
        return false;
    };
    for (int f = 0; f < faceCount && options.freeEdgesTakeSurfaceShare; ++f) {
        if (!failure[f].empty() || chordsOnSurface[f]) continue;
        if (hasFreeEdge(f))
            faceBudgets[f] = faceBudgets[f].withFreeEdges(options.tolerance, options.mode);
    }
    // A face whose shared points all need less than its share gap narrows it to what they need
    // (ErrorBudget::withNarrowerShareGap) and its edges' gaps follow: a shared point found
    // farther off stays one per face. Not a face with a free edge: the removal of the points
    // that cell sides leave on its free chords spends its half gap too (withFreeEdges).
    // The budgets and edge gaps before narrowing are kept for the faces that take their gap
    // back in step 1a (an edge widened above the fixed gap keeps its width there).
    const std::vector<ErrorBudget> unnarrowed = faceBudgets;
    const std::vector<double> unnarrowedEdgeGap = edgeShareGap;
    if (options.mode == ErrorMode::Guaranteed && options.narrowShareGaps) {
        for (int f = 0; f < faceCount; ++f)
            if (failure[f].empty() && !hasFreeEdge(f))
                faceBudgets[f] = faceBudgets[f].withNarrowerShareGap(narrowGap[f], options.mode);
        for (size_t e = 0; e < model.edges.size(); ++e) holdEdgeGapToFaces(e, edgeShareGap[e]);
    }
    // The chords' share of an edge: the smallest of its faces' trimming shares (each face's
    // sum must hold), leaving out the faces whose cells bound all their chords and every use
    // whose cells bound this edge's chords (chordOnSurface): its curve use, and on an exact edge
    // any face it is straight in, whose chords in (u, v) the surface maps onto the curve as the
    // curve use's do, with every point on the curve (ErrorBudget). Such a face spends its
    // trimming share on its other curves only: a cylinder between torus fillets whose circles
    // are exact takes the chords the cells need, not the fillets' trimming share
    // (bug33398.step at relative 1e-4: 32,070 -> 31,562 triangles; one circle of its half
    // cylinder 116 went from 82 points to 49, BRepMesh's 20 keep 0.5 T).
    // The cells' points on such an edge are placed on the curve use's surface at the same
    // fraction of the chord (joinCuts); on an exact edge that is a point of the curve, as for
    // a face whose cells bound all its chords.
    auto edgeBudget = [&](size_t e, bool withCurveUse) {
        ErrorBudget edge = budget;
        // no face to limit it: the most any face's curves can take with the fixed share gap
        double trimming = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < uses[e].size(); ++k)
            if (!chordsOnSurface[uses[e][k].face] &&
                !(withCurveUse &&
                  chordOnSurface(uses[e][k].face, uses[e][k].loop, uses[e][k].curve)))
                trimming = std::min(trimming, faceBudgets[uses[e][k].face].trimming());
        if (!std::isfinite(trimming))
            trimming = ErrorBudget::largestTrimming(options.tolerance, options.mode);
        edge.setTrimming(trimming);
        return edge;
    };
    // The kd-tree lines of each face (faceLines, above). An edge halves its pieces on the lines of
    // one face it is straight in or runs along (BentCurves: narrow bands first): its curve use's if
    // it can, another's otherwise. The points of the edge then lie where that face's kd-tree cuts,
    // and its cells add no points between them. Where only one axis is known (a sloppy band's side
    // a hair past its iso-line), its lines still place the points of the curves that run along it
    // (faceLines): both long sides of bottle.brep's thread flanks then have their points on the
    // flank's columns, which cut their sides 347 times at relative 1e-4 instead of 731. The even
    // columns below are set on these lines too, so that edges follow them.
    // Even columns (evenColumnLines) where a face's region is its whole frame box, or most of it
    // (kEvenColumnsRegionShare). A face with a free edge bounds the cells at its boundary as
    // trimmed ones (CellChoices::filledCellsBySides), which then split within their columns:
    // in guaranteed mode it takes them too (wing.brep at relative 1e-3: 734 triangles instead
    // of 857, 36 open edges instead of 37); the approximate mode's estimate went past the
    // tolerance more with them (wing.brep at 1e-3: 1.09 T instead of 0.75 T), and keeps its
    // halvings there. Such a face takes no columns cut across into rows, whose rows are tested
    // as cells filled to their sides: the generated freeform patch at 1e-3 and 1e-4 took 1,654
    // and 11,374 triangles with them, 1,484 and 10,668 without (open edges 86 -> 84 and
    // 264 -> 266), the revolved profile 5,983 and 51,229, then 5,809 and 48,739 (55 and 169
    // both ways); no other model changed but the ruled face at 1e-4 (8,423 -> 8,385 triangles,
    // 287 -> 289 open edges).
    // An edge that runs along an axis of such a face and is straight in another face's (u, v)
    // is cut by that face's kd-tree too: the two axes take the same columns, the largest of
    // their needs, on the same frame, or neither takes any (bottle.brep's cylinders alone,
    // whose circles its tori share and cut on halvings of their own: 4,428 triangles at
    // relative 1e-3 became 4,676). The axes so tied make one group (union-find over
    // face * 2 + axis); its columns are chosen again where step 1a or 1b changes a member's
    // surface share.
    auto hasEvenColumns = [&](int f) {
        const auto& axes = faceLines[f].axes;
        return (axes[0] && axes[0]->hasEvenColumns()) || (axes[1] && axes[1]->hasEvenColumns());
    };
    std::vector<int> columnGroup(2 * static_cast<size_t>(faceCount));
    std::vector<char> columnsRuledOut(2 * static_cast<size_t>(faceCount));
    std::iota(columnGroup.begin(), columnGroup.end(), 0);
    auto groupOf = [&](int node) {
        while (columnGroup[node] != node) node = columnGroup[node] = columnGroup[columnGroup[node]];
        return node;
    };
    std::vector<char> columnCandidate(faceCount, 0);
    // A face with one axis known only takes columns along it in guaranteed mode: in the
    // approximate one the crossed cylinders at relative 1e-4 took 1,562 triangles with them
    // instead of 1,518, the sphere less a cylinder 36,708 instead of 36,016.
    forEachIndex(0, faceCount, [&](int f) {
        const auto grids = faceLines[f].forColumns();
        const bool oneAxis = !faceLines[f].both();
        columnCandidate[f] =
            options.evenColumns && failure[f].empty() && grids &&
            (!(hasFreeEdge(f) || oneAxis) || options.mode == ErrorMode::Guaranteed) &&
            (regionIsTheBox(model.faces[f], *grids) ||
             regionShareOfBox(model.faces[f], *grids) >= kEvenColumnsRegionShare);
    });
    // An axis whose frame waits for the boundary's points takes none; the other axis of its
    // face takes columns tested over the hull's box (FaceKdTreeLines::forColumns).
    for (int f = 0; f < faceCount; ++f)
        for (int axis = 0; axis < 2; ++axis)
            columnsRuledOut[2 * f + axis] = !columnCandidate[f] || !faceLines[f].axes[axis];
    // the axes along which a straight curve runs
    auto axesAlong = [](const CurveOnSurface& curve) {
        const Point2 from = curve.uv(0), to = curve.uv(1);
        return std::array<bool, 2>{from.x() != to.x(), from.y() != to.y()};
    };
    // The pairs of axes an edge runs along on two faces that may take columns, straight in both
    // (node = 2 face + axis), and whether it runs at the same values on both (to 1e-9 of the
    // first face's frame).
    struct AxisPair {
        int node, otherNode;
        bool sameValues;
    };
    std::vector<AxisPair> axisPairs;
    for (size_t e = 0; e < model.edges.size(); ++e)
        for (const auto& use : uses[e]) {
            if (!columnCandidate[use.face]) continue;
            const CurveOnSurface curve = curveOnSurface(use);
            // a curve bent in this face's (u, v) crosses its kd-tree lines wherever they fall,
            // even columns or halvings: nothing to tie (a plane's hole around a cylinder)
            if (!curve.straightInParameterPlane()) continue;
            const auto along = axesAlong(curve);
            for (const auto& other : uses[e]) {
                if (other.face == use.face && other.loop == use.loop && other.curve == use.curve)
                    continue;
                // A face that takes no columns (its region not its box) has no lines to agree
                // on: its kd-tree cuts through the edge's points wherever they fall, as through
                // a trimming curve's. Ruling this face's columns out for it took hammer.iges's
                // rational fillets 712 and 544 triangles at relative 1e-4 instead of 615 and 423
                // (9,260 -> 8,800 in all; bug33398.step 31,176 -> 30,874, trj7_b1-ec-214.stp
                // 29,377 -> 29,425).
                if (!columnCandidate[other.face]) continue;
                const CurveOnSurface otherCurve = curveOnSurface(other);
                if (!otherCurve.straightInParameterPlane()) continue;
                const auto otherAlong = axesAlong(otherCurve);
                for (int axis = 0; axis < 2; ++axis) {
                    if (!along[axis]) continue;
                    for (int otherAxis = 0; otherAxis < 2; ++otherAxis) {
                        if (!otherAlong[otherAxis]) continue;
                        const auto& grid = faceLines[use.face].axes[axis];
                        bool sameValues = grid && faceLines[other.face].axes[otherAxis];
                        for (const double t : {0.0, 0.5, 1.0})
                            sameValues =
                                sameValues &&
                                std::abs(curve.uv(t)[axis] - otherCurve.uv(t)[otherAxis]) <=
                                    1e-9 / grid->scale() * double(kKdTreeFrameScale);
                        axisPairs.push_back(
                            {2 * use.face + axis, 2 * other.face + otherAxis, sameValues});
                    }
                }
            }
        }
    // Two faces of an edge frame it from their own pcurves' ends, which may differ in the last
    // bits (bottle.brep's tori and the cylinders beside them, mirror images of a pair whose
    // frames agree: 0.0194257807917055 against 0.019425780791706). Such frames, within a step of
    // each other with the same span borders, become one: without, the axes were not tied, and
    // took halvings where their mirror images took columns (1,672 triangles a torus at relative
    // 1e-4 against 1,120). Near frames are not transitive, so each takes the frame of the lowest
    // node it is joined to through near pairs (union-find), where it is near that one too.
    auto gridOf = [&](int node) -> KdTreeGrid& { return *faceLines[node / 2].axes[node % 2]; };
    std::vector<int> frameRoot(2 * static_cast<size_t>(faceCount));
    std::iota(frameRoot.begin(), frameRoot.end(), 0);
    auto frameRootOf = [&](int node) {
        while (frameRoot[node] != node) node = frameRoot[node] = frameRoot[frameRoot[node]];
        return node;
    };
    for (const AxisPair& pair : axisPairs) {
        if (!pair.sameValues || !gridOf(pair.node).nearlySameFrame(gridOf(pair.otherNode)))
            continue;
        const int a = frameRootOf(pair.node), b = frameRootOf(pair.otherNode);
        frameRoot[std::max(a, b)] = std::min(a, b);
    }
    for (int node = 0; node < 2 * faceCount; ++node) {
        const int root = frameRootOf(node);
        if (root != node && !gridOf(node).sameFrame(gridOf(root)) &&
            gridOf(node).nearlySameFrame(gridOf(root)))
            gridOf(node) = gridOf(root);
    }
    // tied only where both run the edge on one frame at the same values
    for (const AxisPair& pair : axisPairs) {
        if (!pair.sameValues || !gridOf(pair.node).sameFrame(gridOf(pair.otherNode))) {
            columnsRuledOut[pair.node] = columnsRuledOut[pair.otherNode] = 1;
            continue;
        }
        columnGroup[groupOf(pair.node)] = groupOf(pair.otherNode);
    }
    std::map<int, std::vector<int>> columnGroups;  // group -> its nodes
    for (int node = 0; node < 2 * faceCount; ++node)
        if (columnCandidate[node / 2]) columnGroups[groupOf(node)].push_back(node);
    // A group's columns per interval: none where a member has none; the lines of its members
    // where they agree; the largest count where all are equal columns; otherwise all members'
    // lines together, less each line whose two columns, merged, settle on every member (each
    // member's own lines settle on it, and a column within a settled one settles too). Returns
    // its faces.
    // whether face f's columns may be cut across into rows (evenColumnLines' cutAcross)
    auto mayCutAcross = [&](int f) { return options.evenColumnsCutAcross && !hasFreeEdge(f); };
    auto assignColumns = [&](const std::vector<int>& nodes) {
        std::set<int> faces;
        for (const int node : nodes) faces.insert(node / 2);
        auto setLines = [&](const std::vector<std::vector<std::int64_t>>& lines) {
            for (const int node : nodes)
                if (auto& axis = faceLines[node / 2].axes[node % 2]) axis->setColumnLines(lines);
        };
        setLines({});
        if (std::any_of(nodes.begin(), nodes.end(),
                        [&](int node) { return columnsRuledOut[node]; }))
            return faces;
        const KdTreeGrid& grid = *faceLines[nodes.front() / 2].axes[nodes.front() % 2];
        const std::vector<std::int64_t> intervals = grid.intervals();
        std::vector<std::vector<std::vector<std::int64_t>>> lines(nodes.size());
        // the face's edges that run along the axis on an iso-line, with their chords' share
        auto chordsAlong = [&](int f, int axis) {
            std::vector<ChordsAlong> chords;
            for (int l = 0; l < static_cast<int>(model.faces[f].loops.size()); ++l)
                for (int c = 0; c < static_cast<int>(model.faces[f].loops[l].curves.size()); ++c) {
                    const std::size_t e = model.faces[f].loops[l].curves[c].edge;
                    if (e >= uses.size() || model.edges[e].degenerated) continue;
                    ChordsAlong edge;
                    for (std::size_t k = 0; k < uses[e].size(); ++k) {
                        const EdgeUse& use = uses[e][k];
                        if (use.face == f && use.loop == l && use.curve == c) edge.own = k;
                        edge.uses.push_back(curveOnSurface(use));
                    }
                    const CurveOnSurface& own = edge.uses[edge.own];
                    if (!own.straightInParameterPlane() ||
                        own.uv(0)[1 - axis] != own.uv(1)[1 - axis] ||
                        own.uv(0)[axis] == own.uv(1)[axis])
                        continue;
                    edge.approximation = edgeBudget(e, curveUse[e] >= 0).lineApproximation;
                    chords.push_back(std::move(edge));
                }
            return chords;
        };
        std::vector<std::vector<ChordsAlong>> chords(nodes.size());
        for (std::size_t k = 0; k < nodes.size(); ++k)
            chords[k] = chordsAlong(nodes[k] / 2, nodes[k] % 2);
        // what the group's columns depend on, for a tessellation of the same model before
        std::vector<double> key;
        if (columnMemo) {
            for (std::size_t k = 0; k < nodes.size(); ++k) {
                const int f = nodes[k] / 2;
                key.insert(key.end(), {double(nodes[k]), faceBudgets[f].surface});
                const auto grids = faceLines[f].forColumns();
                for (const KdTreeGrid& grid : *grids) {
                    key.insert(key.end(), {grid.low(), grid.parameterAt(kKdTreeFrameScale)});
                    for (const std::int64_t border : grid.intervals())
                        key.push_back(double(border));
                    appendColumnLines(key, grid);
                }
                for (const ChordsAlong& edge : chords[k])
                    key.insert(key.end(),
                               {edge.approximation, double(edge.uses.size()), double(edge.own)});
            }
            const std::lock_guard<std::mutex> lock(columnMemo->mutex);
            if (const auto known = columnMemo->lines.find(key); known != columnMemo->lines.end()) {
                setLines(known->second);
                return faces;
            }
        }
        forEachIndex(size_t(0), nodes.size(), [&](size_t k) {
            const int f = nodes[k] / 2;
            try {
                lines[k] = evenColumnLines(
                    model.faces[f], *faceLines[f].forColumns(), nodes[k] % 2,
                    faceBudgets[f].surface, options.mode, options.flatCellsByDistance,
                    mayCutAcross(f), options.gradedColumns, chords[k], surfaceCache.patches(f));
            } catch (const std::exception&) {
                // no columns: the face's own tessellation then says what is wrong with it
                lines[k].assign(intervals.size() - 1, {});
            }
        });
        // each member's column test, made where lines that disagree are merged
        std::vector<std::unique_ptr<ColumnTest>> tests;
        std::vector<std::vector<std::int64_t>> merged(intervals.size() - 1);
        for (std::size_t i = 0; i < merged.size(); ++i) {
            const std::int64_t a = intervals[i], b = intervals[i + 1];
            bool none = false, agree = true, allEqual = true;
            std::size_t most = 0;
            for (const auto& own : lines) {
                none = none || own[i].empty();
                agree = agree && own[i] == lines.front()[i];
                allEqual = allEqual && own[i] == KdTreeGrid::equalColumnLines(
                                                     a, b, static_cast<int>(own[i].size()) - 1);
                most = std::max(most, own[i].size());
            }
            if (none) continue;
            if (agree) {
                merged[i] = lines.front()[i];
                continue;
            }
            if (allEqual) {
                merged[i] = KdTreeGrid::equalColumnLines(a, b, static_cast<int>(most) - 1);
                continue;
            }
            std::set<std::int64_t> all;
            for (const auto& own : lines) all.insert(own[i].begin(), own[i].end());
            std::vector<std::int64_t> kept{a};
            std::vector<std::int64_t> candidates(all.begin(), all.end());
            for (std::size_t k = tests.size(); k < nodes.size(); ++k)
                tests.push_back(std::make_unique<ColumnTest>(
                    model.faces[nodes[k] / 2], *faceLines[nodes[k] / 2].forColumns(), nodes[k] % 2,
                    faceBudgets[nodes[k] / 2].surface, options.mode, options.flatCellsByDistance,
                    chords[k], surfaceCache.patches(nodes[k] / 2)));
            for (std::size_t c = 1; c + 1 < candidates.size(); ++c) {
                const bool mergeable = std::all_of(tests.begin(), tests.end(), [&](const auto& t) {
                    return t->columnAndChordsSettle(kept.back(), candidates[c + 1]);
                });
                if (!mergeable) kept.push_back(candidates[c]);
            }
            kept.push_back(b);
            merged[i] = std::move(kept);
        }
        if (columnMemo) {
            const std::lock_guard<std::mutex> lock(columnMemo->mutex);
            columnMemo->lines.emplace(std::move(key), merged);
        }
        setLines(merged);
        return faces;
    };
    // A column's test cuts it into rows on the lines of its face's other axis (ColumnTest), and
    // those are chosen by their own group, before or after this one: the first pass tests the
    // groups chosen first against halvings across. So each group whose members' other axes took
    // other lines after it was chosen is chosen once more, in the same order; the groups after
    // it then see its new lines. A sphere's longitudes had been tested against halved latitudes
    // (1.4 degrees at relative 1e-4) and its latitudes against those longitudes (2 degrees), so
    // its kd-tree cut the longitudes again where the two met: 264 points on the equator, now
    // 192 (the generated sphere at 1e-4: 33,564 -> 27,192 triangles). Only columns cut across
    // are tested on the other axis's lines, so only groups that may take them are chosen again
    // (bug33398.step at relative 1e-3 spent 8 ms choosing 14 groups again, all the same). A third
    // pass swung the sphere at 1e-3 back to its first choice.
    auto linesAcross = [&](const std::vector<int>& nodes) {
        std::vector<std::int64_t> lines;
        for (const int node : nodes) {
            const auto& other = faceLines[node / 2].axes[1 - node % 2];
            // only columns cut across into rows are tested on them
            if (!mayCutAcross(node / 2) || !other ||
                other->intervals().size() - 1 > kMostSpansCutAcross)
                continue;
            appendColumnLines(lines, *other);
        }
        return lines;
    };
    std::map<int, std::vector<std::int64_t>> testedAcross;  // group -> the lines it was tested on
    for (const auto& [group, nodes] : columnGroups) {
        testedAcross[group] = linesAcross(nodes);
        assignColumns(nodes);
    }
    for (const auto& [group, nodes] : columnGroups)
        if (linesAcross(nodes) != testedAcross[group]) assignColumns(nodes);
    // After the surface shares of `changed` faces changed: their groups' columns chosen again,
    // and the edges of those faces and of the groups' faces, to discretise again.
    auto edgesAfterRebudget = [&](const std::set<int>& changed) {
        std::set<int> groups, faces = changed, edges;
        for (const int f : changed)
            for (int axis = 0; axis < 2; ++axis)
                if (columnCandidate[f]) groups.insert(groupOf(2 * f + axis));
        for (const int group : groups) {
            const auto members = assignColumns(columnGroups.at(group));
            faces.insert(members.begin(), members.end());
        }
        for (const int f : faces)
            for (const auto& loop : model.faces[f].loops)
                for (const auto& curve : loop.curves) edges.insert(curve.edge);
        return edges;
    };
    auto onKdTreeLines =
        [&](size_t e, const std::vector<CurveOnSurface>& curves, const ErrorBudget& edge,
            std::vector<CurvePoints>& points) -> std::optional<std::vector<double>> {
        std::vector<size_t> order;
        if (curveUse[e] >= 0) order.push_back(static_cast<size_t>(curveUse[e]));
        for (size_t k = 0; k < curves.size(); ++k)
            if (static_cast<int>(k) != curveUse[e]) order.push_back(k);
        // A bent curve (not straight in (u, v)) put on the lines of a face on a cylinder takes
        // them only where they leave it fewer chords than midpoint subdivision does: such a face
        // is mostly triangulated unrolled over its boundary points (CylinderDevelopment), and
        // its lines then cut nothing. The lines' halvings overshoot: each radial hole of the
        // drilled tube of tests/bench/generated_shapes.py took 96 chords on its hole cylinder's
        // lines at relative 1e-4, 81 free (6,112 -> 5,404 triangles), while at 1e-3 the lines
        // give 24 and the subdivision 32. Over the 140 benchmark runs no mesh took more
        // triangles; bug33398.step at 1e-3 6,130 -> 6,090. Always free, the crossed cylinders
        // took 2,160 triangles at 1e-4 instead of 1,752 (their circles' points on the same
        // lines); choosing so on every face, trj7_b1-ec-214.stp at 1e-4 29,365 instead of 29,223.
        // Not in approximate mode, whose estimate took more triangles with it (the crossed
        // cylinders at 1e-3 504 instead of 452, the sphere less a cylinder 3,584 instead of
        // 3,484; 1.001x over the 140 runs).
        auto fewerChords = [&](std::vector<double> onLines, std::size_t k) {
            if (options.mode != ErrorMode::Guaranteed || !model.faces[uses[e][k].face].cylinder ||
                curves[k].straightInParameterPlane())
                return onLines;
            std::vector<double> free = discretizeEdge(curves, edge.lineApproximation,
                                                      edge.lineSimplification, {}, &points);
            auto chords = [&](const std::vector<double>& params) {
                return mergeChords(curves, params, edge.lineApproximation, edge.lineSimplification,
                                   &points)
                    .size();
            };
            return chords(free) < chords(onLines) ? free : onLines;
        };
        for (const BentCurves rule : {BentCurves::narrowBand, BentCurves::onRuledSurface})
            for (size_t k : order)
                if (auto params = discretizeEdgeOnKdTreeLines(
                        curves, k, &faceLines[uses[e][k].face], edge.lineApproximation,
                        edge.lineSimplification, &points, rule))
                    return fewerChords(std::move(*params), k);
        if (curveUse[e] < 0) return std::nullopt;
        return discretizeEdgeOnKdTreeLines(curves, curveUse[e], nullptr, edge.lineApproximation,
                                           edge.lineSimplification, &points);
    };
    // The curves of an edge and their points evaluated so far, kept from the edge's first
    // discretisation to the second that steps 1a and 1b may give it: only the budget changes,
    // so every point evaluated the first time is good the second. bottle.brep at relative 1e-4
    // discretises 12 of its 157 edges again in step 1a, its thread's helices, and that took
    // 7 ms where the first time over all of them took 11; trj7_b1-ec-214.stp 539 of its 1,178
    // in step 1b, 12.7 ms against 22.5.
    struct EvaluatedCurves {
        std::vector<CurveOnSurface> curves;
        std::vector<CurvePoints> points;  // into curves' elements, which a move leaves in place
    };
    std::vector<EvaluatedCurves> keptCurves(model.edges.size());
    bool keepCurves = true;  // up to step 1c
    auto discretizeAnew = [&](size_t e, const ErrorBudget& edge) {
        EvaluatedCurves own;
        EvaluatedCurves& evaluated = keepCurves ? keptCurves[e] : own;
        if (evaluated.curves.empty()) {
            for (const auto& u : uses[e]) evaluated.curves.push_back(curveOnSurface(u));
            evaluated.points = curvePointsOf(evaluated.curves);
        }
        const std::vector<CurveOnSurface>& curves = evaluated.curves;
        // A degenerated edge (a pole) is discretised like any other: on a true pole its points
        // coincide and their triangles vanish; on a sloppy one (a "pole" row spread over the
        // edge tolerance) they follow the surface instead of collapsing onto one vertex.
        // a free edge's every segment is an open edge of the mesh: as few as the bound allows
        if (curves.size() == 1)
            return discretizeEdgeByLongestChords(curves, edge.lineApproximation,
                                                 edge.lineSimplification);
        // Midpoint subdivision stops anywhere between a quarter and all of the bound, and the
        // paper's simplification (a quarter of the share, on the polyline) merges little on
        // evenly bent curves: the points are then thinned to the chords that the whole share
        // allows on the exact curves (mergeChords). On kd-tree lines the points kept are still
        // on them.
        // every way tried, and the merging, evaluate each of the curves' points once
        std::vector<CurvePoints>& points = evaluated.points;
        std::vector<double> params;
        if (auto aligned = onKdTreeLines(e, curves, edge, points))
            params = std::move(*aligned);
        else
            params = discretizeEdge(curves, edge.lineApproximation, edge.lineSimplification, {},
                                    &points);
        return mergeChords(curves, params, edge.lineApproximation, edge.lineSimplification,
                           &points);
    };
    if (keep) memo->edges.edges.assign(model.edges.size(), {});
    // (each edge is discretised by one thread at a time: its memo's entry is its own)
    auto discretize = [&](size_t e, const ErrorBudget& edge) {
        if (!memo) return discretizeAnew(e, edge);
        // a discretisation kept for the same shares, curve use and faces' kd-tree lines
        auto same = [&](const EdgeMemo::Discretisation& d) {
            if (d.approximation != edge.lineApproximation ||
                d.simplification != edge.lineSimplification || d.curveUse != curveUse[e] ||
                d.lines.size() != uses[e].size())
                return false;
            for (std::size_t k = 0; k < uses[e].size(); ++k)
                if (!(d.lines[k] == faceLines[uses[e][k].face])) return false;
            return true;
        };
        if (take)
            for (const auto& known : memo->edges.edges[e])
                if (same(known)) return known.params;
        std::vector<double> params = discretizeAnew(e, edge);
        if (keep) {
            EdgeMemo::Discretisation kept{
                edge.lineApproximation, edge.lineSimplification, curveUse[e], {}, params};
            for (const auto& u : uses[e]) kept.lines.push_back(faceLines[u.face]);
            memo->edges.edges[e].push_back(std::move(kept));
        }
        return params;
    };

    // 1. every edge discretised once for all its faces (sections 4 and 5.1), its points kept
    // up to step 1c
    auto narrowedGap = [&](size_t e) {
        return uses[e].size() >= 2 && !model.edges[e].degenerated &&
               edgeShareGap[e] < budget.shareGap;
    };
    std::vector<EdgePolyline> polylines(model.edges.size());
    // each use's (u, v) at the edge's parameters
    auto sampleUses = [&](size_t e) {
        auto& poly = polylines[e];
        poly.uv.assign(uses[e].size(), {});
        for (size_t k = 0; k < uses[e].size(); ++k) {
            const auto curve = curveOnSurface(uses[e][k]);
            for (double s : poly.params) poly.uv[k].push_back(curve.uv(s));
        }
    };
    auto discretizeOnce = [&](size_t e) {
        if (uses[e].empty()) return;
        polylines[e].params = discretize(e, edgeBudget(e, curveUse[e] >= 0));
        sampleUses(e);
    };
    forEachIndex(size_t(0), model.edges.size(), discretizeOnce);
    // The second tessellation of a lone face (tessellateModel) stops here where its free edges
    // already have more segments than the first one's open edges: cell sides only add points.
    // the segments of each face's free edges, as discretised so far
    auto freeSegmentsByFace = [&] {
        std::vector<std::size_t> segments(faceCount, 0);
        for (size_t e = 0; e < model.edges.size(); ++e)
            if (isFreeEdge(e) && !polylines[e].params.empty())
                segments[uses[e][0].face] += polylines[e].params.size() - 1;
        return segments;
    };
    if (freeEdgesAsCurveUses && openEdgeLimit > 0) {
        const auto segments = freeSegmentsByFace();
        if (std::accumulate(segments.begin(), segments.end(), std::size_t(0)) > openEdgeLimit) {
            result.failures.push_back({1, "more segments on its free edges than before"});
            return result;
        }
    }

    // 1a. A narrowed gap is checked at its edges' own points: where the faces' points of one are
    // farther apart than it (between the samples above), the faces of that edge take their
    // gap back (the fixed split, or what the face had before narrowing) and their edges are
    // discretised again with it. hammer.iges at relative 1e-4 had a point 0.06 T apart, farther
    // than its edge's samples had measured: an open crack.
    if (options.mode == ErrorMode::Guaranteed && options.narrowShareGaps) {
        std::vector<char> tooNarrow(model.edges.size(), 0);
        forEachIndex(size_t(0), model.edges.size(), [&](size_t e) {
            if (!narrowedGap(e)) return;
            const auto& poly = polylines[e];
            for (size_t k = 1; k + 1 < poly.params.size() && !tooNarrow[e]; ++k) {
                std::vector<Point3> own;
                for (size_t u = 0; u < uses[e].size(); ++u)
                    own.push_back(model.faces[uses[e][u].face].surface.point(poly.uv[u][k].x(),
                                                                             poly.uv[u][k].y()));
                tooNarrow[e] = farthest(own, centroid(own)) > 0.5 * edgeShareGap[e];
            }
        });
        std::set<int> widened;
        for (size_t e = 0; e < model.edges.size(); ++e)
            if (tooNarrow[e])
                for (const auto& u : uses[e]) widened.insert(u.face);
        for (const int f : widened) faceBudgets[f] = unnarrowed[f];
        const std::set<int> again = edgesAfterRebudget(widened);
        for (const int e : again) holdEdgeGapToFaces(e, unnarrowedEdgeGap[e]);
        const std::vector<int> edges(again.begin(), again.end());
        forEachIndex(size_t(0), edges.size(), [&](size_t i) { discretizeOnce(edges[i]); });
    }
    // A sloppy edge's faces are farther apart than the share gap, yet they often meet at an
    // angle or overlap along the surfaces (the gap lies in the surfaces, not across them): a
    // point near both surfaces then serves both faces. It is found from the faces' own points
    // (nearestCommonPoint: where the surfaces meet, else averaged projections); each face takes its
    // foot's (u, v), so the shared vertex is at most the edge's shareGap/2 off each surface (the
    // share budget). The face's boundary moves inside its surface, by at most the edge's own
    // tolerance: the B-rep places the true edge within that of each trimming curve, and it is
    // what meshjudge and the verifier allow at a face's boundary (a sample counts as
    // (distance to the trimmed face) - (largest tolerance of the face's edges)).
    // trj7_b1-ec-214.stp's 0.5 mm edges: trimming curves up to 0.5 mm (14 T at relative 1e-4)
    // from the 3D edge, which lies on both surfaces within 0.003 T.
    auto commonPoint = [&](std::size_t e, std::size_t k) -> std::optional<CommonPoint> {
        const auto& poly = polylines[e];
        const std::size_t useCount = uses[e].size();
        std::vector<Point3> own(useCount);
        std::vector<Point2> start(useCount);
        for (std::size_t u = 0; u < useCount; ++u) {
            start[u] = poly.uv[u][k];
            own[u] = model.faces[uses[e][u].face].surface.point(start[u].x(), start[u].y());
        }
        const double halfGap = 0.5 * edgeShareGap[e];
        CommonPoint common = nearestCommonPoint(e, anchorsOf(e, poly.params[k], own), start,
                                                halfGap, edgeShareGap[e]);
        if (!(common.offset <= halfGap)) return std::nullopt;
        return common;
    };
    // Whether the faces' own points of edge e at one place are shared as one vertex midway
    // between them: within the fixed share gap, or within the edge's own where it is wider or
    // narrower.
    auto sharedMidway = [&](size_t e, const std::vector<Point3>& points) {
        return (spread(points) <= budget.shareGap && edgeShareGap[e] >= budget.shareGap) ||
               farthest(points, centroid(points)) <= 0.5 * edgeShareGap[e];
    };
    // The other edges are checked at their points too. An edge whose samples all came within
    // its gap may still have a point farther apart (between the samples, or nearer an end than
    // the first sample): where its faces have no common point within the gap there either, that
    // point stays one per face, an open crack. Such an edge widens its gap to what its points
    // need (with the margin), where each of its faces can give that out of its other shares
    // (as for the samples above), and its faces' edges are discretised again. hammer.brep of
    // OpenCASCADE's samples at relative 1e-4: edges 77 and 79 measured 0.085 T and 0.06 T apart
    // at their samples and kept the fixed gap (0.2 T), but placed points 0.21 T apart there:
    // 16 open edges where BRepMesh has none.
    if (options.mode == ErrorMode::Guaranteed) {
        std::vector<double> wider(model.edges.size(), 0);
        forEachIndex(size_t(0), model.edges.size(), [&](size_t e) {
            if (uses[e].size() < 2 || model.edges[e].degenerated || narrowedGap(e)) return;
            const auto& poly = polylines[e];
            const double halfGap = 0.5 * edgeShareGap[e];
            double farthestOffset = 0;
            std::vector<Point3> own(uses[e].size());
            std::vector<Point2> start(uses[e].size());
            for (size_t k = 1; k + 1 < poly.params.size(); ++k) {
                for (size_t u = 0; u < uses[e].size(); ++u) {
                    start[u] = poly.uv[u][k];
                    own[u] = model.faces[uses[e][u].face].surface.point(start[u].x(), start[u].y());
                }
                // shared as shareVertices shares it: midway, or where the surfaces meet
                if (sharedMidway(e, own) || commonPoint(e, k)) continue;
                // a wider gap shares the point midway, or where the surfaces meet if that is
                // nearer
                const double midway = farthest(own, centroid(own));
                const double offset = nearestCommonPoint(e, anchorsOf(e, poly.params[k], own),
                                                         start, halfGap, largestGap)
                                          .offset;
                farthestOffset = std::max(
                    farthestOffset, std::isfinite(offset) ? std::min(offset, midway) : midway);
            }
            wider[e] = 2 * margin * farthestOffset;
        });
        std::set<int> widened;
        for (size_t e = 0; e < model.edges.size(); ++e) {
            if (!(wider[e] > edgeShareGap[e])) continue;
            if (!everyFaceAffords(e, wider[e])) continue;
            edgeShareGap[e] = wider[e];
            for (const auto& u : uses[e]) {
                faceBudgets[u.face] = faceBudgets[u.face].withShareGap(
                    std::max(faceBudgets[u.face].shareGap, wider[e]), options.tolerance,
                    options.mode);
                widened.insert(u.face);
            }
        }
        const std::set<int> again = edgesAfterRebudget(widened);
        for (const int e : again) holdEdgeGapToFaces(e, edgeShareGap[e]);
        const std::vector<int> edges(again.begin(), again.end());
        forEachIndex(size_t(0), edges.size(), [&](size_t i) { discretizeOnce(edges[i]); });
    }

    // The segments of face f's boundary polygon that cross another of its segments, as
    // (edge, segment) pairs: proper crossings only, so segments that share an end (consecutive
    // ones, loops that touch at a vertex) do not count, nor (for step 1b) two whose ends lie a
    // hair apart and that cross right there: a corner, where a finer budget changes nothing.
    // EngineBlock.rle of OpenCASCADE's samples: a circle's end and a line's end 1e-7 apart in a
    // plane's (u, v) made its two planes take the fixed split back, and the cylinders on their
    // circles twice the columns (492 triangles at relative 1e-3 instead of 276; BRepMesh 294);
    // trj7_b1-ec-214.stp 6,390 instead of 6,208, 70 of its 74 faces so rebudgeted at 1e-4.
    // A sweep over the segments sorted by their smallest u keeps it near linear on long loops.
    // With `toHalve`, only the crossings that halving can undo (step 1c): not two segments that
    // meet at a corner (ends closer than 1e-3 of the shorter one: curves that end at one vertex
    // up to rounding or up to a sloppy file's gap cross there however short their chords get),
    // nor two whose curves cross too (a sloppy curve that loops on itself near a corner), which
    // is tried with 16 chords on each.
    auto crossingSegments = [&](int f, bool toHalve) {
        struct Segment {
            Point2 a, b;
            int edge, index, use;
        };
        std::vector<Segment> segments;
        const auto& face = model.faces[f];
        for (int l = 0; l < int(face.loops.size()); ++l)
            for (int c = 0; c < int(face.loops[l].curves.size()); ++c) {
                const int e = face.loops[l].curves[c].edge;
                const int u = useIndex.at({f, l, c});
                const auto& uv = polylines[e].uv[u];
                for (size_t k = 0; k + 1 < uv.size(); ++k)
                    segments.push_back({uv[k], uv[k + 1], e, static_cast<int>(k), u});
            }
        auto side = [](const Point2& a, const Point2& b, const Point2& p) {
            const double cross = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
            return (cross > 0) - (cross < 0);
        };
        auto cross = [&](const Segment& s, const Segment& t) {
            return side(s.a, s.b, t.a) * side(s.a, s.b, t.b) < 0 &&
                   side(t.a, t.b, s.a) * side(t.a, t.b, s.b) < 0;
        };
        // segments that share an end (consecutive ones, loops that touch at a vertex) do not
        // cross, also where two curves' ends differ by rounding (a line's end and an arc's
        // rational end at one vertex)
        auto same = [](const Point2& p, const Point2& q) {
            return (p - q).norm() <= 1e-12 * (1 + p.norm());
        };
        auto touch = [&](const Segment& s, const Segment& t) {
            const double shorter2 = std::min((s.b - s.a).squaredNorm(), (t.b - t.a).squaredNorm());
            const double near2 = 1e-6 * shorter2;
            if (!toHalve) {
                if (same(s.a, t.a) || same(s.a, t.b) || same(s.b, t.a) || same(s.b, t.b))
                    return true;
                // ends a hair apart whose segments cross right there, within a hundredth of
                // the shorter one: a corner (see below), not a strip narrower than its chords'
                // sag, whose sides cross away from their ends
                const Point2 along = s.b - s.a, other = t.b - t.a;
                const double denominator = along.x() * other.y() - along.y() * other.x();
                if (denominator == 0) return false;
                const Point2 start = t.a - s.a;
                const double r = (start.x() * other.y() - start.y() * other.x()) / denominator;
                const Point2 crossing = s.a + r * along;
                for (const Point2* p : {&s.a, &s.b})
                    for (const Point2* q : {&t.a, &t.b})
                        if ((*p - *q).squaredNorm() <= near2 &&
                            (crossing - *p).squaredNorm() <= 1e-4 * shorter2)
                            return true;
                return false;
            }
            for (const Point2* p : {&s.a, &s.b})
                for (const Point2* q : {&t.a, &t.b})
                    if ((*p - *q).squaredNorm() <= near2) return true;
            return false;
        };
        // the segment's curve as 16 chords
        auto finer = [&](const Segment& s) {
            constexpr int pieces = 16;
            const auto& params = polylines[s.edge].params;
            const CurveOnSurface curve = curveOnSurface(uses[s.edge][s.use]);
            std::vector<Segment> chords;
            Point2 previous = s.a;
            for (int i = 1; i <= pieces; ++i) {
                const Point2 next =
                    i == pieces ? s.b
                                : curve.uv(params[s.index] +
                                           (params[s.index + 1] - params[s.index]) * i / pieces);
                chords.push_back({previous, next, s.edge, s.index, s.use});
                previous = next;
            }
            return chords;
        };
        auto curvesCross = [&](const Segment& s, const Segment& t) {
            const auto sChords = finer(s), tChords = finer(t);
            for (const Segment& a : sChords)
                for (const Segment& b : tChords)
                    if (!touch(a, b) && cross(a, b)) return true;
            return false;
        };
        auto lowU = [](const Segment& s) { return std::min(s.a.x(), s.b.x()); };
        std::sort(segments.begin(), segments.end(),
                  [&](const Segment& s, const Segment& t) { return lowU(s) < lowU(t); });
        std::set<std::pair<int, int>> crossing;
        for (size_t i = 0; i < segments.size(); ++i) {
            const Segment& s = segments[i];
            const double highU = std::max(s.a.x(), s.b.x());
            for (size_t j = i + 1; j < segments.size() && lowU(segments[j]) <= highU; ++j) {
                const Segment& t = segments[j];
                if (touch(s, t) || !cross(s, t) || (toHalve && curvesCross(s, t))) continue;
                crossing.insert({s.edge, s.index});
                crossing.insert({t.edge, t.index});
            }
        }
        return crossing;
    };
    auto chordsCross = [&](int f) { return !crossingSegments(f, false).empty(); };

    // 1b. A face that gave its surface share to its trimming curves has longer chords; on a
    // strip narrower than their sag (trj7_b1-ec-214.stp faces 54 and 86: planes 0.08 mm wide at
    // T = 0.36 mm) the chords of its two sides cross, the loop repair of section 5.1 cuts the
    // strip away, and its neighbours' edges stay open. Such a face takes the fixed split back
    // and its edges are discretised again (their share is the smallest of their faces').
    for (int round = 0; round < 2; ++round) {
        std::set<int> changed;
        for (int f = 0; f < faceCount; ++f)
            if (failure[f].empty() && faceBudgets[f].trimming() > budget.trimming() &&
                chordsCross(f)) {
                rebudget(f, budget);
                changed.insert(f);
            }
        const std::set<int> again = edgesAfterRebudget(changed);
        if (again.empty()) break;
        const std::vector<int> edges(again.begin(), again.end());
        forEachIndex(size_t(0), edges.size(), [&](size_t i) { discretizeOnce(edges[i]); });
    }

    keepCurves = false;
    keptCurves.clear();
    keptCurves.shrink_to_fit();

    // 1c. Chords that still cross in a face's (u, v), and loops of fewer than three points, are
    // halved, for every face of their edges at once. A crossing left to the loop repair of
    // section 5.1 puts a point at the crossing that only this face has, and a loop of two
    // points is fanned over the middles of its chords, which are its own too: open edges either
    // way. trj7_b1-ec-214.stp face 197 (a plane 0.15 mm wide where three faces meet, at
    // relative 1e-3) had edge 415's chord cross edge 602's; face 129 (a sliver between two
    // curves that join the same two vertices, closed by a pole) had one chord on each curve.
    // Halving brings each chord nearer its curve, and curves that do not cross stop their
    // chords crossing within a few rounds; where the curves themselves cross, the rounds end.
    {
        constexpr int kHalvingRounds = 6;
        auto splitSegments = [&](int e, const std::set<int>& segments) {
            auto& params = polylines[e].params;
            std::vector<double> halved;
            for (size_t k = 0; k < params.size(); ++k) {
                halved.push_back(params[k]);
                if (k + 1 < params.size() && segments.count(static_cast<int>(k)))
                    halved.push_back(0.5 * (params[k] + params[k + 1]));
            }
            params = std::move(halved);
            sampleUses(e);
        };
        for (int round = 0; round < kHalvingRounds; ++round) {
            std::vector<std::set<std::pair<int, int>>> toSplit(faceCount);
            forEachIndex(0, faceCount, [&](int f) {
                if (!failure[f].empty()) return;
                toSplit[f] = crossingSegments(f, true);
                for (const auto& loop : model.faces[f].loops) {
                    std::size_t segments = 0;
                    for (const auto& curve : loop.curves)
                        if (!model.edges[curve.edge].degenerated &&
                            !polylines[curve.edge].params.empty())
                            segments += polylines[curve.edge].params.size() - 1;
                    if (segments == 0 || segments >= 3) continue;
                    for (const auto& curve : loop.curves)
                        if (!model.edges[curve.edge].degenerated)
                            for (size_t k = 0; k + 1 < polylines[curve.edge].params.size(); ++k)
                                toSplit[f].insert({curve.edge, static_cast<int>(k)});
                }
            });
            std::map<int, std::set<int>> byEdge;
            for (const auto& list : toSplit)
                for (const auto& [e, k] : list) byEdge[e].insert(k);
            if (byEdge.empty()) break;
            const std::vector<std::pair<int, std::set<int>>> edges(byEdge.begin(), byEdge.end());
            forEachIndex(size_t(0), edges.size(),
                         [&](size_t i) { splitSegments(edges[i].first, edges[i].second); });
        }
    }

    // 2. shared vertices: B-rep vertices first, then the inner points of every edge; each
    // curve end at its vertex as endAtVertex puts it.
    std::vector<std::vector<std::array<Point3, 2>>> endPoints(model.edges.size());
    forEachIndex(size_t(0), model.edges.size(), [&](size_t e) {
        if (uses[e].empty()) return;
        auto& poly = polylines[e];
        const auto [firstVertex, lastVertex] = endVertices[e];
        endPoints[e].resize(uses[e].size());
        for (size_t k = 0; k < uses[e].size(); ++k) {
            const BSplineSurface& surface = model.faces[uses[e][k].face].surface;
            for (int end = 0; end < 2; ++end) {
                const int vertex = end == 0 ? firstVertex : lastVertex;
                Point2& uv = end == 0 ? poly.uv[k].front() : poly.uv[k].back();
                endPoints[e][k][end] = endAtVertex(surface, vertex, uv);
            }
        }
    });
    std::vector<Point3> positions;
    // how far each shared position is from the faces' own points it stands for: the share
    // budget it spends (0 for a point of one face)
    std::vector<double> offsets;
    std::map<std::pair<int, int>, std::uint32_t> vertexOfBrepVertex;  // (vertex, face or -1)
    {
        // endpoint positions of every use, by B-rep vertex
        std::map<int, std::vector<std::pair<int, Point3>>> endpoints;
        for (size_t e = 0; e < model.edges.size(); ++e) {
            if (uses[e].empty()) continue;
            const auto [firstVertex, lastVertex] = endVertices[e];
            for (size_t k = 0; k < uses[e].size(); ++k) {
                if (firstVertex >= 0)
                    endpoints[firstVertex].push_back({uses[e][k].face, endPoints[e][k][0]});
                if (lastVertex >= 0)
                    endpoints[lastVertex].push_back({uses[e][k].face, endPoints[e][k][1]});
            }
        }
        for (auto& [vertex, list] : endpoints) {
            std::vector<Point3> all;
            // a vertex's point moves the triangles of every face there: the smallest gap
            double gap = std::numeric_limits<double>::infinity();
            for (auto& [face, p] : list) {
                all.push_back(p);
                gap = std::min(gap, faceBudgets[face].shareGap);
            }
            std::map<int, std::vector<Point3>> byFace;
            for (auto& [face, p] : list) byFace[face].push_back(p);
            // Each face may also move its points to the common one as far as it moves them to
            // a point of its own: a sloppy wire's curves end apart at their vertex, and the
            // face's own point, their centroid, is that far from them already.
            // SMB_DO_214AA.stp of FreeCAD's IDF library: a band 0.005 mm high (0.72 T at
            // relative 1e-3) whose top shares its edges with the planes under it (tolerance
            // 0.0044), and a side wall whose two curves end at the top's and the plane's
            // heights: the side wall's own gap kept each face a corner of its own, and the
            // band's edges, a chord each, open (16 open edges; BRepMesh 0).
            const Point3 middle = centroid(all);
            bool eachFaceAllows = true;
            for (const auto& [face, points] : byFace)
                eachFaceAllows = eachFaceAllows && farthest(points, middle) <=
                                                       std::max(0.5 * faceBudgets[face].shareGap,
                                                                farthest(points, centroid(points)));
            // within the fixed gap as before; within a wider one, its point is within half of
            // it of every face's own point
            if ((spread(all) <= budget.shareGap && gap >= budget.shareGap) ||
                farthest(all, middle) <= 0.5 * gap || eachFaceAllows) {
                vertexOfBrepVertex[{vertex, -1}] = static_cast<std::uint32_t>(positions.size());
                positions.push_back(middle);
                offsets.push_back(farthest(all, positions.back()));
                continue;
            }
            for (auto& [face, points] : byFace) {
                vertexOfBrepVertex[{vertex, face}] = static_cast<std::uint32_t>(positions.size());
                positions.push_back(centroid(points));
                offsets.push_back(farthest(points, positions.back()));
            }
        }
    }
    auto brepVertexId = [&](int vertex, int face) -> std::uint32_t {
        if (auto it = vertexOfBrepVertex.find({vertex, -1}); it != vertexOfBrepVertex.end())
            return it->second;
        return vertexOfBrepVertex.at({vertex, face});
    };
    // the shared vertices of one edge; false where a point stays one per face (a sloppy edge)
    auto shareVertices = [&](size_t e) {
        auto& poly = polylines[e];
        const auto [firstVertex, lastVertex] = endVertices[e];
        const size_t n = poly.params.size();
        poly.vertices.assign(uses[e].size(), std::vector<std::uint32_t>(n));
        poly.inserted.assign(n - 1, {});
        std::vector<CurveOnSurface> curves;
        for (const auto& u : uses[e]) curves.push_back(curveOnSurface(u));
        bool allShared = true;
        for (size_t k = 0; k < n; ++k) {
            const bool first = k == 0, last = k + 1 == n;
            if ((first && firstVertex >= 0) || (last && lastVertex >= 0)) {
                const int vertex = last ? lastVertex : firstVertex;
                for (size_t u = 0; u < uses[e].size(); ++u)
                    poly.vertices[u][k] = brepVertexId(vertex, uses[e][u].face);
                continue;
            }
            std::vector<Point3> points;
            for (const auto& c : curves) points.push_back(c.point(poly.params[k]));
            if (sharedMidway(e, points)) {
                const auto id = static_cast<std::uint32_t>(positions.size());
                positions.push_back(centroid(points));
                offsets.push_back(farthest(points, positions.back()));
                for (auto& v : poly.vertices) v[k] = id;
            } else if (auto common = commonPoint(e, k)) {
                const auto id = static_cast<std::uint32_t>(positions.size());
                positions.push_back(common->point);
                offsets.push_back(common->offset);
                for (size_t u = 0; u < uses[e].size(); ++u) {
                    poly.vertices[u][k] = id;
                    poly.uv[u][k] = common->uv[u];
                }
            } else {
                allShared = false;
                for (size_t u = 0; u < points.size(); ++u) {
                    poly.vertices[u][k] = static_cast<std::uint32_t>(positions.size());
                    positions.push_back(points[u]);
                    offsets.push_back(0);
                }
            }
        }
        for (size_t u = 1; u < uses[e].size(); ++u)
            for (const int end : {0, static_cast<int>(n) - 1})
                allShared &= poly.vertices[u][end] == poly.vertices[0][end];
        return allShared;
    };
    for (size_t e = 0; e < model.edges.size(); ++e) {
        if (uses[e].empty()) continue;
        if (shareVertices(e) || curveUse[e] < 0) continue;
        // A segment whose faces keep their own points gets no shared cuts: the face of the
        // straight curve would find its cells' points on chords of the other faces' share.
        // The edge is discretised again with every face's share (the ends keep their (u, v),
        // moved onto the B-rep vertices above); the positions made for it are left unused.
        auto& poly = polylines[e];
        std::vector<std::pair<Point2, Point2>> ends;
        for (const auto& uv : poly.uv) ends.push_back({uv.front(), uv.back()});
        curveUse[e] = -1;
        discretizeOnce(e);
        for (size_t k = 0; k < uses[e].size(); ++k)
            std::tie(poly.uv[k].front(), poly.uv[k].back()) = ends[k];
        shareVertices(e);
    }

    // exact integer points of cuts, by (edge, use, shared vertex): the two sides of a seam are
    // two uses of one edge in one face and share the vertex, but not the (u, v) point
    std::map<std::tuple<int, int, std::uint32_t>, std::pair<std::int64_t, std::int64_t>>
        exactPoints;

    // a face's boundary polygons from the shared polylines
    // (the fan of a thin face also takes loops of two points: two curves between two vertices)
    auto boundaryOf = [&](int f, std::size_t minimumPoints = 3) {
        std::vector<BoundaryLoop> loops;
        const auto& face = model.faces[f];
        for (int l = 0; l < int(face.loops.size()); ++l) {
            BoundaryLoop loop;
            for (int c = 0; c < int(face.loops[l].curves.size()); ++c) {
                const TrimCurve& curve = face.loops[l].curves[c];
                const int e = curve.edge;
                const int u = useIndex.at({f, l, c});
                const auto& poly = polylines[e];
                // Points that cell sides add go onto the curve use's surface, on the curve (step
                // 4); a face whose own curve is not straight in (u, v) takes them at their foot
                // on its surface, not on its (u, v) chord: the chord is up to the chord's sag
                // away, which folds its thin triangles between two close points.
                const bool onOtherCurve = curveUse[e] >= 0 && curveUse[e] != u &&
                                          !curveOnSurface({f, l, c}).straightInParameterPlane();
                // the curve's points in edge order, with the segment each one starts
                std::vector<BoundaryPoint> points;
                std::vector<int> segmentAfter;
                const size_t n = poly.params.size();
                for (size_t k = 0; k < n; ++k) {
                    points.push_back({poly.uv[u][k], poly.vertices[u][k]});
                    segmentAfter.push_back(static_cast<int>(k));
                    if (k + 1 == n) break;
                    // Not on a segment where this face's clipper placed cuts of its own: those
                    // lie on its (u, v) chord, and feet on the curve beside them, up to the
                    // chord's sag away, can zigzag across the cell side that made them where
                    // the boundary runs nearly along it (bottle.brep's thread tip at relative
                    // 1e-3 with merged chords: six open edges).
                    bool ownCuts = false;
                    for (const auto& ins : poly.inserted[k])
                        ownCuts |= exactPoints.count({e, u, ins.vertices[u]}) > 0;
                    for (const auto& ins : poly.inserted[k]) {
                        BoundaryPoint p{
                            (1 - ins.lambda) * poly.uv[u][k] + ins.lambda * poly.uv[u][k + 1],
                            ins.vertices[u]};
                        if (onOtherCurve && !ownCuts)
                            p.uv = projectOntoSurface(face.surface, positions[p.vertex], p.uv).uv;
                        if (auto it = exactPoints.find({e, u, p.vertex}); it != exactPoints.end()) {
                            p.exact = true;
                            p.x = it->second.first;
                            p.y = it->second.second;
                        }
                        points.push_back(p);
                        segmentAfter.push_back(static_cast<int>(k));
                    }
                }
                const bool forward = !curve.reversed;
                if (!forward) {
                    std::reverse(points.begin(), points.end());
                    std::reverse(segmentAfter.begin(), segmentAfter.end());
                }
                // join to the previous curve: the same vertex is one point; otherwise a gap
                size_t startIndex = 0;
                if (!loop.points.empty() && loop.points.back().vertex == points.front().vertex &&
                    points.size() > 1) {
                    startIndex = 1;
                    loop.origins.back() = {e, forward ? segmentAfter[0] : segmentAfter[1], forward,
                                           u};
                }
                for (size_t i = startIndex; i < points.size(); ++i) {
                    loop.points.push_back(points[i]);
                    // segment from this point to the next one of the curve
                    int segment = forward ? segmentAfter[i]
                                          : (i + 1 < points.size() ? segmentAfter[i + 1] : 0);
                    loop.origins.push_back({e, segment, forward, u});
                }
                loop.origins.back() = {-1, 0, true, 0};  // to the next curve, until joined
            }
            // close: the last point equal to the first is one point
            if (loop.points.size() > 1 && loop.points.back().vertex == loop.points.front().vertex) {
                // the segment into the dropped point now closes the loop: its origin holds
                loop.points.pop_back();
                loop.origins.pop_back();
            }
            if (loop.points.size() >= minimumPoints) loops.push_back(std::move(loop));
        }
        return loops;
    };

    // 3. first pass over faces: kd-trees and the cuts of cell sides with the boundary
    if (keep) {
        treeMemo->faces.clear();
        treeMemo->faces.resize(faceCount);
    }
    std::vector<std::unique_ptr<FaceTessellator>> tessellators(faceCount);
    std::vector<char> keptTree(faceCount, 0);  // taken from the last tessellation (treeMemo)
    std::vector<std::vector<BoundaryCrossing>> crossings(faceCount);
    std::vector<char> thinFace(faceCount, 0);  // loops without area: fanned in the second pass
    std::atomic<std::size_t> done{0};
    forEachIndex(0, faceCount, [&](int f) {
        if (!failure[f].empty()) return;
        try {
            CellChoices choices;
            choices.splitThroughBoundaryPoints = options.splitThroughBoundaryPoints;
            choices.flatCellsByDistance = options.flatCellsByDistance;
            choices.middleSplits = options.middleSplits;
            choices.openPointsSpendCellSlack = options.openPointsSpendCellSlack;
            choices.openPointsBoundedBySurface = options.openPointsBoundedBySurface;
            choices.compact = options.compact;
            // A face asked to refine at its free chords takes finer cells there, where the
            // removal may drop their points (not on chords on the surface, where every point
            // stays), and, as a lone face tried with its free edges as curve uses, its cells
            // cut along those chords where that does nearly as well. On a first tessellation
            // the cuts along cost more than they save (wing.brep, four lone faces with free
            // edges only, at relative 1e-3: 644 -> 1,095 triangles, 32 -> 39 open edges).
            const bool refine =
                f < static_cast<int>(refineFreeChords.size()) && refineFreeChords[f];
            choices.finerCellsAtFreeChords = refine && !chordsOnSurface[f];
            choices.cutsAlongFreeChords =
                options.cutsAlongFreeChords && (refine || freeEdgesAsCurveUses);
            if (options.mode == ErrorMode::Guaranteed && options.freeEdgesTakeSurfaceShare &&
                (choices.finerCellsAtFreeChords || choices.cutsAlongFreeChords)) {
                for (const auto& loop : model.faces[f].loops)
                    for (const auto& curve : loop.curves)
                        if (isFreeEdge(curve.edge)) choices.freeEdges.push_back(curve.edge);
                std::sort(choices.freeEdges.begin(), choices.freeEdges.end());
            }
            choices.filledCellsBySides = !hasFreeEdge(f) || chordsOnSurface[f];
            choices.freeEdgesOnSurface = hasFreeEdge(f) && chordsOnSurface[f];
            if (hasEvenColumns(f)) choices.evenColumns = faceLines[f].forColumns();
            std::vector<BoundaryLoop> loops = boundaryOf(f);
            if (take) {
                FaceTreeMemo::Face& kept = treeMemo->faces[f];
                if (kept.tessellator && kept.budget == faceBudgets[f] && kept.choices == choices &&
                    kept.loops == loops) {
                    tessellators[f] = std::move(kept.tessellator);
                    crossings[f] = std::move(kept.crossings);
                    keptTree[f] = 1;
                    return;
                }
            }
            tessellators[f] = std::make_unique<FaceTessellator>(
                model.faces[f], faceBudgets[f], options.mode, choices, surfaceCache.patches(f));
            crossings[f] = tessellators[f]->findCrossings(loops);
            if (keep) {
                FaceTreeMemo::Face& entry = treeMemo->faces[f];
                entry.budget = faceBudgets[f];
                entry.choices = std::move(choices);
                entry.loops = std::move(loops);
                entry.crossings = crossings[f];
                entry.kdTreeAfterCrossings = tessellators[f]->hasKdTree();
            }
        } catch (const FaceWithoutArea&) {
            thinFace[f] = 1;
            tessellators[f].reset();
        } catch (const std::exception& e) {
            failure[f] = e.what();
            tessellators[f].reset();
        }
    });

    // 4. every cut joins its edge's polyline, for both faces of the edge; returns the edges that
    // gained a point
    using CutList = std::vector<std::tuple<double, int, std::int64_t, std::int64_t>>;
    auto joinCuts = [&](std::map<std::pair<int, int>, CutList>& cuts) {
        std::set<int> changed;
        for (auto& [key, list] : cuts) {
            auto [e, k] = key;
            auto& poly = polylines[e];
            std::sort(list.begin(), list.end());
            const size_t useCount = uses[e].size();
            bool sharedEnds = true;
            for (size_t u = 1; u < useCount; ++u)
                sharedEnds &= poly.vertices[u][k] == poly.vertices[0][k] &&
                              poly.vertices[u][k + 1] == poly.vertices[0][k + 1];
            // A segment that no two faces share (a free edge, or a sloppy edge whose faces keep
            // their own points) gains nothing from the cut: the face that found it makes its own
            // point on the chord, which it may drop again (removeOpenBoundaryPoints).
            if (useCount == 1 || !sharedEnds) continue;
            auto& inserted = poly.inserted[k];
            for (auto& [lambda, use, x, y] : list) {
                if (lambda <= 0 || lambda >= 1) continue;
                auto at = std::lower_bound(
                    inserted.begin(), inserted.end(), lambda - 1e-9,
                    [](const EdgePolyline::Inserted& i, double l) { return i.lambda < l; });
                if (at == inserted.end() || at->lambda - lambda > 1e-9) {
                    // all uses share the segment's ends, so they share the point
                    const auto id = static_cast<std::uint32_t>(positions.size());
                    if (const int c = curveUse[e]; c >= 0) {
                        // on the straight curve's surface, hence on the curve
                        const Point2 uv = (1 - lambda) * poly.uv[c][k] + lambda * poly.uv[c][k + 1];
                        positions.push_back(
                            model.faces[uses[e][c].face].surface.point(uv.x(), uv.y()));
                    } else {
                        positions.push_back((1 - lambda) * positions[poly.vertices[0][k]] +
                                            lambda * positions[poly.vertices[0][k + 1]]);
                    }
                    offsets.push_back(
                        std::max(offsets[poly.vertices[0][k]], offsets[poly.vertices[0][k + 1]]));
                    at = inserted.insert(at, {lambda, std::vector<std::uint32_t>(useCount, id)});
                    changed.insert(e);
                }
                // the side that found the cut places it exactly where its clipper did
                exactPoints[{e, use, at->vertices[use]}] = {x, y};
            }
        }
        return changed;
    };
    {
        std::map<std::pair<int, int>, CutList> cuts;
        for (int f = 0; f < faceCount; ++f)
            for (const auto& c : crossings[f])
                cuts[{c.edge, c.segment}].push_back({c.lambda, c.use, c.x, c.y});
        joinCuts(cuts);
    }

    // 5. second pass: cut and triangulate with the completed boundaries
    std::vector<FaceMesh> faceMeshes(faceCount);
    std::vector<char> fanned(faceCount, 0);
    auto meshFace = [&](int f) {
        if (tessellators[f]) {
            try {
                std::vector<BoundaryLoop> loops = boundaryOf(f);
                std::optional<FaceMesh> kept;
                if (keptTree[f])
                    kept = keptMeshRenamed(treeMemo->faces[f], loops, positions, offsets);
                faceMeshes[f] = kept ? std::move(*kept)
                                     : tessellators[f]->triangulate(loops, positions, offsets);
                if (keep) {
                    FaceTreeMemo::Face& entry = treeMemo->faces[f];
                    entry.mesh = faceMeshes[f];
                    entry.meshPositions = ofLoopPoints(loops, positions);
                    entry.meshOffsets = ofLoopPoints(loops, offsets);
                    entry.meshLoops = std::move(loops);
                }
            } catch (const std::exception& e) {
                failure[f] = e.what();
                tessellators[f].reset();
            }
        }
        // A face too thin for any cell to find area inside its loops is still meshed: a fan
        // over its boundary (a face must never be missing).
        if (thinFace[f] || (failure[f].empty() && faceMeshes[f].triangles.empty())) {
            faceMeshes[f] = fanOverBoundary(model.faces[f], boundaryOf(f, 2), positions);
            if (keep) treeMemo->faces[f].mesh.reset();
            fanned[f] = 1;
            tessellators[f].reset();
            failure[f].clear();
            if (faceMeshes[f].triangles.empty())
                failure[f] = "no triangles inside the trimming loops";
        }
    };
    forEachIndex(0, faceCount, [&](int f) {
        meshFace(f);
        const std::size_t n = ++done;
        if (options.progress) options.progress(n, static_cast<std::size_t>(faceCount));
    });

    // 5b. The second pass cuts a boundary that has more points than the first one saw, and the
    // clipper's rounding differs with them: a cell side can cut a shared chord where the first
    // pass found nothing, which only that face knows (an open edge). Such cuts join their edge
    // as in step 4 and both faces of the edge are cut again; a round or two leaves none.
    for (int round = 0; round < 3; ++round) {
        std::map<std::pair<int, int>, CutList> cuts;
        for (int f = 0; f < faceCount; ++f)
            for (const auto& cut : faceMeshes[f].openCuts) {
                const auto& poly = polylines[cut.edge];
                const Point3& a = positions[poly.vertices[cut.use][cut.segment]];
                const Point3& b = positions[poly.vertices[cut.use][cut.segment + 1]];
                const double length2 = (b - a).squaredNorm();
                if (!(length2 > 0)) continue;
                const double lambda = (cut.position - a).dot(b - a) / length2;
                cuts[{cut.edge, cut.segment}].push_back({lambda, cut.use, cut.x, cut.y});
            }
        const std::set<int> changed = joinCuts(cuts);
        if (changed.empty()) break;
        std::vector<int> again;
        std::vector<char> listed(faceCount, 0);
        for (int e : changed)
            for (const auto& use : uses[e])
                if (tessellators[use.face] && !listed[use.face]) {
                    listed[use.face] = 1;
                    again.push_back(use.face);
                }
        forEachIndex(0, static_cast<int>(again.size()), [&](int i) { meshFace(again[i]); });
    }
    if (keep) {
        // (triangulate leaves a face as findCrossings did, but where it built its kd-tree)
        for (int f = 0; f < faceCount; ++f)
            if (tessellators[f] &&
                (treeMemo->faces[f].kdTreeAfterCrossings || !tessellators[f]->hasKdTree()))
                treeMemo->faces[f].tessellator = std::move(tessellators[f]);
        memo->kept = true;
    } else if (take) {
        memo->trees.faces.clear();
        memo->edges.edges.clear();
        memo->kept = false;
    }
    tessellators.clear();

    // 6. one mesh: shared positions first, then each face's own points, in face order
    Mesh& mesh = result.mesh;
    mesh.positions = std::move(positions);
    std::vector<char> used(mesh.positions.size(), 0);
    if (options.keepFaceVertices) result.faceVertices.resize(faceCount);
    for (int f = 0; f < faceCount; ++f) {
        if (!failure[f].empty()) {
            result.failures.push_back({f + 1, failure[f]});
            continue;
        }
        const FaceMesh& fm = faceMeshes[f];
        if (options.keepFaceVertices && !fanned[f]) {
            FaceVertexSet& set = result.faceVertices[f];
            set.firstNormal = static_cast<std::uint32_t>(mesh.normals.size());
            for (const auto& v : fm.vertices) {
                set.uv.push_back(v.uv);
                set.needsPosition.push_back(v.positionFromSurface ? 1 : 0);
                set.positions.push_back(v.position);
            }
        }
        std::vector<std::uint32_t> global(fm.vertices.size());
        const auto normalBase = static_cast<std::uint32_t>(mesh.normals.size());
        for (size_t i = 0; i < fm.vertices.size(); ++i) {
            const auto& v = fm.vertices[i];
            if (v.shared) {
                global[i] = v.sharedId;
            } else {
                global[i] = static_cast<std::uint32_t>(mesh.positions.size());
                mesh.positions.push_back(v.position);
                used.push_back(0);
            }
            mesh.normals.push_back(v.normal);
            mesh.parameters.push_back(v.uv);
        }
        for (const auto& t : fm.triangles) {
            mesh.triangles.push_back({global[t[0]], global[t[1]], global[t[2]]});
            mesh.triangleNormals.push_back(
                {normalBase + t[0], normalBase + t[1], normalBase + t[2]});
            mesh.triangleFaces.push_back(f + 1);
            for (auto i : t) used[global[i]] = 1;
        }
    }
    // Drop positions no triangle uses (edges of failed faces) and weld points closer than
    // 1e-2 of the tolerance: a cell side that cuts an edge next to one of its points leaves a
    // sliver that is noise for the error but a degenerate triangle for whoever reads the mesh,
    // and two B-rep vertices a sloppy file puts that close (trj7_b1-ec-214.stp: 0.0008 apart,
    // 0.002 T at relative 1e-3) leave a crack where one face ends at each. Moving a point by at
    // most 1e-2 T moves its triangles by no more, within the budget's slack.
    // The two ends of one B-rep edge at least half the weld distance long are not welded: the
    // edge's chord already joins its faces, and a label on a chip lower than the weld (0.002
    // under 0.0025 at relative 1e-1) lost its side faces so, its top and the body meeting on
    // points some of which had moved (FreeCAD's IDF chips at 1e-1 and 5e-2: up to 67 open
    // edges, BRepMesh none; now none but SOT_96's 10 at 5e-2, 15 before). Shorter edges are the
    // slivers the weld is for: with every edge's ends kept apart, trj7_b1-ec-214.stp's edges of
    // 4e-6 to 3e-5 kept their triangles and took 2 to 8 more sides of three triangles at relative
    // 1e-3 and 1e-4, and SOD_323.stp at 1e-4 one more open edge.
    const double weldDistance = 1e-2 * options.tolerance;
    constexpr double kLeastUnweldedEdge = 0.5;
    std::vector<std::int32_t> brepVertex(mesh.positions.size(), -1);
    for (const auto& [vertexAndFace, id] : vertexOfBrepVertex)
        if (id < brepVertex.size()) brepVertex[id] = vertexAndFace.first;
    std::set<std::pair<int, int>> edgeEnds;
    for (const ModelEdge& edge : model.edges)
        if (edge.firstVertex >= 0 && edge.lastVertex >= 0 && edge.firstVertex != edge.lastVertex &&
            (model.vertices[edge.firstVertex].point - model.vertices[edge.lastVertex].point)
                    .norm() >= kLeastUnweldedEdge * weldDistance)
            edgeEnds.insert(std::minmax(edge.firstVertex, edge.lastVertex));
    const auto mayJoin = [&](std::uint32_t point, std::uint32_t kept) {
        const int a = brepVertex[point], b = brepVertex[kept];
        return a < 0 || b < 0 || a == b || !edgeEnds.count(std::minmax(a, b));
    };
    WeldedPoints welded = weldPoints(mesh.positions, used, weldDistance, mayJoin);
    // Not across a plate thinner than that (a 0.01 mm plate at T = 1.03 mm, relative 2e-2 of
    // the box fused with a cylinder of tests/bench/generated_shapes.py): its two sides' corners
    // would become one, the sides would lie on each other, and the mesh would open along its
    // rims (8 open edges and 11 used by three triangles or more, where BRepMesh leaves none).
    unweldFolds(mesh.triangles, mesh.positions, brepVertex, weldDistance, welded);
    const std::vector<std::uint32_t>& remap = welded.remap;
    // whether a triangle keeps three points after the weld
    auto keepsThreePoints = [&](const std::array<std::uint32_t, 3>& c) {
        return remap[c[0]] != remap[c[1]] && remap[c[1]] != remap[c[2]] &&
               remap[c[0]] != remap[c[2]];
    };
    // A face narrower than the weld loses every triangle to it: SOD_323.stp of FreeCAD's IDF
    // library has faces 1.5e-6 mm wide along 1.8 mm edges, whose area (2.6e-6) exceeds T^2 at
    // relative 1e-4 (T = 3.1e-4), where the verifier and meshjudge count a face without
    // triangles as missing. Such a face keeps its own triangles on its own points, unwelded:
    // they lie within the face's width of it both ways, and its neighbours, welded across it,
    // stay closed; only its own triangles' sides are open.
    struct SliverTriangle {
        std::array<Point3, 3> corners;
        std::array<std::uint32_t, 3> normals;
        std::int32_t face;
    };
    std::vector<SliverTriangle> slivers;
    {
        std::vector<char> survives(faceCount, 0);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            if (keepsThreePoints(mesh.triangles[t])) survives[mesh.triangleFaces[t] - 1] = 1;
        // only a face whose own triangles' area exceeds T^2, as the judges' rule for a missing
        // face; one of no area (two edges on one curve) is listed as before
        std::vector<double> area(faceCount, 0);
        auto triangleArea = [&](const std::array<std::uint32_t, 3>& c) {
            const Point3 &a = mesh.positions[c[0]], &b = mesh.positions[c[1]],
                         &d = mesh.positions[c[2]];
            return 0.5 * (b - a).cross(d - a).norm();
        };
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            if (!survives[mesh.triangleFaces[t] - 1])
                area[mesh.triangleFaces[t] - 1] += triangleArea(mesh.triangles[t]);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& c = mesh.triangles[t];
            const int f = mesh.triangleFaces[t] - 1;
            if (survives[f] || !(area[f] > options.tolerance * options.tolerance)) continue;
            slivers.push_back({{mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]]},
                               mesh.triangleNormals[t],
                               mesh.triangleFaces[t]});
        }
    }
    mesh.positions = std::move(welded.kept);
    // Keeps the triangles that keep(t, corners) takes, in order, with their normals and faces;
    // keep may renumber the corners.
    auto keepTriangles = [&mesh](auto keep) {
        std::size_t out = 0;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            auto corners = mesh.triangles[t];
            if (!keep(t, corners)) continue;
            mesh.triangles[out] = corners;
            mesh.triangleNormals[out] = mesh.triangleNormals[t];
            mesh.triangleFaces[out] = mesh.triangleFaces[t];
            ++out;
        }
        mesh.triangles.resize(out);
        mesh.triangleNormals.resize(out);
        mesh.triangleFaces.resize(out);
    };
    keepTriangles([&](std::size_t, std::array<std::uint32_t, 3>& corners) {
        if (!keepsThreePoints(corners)) return false;
        for (auto& i : corners) i = remap[i];
        return true;
    });
    // A face's own point that the weld moved onto a point of another face's chord (a thin band
    // of a trimmed cell along its boundary, 1e-6 of a millimetre wide on bottle.brep's thread)
    // leaves a needle there: its triangle across that chord is split at the point instead.
    std::vector<TriangleOrigin> origins;
    if (splitNeedles(
            mesh.triangles, [&](std::uint32_t i) -> const Point3& { return mesh.positions[i]; },
            &origins)) {
        const auto normalsBefore = std::move(mesh.triangleNormals);
        const auto facesBefore = std::move(mesh.triangleFaces);
        mesh.triangleNormals.resize(origins.size());
        mesh.triangleFaces.resize(origins.size());
        for (std::size_t t = 0; t < origins.size(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const CornerOrigin& from = origins[t].corners[k];
                mesh.triangleNormals[t][k] = normalsBefore[from.triangle][from.corner];
            }
            mesh.triangleFaces[t] = facesBefore[origins[t].triangle];
        }
    }
    // folds without area, a pair of triangles each way round on three points of a chord
    // (FoldedPairs)
    const std::vector<char> kept = trianglesOutsideFolds(mesh.triangles, mesh.positions);
    if (std::find(kept.begin(), kept.end(), 0) != kept.end()) {
        keepTriangles([&](std::size_t t, std::array<std::uint32_t, 3>&) { return kept[t] != 0; });
        // the fold's points on the chord that no other triangle uses go with it
        std::vector<std::uint32_t> newIndex(mesh.positions.size(), 0);
        for (const auto& t : mesh.triangles)
            for (auto i : t) newIndex[i] = 1;
        std::uint32_t next = 0;
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            if (!newIndex[i]) continue;
            mesh.positions[next] = mesh.positions[i];
            newIndex[i] = next++;
        }
        mesh.positions.resize(next);
        for (auto& t : mesh.triangles)
            for (auto& i : t) i = newIndex[i];
    }

    for (const SliverTriangle& sliver : slivers) {
        std::array<std::uint32_t, 3> corners;
        for (int k = 0; k < 3; ++k) {
            corners[k] = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(sliver.corners[k]);
        }
        mesh.triangles.push_back(corners);
        mesh.triangleNormals.push_back(sliver.normals);
        mesh.triangleFaces.push_back(sliver.face);
    }

    // A face meshed without a failure must still have a triangle after the weld and the folds
    // went: one that has none is listed, never silently missing (a closed edge whose pcurve
    // read as one point gave its plane no boundary, and no word).
    std::vector<char> hasTriangle(faceCount, 0);
    for (const int f : mesh.triangleFaces) hasTriangle[f - 1] = 1;
    for (int f = 0; f < faceCount; ++f)
        if (failure[f].empty() && !hasTriangle[f])
            result.failures.push_back({f + 1, kNoTriangleLeft});
    std::sort(result.failures.begin(), result.failures.end(),
              [](const FaceFailure& a, const FaceFailure& b) { return a.face < b.face; });

    if (freeSegments) *freeSegments = freeSegmentsByFace();
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace

// The most triangles per open edge of a lone face's first mesh for its second tessellation
// (tessellateModel). The generated fitted surface (57 x 57 spans, four free edges) at relative
// 1e-3 takes 932 triangles and 104 open edges on its first tessellation, 8.96 per open edge,
// and 580 and 94 on its second; with 8 it kept the first.
constexpr std::size_t kBorderShare = 10;

// How many open edges per free segment a first mesh may keep before it is tessellated again
// with finer cells at its free chords (tessellateModel).
constexpr double kUndroppedShare = 1.1;

// The most triangles a model's second tessellation, with finer cells at its free chords, may
// take where it brings its open edges down to about its free segments, as a multiple of its
// first mesh's (tessellateModel).
constexpr double kRefinedTriangles = 3;

namespace {

// How many times a face left without a triangle is tried again at a quarter of the tolerance.
constexpr int kLostFaceRounds = 3;

// tessellateModel in the model's own coordinates (Model::origin), the tolerance checked
TessellationResult tessellateNearOrigin(const Model& model, const TessellationOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    // A lone face (LoneFaces.hpp) whose region is its whole frame box is tessellated again on
    // its own with its free edges as its curve uses: no trimming share, the cells at its border
    // bounded for corners on their sides, but the points its cells cut on its free chords stay
    // on the curve, where the first tessellation drops them from the chord. Which has fewer
    // open edges depends on how evenly the surface bends along those chords: OpenCASCADE's
    // face1.brep (a bent rectangle) at relative 1e-3 takes 50 instead of 63 (BRepMesh at the
    // same deflection: 58), an open cylinder of FreeCAD's FEM tests at 1e-4 112 instead of 151
    // (BRepMesh: 140); the generated revolved_profile.brep, whose small end circles would carry
    // the columns of its bulge, 133 instead of 55. The one with fewer open edges is kept, then
    // the one with fewer triangles. Only a face whose first mesh is mostly its border is tried
    // (at most kBorderShare triangles per open edge: a strip a few cells wide), where the
    // columns that cut its free edges are about the ones its surface needs there; inside a
    // larger face they are spaced for its most bent part, and the second tessellation, which
    // costs about as much as the first (MAT.brep at relative 1e-3: 0.4 s more), never won on
    // the sample models (MAT.brep: 15,976 triangles and 244 open edges at 1e-3, 446 on the
    // second try; the revolved profile: 5,983 and 55, 133).
    // the faces a result lists as failed (the lone faces' retries list none)
    auto failedFaces = [&](const TessellationResult& result) {
        std::vector<char> failed(model.faces.size(), 0);
        for (const auto& failure : result.failures)
            if (failure.face >= 1 && failure.face <= static_cast<int>(failed.size()))
                failed[failure.face - 1] = 1;
        return failed;
    };
    // the faces' Bezier patches and surface needs, for both tessellations of the model and the
    // lone faces' retries
    const FaceSurfaceCache surfaces(model);
    auto retryLoneFaces = [&](TessellationResult& result) {
        if (options.mode != ErrorMode::Guaranteed || !options.retryLoneFaces ||
            !options.freeEdgesTakeSurfaceShare || options.keepFaceVertices)
            return;
        const std::vector<char> failed = failedFaces(result);
        TessellationOptions alone = options;
        alone.progress = nullptr;
        for (const int f : loneBoxFaces(model, kExactEdge * options.tolerance)) {
            if (failed[f]) continue;
            const std::size_t before = faceOpenEdges(result.mesh, f + 1);
            const std::size_t trianglesBefore = static_cast<std::size_t>(std::count(
                result.mesh.triangleFaces.begin(), result.mesh.triangleFaces.end(), f + 1));
            if (trianglesBefore > kBorderShare * before) continue;
            const Model lone = loneFaceModel(model, f);
            FaceSurfaceCache loneSurfaces(lone);
            try {
                loneSurfaces.take(0, surfaces, f);
            } catch (const std::exception&) {
                // the retry makes its own, and says what is wrong with the face
            }
            TessellationResult retried =
                tessellateOnce(lone, alone, true, before, {}, nullptr, nullptr, &loneSurfaces);
            if (!retried.failures.empty()) continue;
            const std::size_t after = faceOpenEdges(retried.mesh, 1);
            if (after < before ||
                (after == before && retried.mesh.triangles.size() < trianglesBefore))
                replaceFaceTriangles(result.mesh, f + 1, retried.mesh);
        }
    };
    std::vector<std::size_t> freeSegments;
    FirstTessellationMemo kept;
    FirstTessellationMemo* const memo = options.reuseFirstTessellation ? &kept : nullptr;
    TessellationResult result =
        tessellateOnce(model, options, false, 0, {}, &freeSegments, memo, &surfaces);
    retryLoneFaces(result);
    // A face whose free chords keep more than a tenth more open edges than their segments
    // (points that cell sides left on them and the removal could not drop) is tessellated
    // again with its cells at those chords bounded to half the surface share
    // (FaceTessellator::kFreeChordTarget), which leaves the removal the other half of their
    // share (Leaf::slack). The model's second mesh (its lone faces retried as above) is kept
    // where it drops a larger share of the open edges than it adds of triangles: OpenCASCADE's
    // MAT.brep (one face of 77 x 80 spans, four free edges) at relative 1e-3 takes 11,324
    // triangles and 146 open edges instead of 10,470 and 216 (BRepMesh at the same deflection:
    // 8,060 and 196), at 1e-4 80,187 and 455 instead of 78,074 and 726 (91,762 and 512).
    if (options.mode == ErrorMode::Guaranteed && options.refineAtFreeChords &&
        options.freeEdgesTakeSurfaceShare && freeSegments.size() == model.faces.size() &&
        std::any_of(freeSegments.begin(), freeSegments.end(),
                    [](std::size_t n) { return n > 0; })) {
        // (a model without free edges skips the count of its open edges: a map of every side)
        const std::vector<std::size_t> openByFace =
            meshOpenEdgesByFace(result.mesh, model.faces.size());
        std::vector<char> refine(model.faces.size(), 0);
        for (std::size_t f = 0; f < model.faces.size(); ++f) {
            refine[f] = freeSegments[f] > 0 &&
                        double(openByFace[f]) > kUndroppedShare * double(freeSegments[f]);
            // a refined face takes other cells: its kept ones would only hold memory
            if (refine[f] && f < kept.trees.faces.size()) kept.trees.faces[f] = {};
        }
        if (std::find(refine.begin(), refine.end(), 1) != refine.end()) {
            TessellationResult refined =
                tessellateOnce(model, options, false, 0, refine, nullptr, memo, &surfaces);
            retryLoneFaces(refined);
            auto sum = [](const std::vector<std::size_t>& counts) {
                return double(std::accumulate(counts.begin(), counts.end(), std::size_t(0)));
            };
            const double open = sum(openByFace);
            const double fewerOpen =
                open - sum(meshOpenEdgesByFace(refined.mesh, model.faces.size()));
            const double triangles = double(result.mesh.triangles.size());
            const double moreTriangles = double(refined.mesh.triangles.size()) - triangles;
            // Where it brings the open edges down to about the free segments, it may take up to
            // kRefinedTriangles times the triangles: a twisted face's rims need many more
            // (the ruled face of OpenEdges.TwistedRimsAreCutAlongTheirChords at 1e-3).
            const bool reachesSegments = open - fewerOpen <= kUndroppedShare * sum(freeSegments) &&
                                         moreTriangles <= (kRefinedTriangles - 1) * triangles;
            if (refined.failures.size() <= result.failures.size() && fewerOpen > 0 &&
                (fewerOpen / open >= moreTriangles / triangles || reachesSegments))
                result = std::move(refined);
        }
    }
    // A tolerance about the size of a face can leave it no triangle: a sphere of radius 1 beside
    // a box of 300 at relative 1e-2 (the workbench's coarsest level), its seam one chord and its
    // cells' corners all on its poles. A finer mesh keeps the tolerance as well: such a face is
    // tessellated again on its own at a quarter of it, then a sixteenth and a sixty-fourth,
    // until it has triangles. Its edges are then its own: where it shares one, the seam shows as
    // open edges, but the face is there.
    if (!options.keepFaceVertices)
        for (FaceFailure& failure : result.failures) {
            if (failure.reason != kNoTriangleLeft) continue;
            const int f = failure.face - 1;
            const Model lone = loneFaceModel(model, f);
            TessellationOptions finer = options;
            finer.progress = nullptr;
            for (int round = 0; round < kLostFaceRounds; ++round) {
                finer.tolerance *= 0.25;
                const TessellationResult alone = tessellateOnce(lone, finer, false);
                if (!alone.failures.empty() || alone.mesh.triangles.empty()) continue;
                replaceFaceTriangles(result.mesh, f + 1, alone.mesh);
                failure.reason.clear();
                break;
            }
        }
    std::erase_if(result.failures,
                  [](const FaceFailure& failure) { return failure.reason.empty(); });
    const std::vector<char> failed = failedFaces(result);
    // single-precision readers of the mesh measure needles right (LargestAngleFirst.hpp)
    startAtLargestAngle(result.mesh);
    for (size_t f = 0; f < model.faces.size(); ++f)
        if (!model.faces[f].warning.empty() && !failed[f])
            result.warnings.push_back({static_cast<int>(f) + 1, model.faces[f].warning});
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace

TessellationResult tessellateModel(const Model& model, const TessellationOptions& options) {
    if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
        throw std::invalid_argument("the tolerance must be a positive number, not " +
                                    std::to_string(options.tolerance));
    // Placing the mesh at the model's origin rounds each coordinate by up to half a unit in its
    // last place, a point by sqrt(3) / 2 of it: a far model's faces are meshed within what is
    // left of the tolerance, so that the written mesh keeps it. Where rounding would take more
    // than half, doubles cannot hold the tolerance so far from the world's origin.
    const double diagonal =
        std::isfinite(model.boundingBoxDiagonal) ? model.boundingBoxDiagonal : 0;
    const double magnitude = model.origin.cwiseAbs().maxCoeff() + diagonal;
    const double rounding =
        0.5 * std::sqrt(3.0) * std::numeric_limits<double>::epsilon() * magnitude;
    auto refuse = [&](const std::string& reason) {
        std::ostringstream message;
        message << std::setprecision(3) << "the tolerance " << options.tolerance << " is "
                << reason;
        throw std::invalid_argument(message.str());
    };
    if (diagonal > 0 && diagonal < kSmallestModel) {
        std::ostringstream message;
        message << std::setprecision(3) << "the model is only " << diagonal
                << " across: OpenCASCADE takes points within 1e-7 of each other for one (its "
                   "confusion distance), so its faces cannot be told apart; scale it up";
        throw std::invalid_argument(message.str());
    }
    if (options.tolerance < kFinestRelativeTolerance * diagonal) {
        std::ostringstream reason;
        reason << std::setprecision(3) << "finer than " << kFinestRelativeTolerance * diagonal
               << ", " << kFinestRelativeTolerance << " of the model's diagonal (" << diagonal
               << "): the mesh would take tens of millions of triangles or more";
        refuse(reason.str());
    }
    if (rounding > 0.5 * options.tolerance) {
        std::ostringstream reason;
        reason << std::setprecision(3) << "finer than the model's coordinates can hold: they reach "
               << magnitude << " and round by up to " << rounding;
        refuse(reason.str());
    }
    if (model.origin.isZero()) return tessellateNearOrigin(model, options);
    TessellationOptions nearOrigin = options;
    nearOrigin.tolerance = options.tolerance - rounding;
    TessellationResult result = tessellateNearOrigin(model, nearOrigin);
    result.tolerance = options.tolerance;
    for (Point3& position : result.mesh.positions) position += model.origin;
    for (FaceVertexSet& set : result.faceVertices)
        for (Point3& position : set.positions) position += model.origin;
    return result;
}

}  // namespace nurbslod
