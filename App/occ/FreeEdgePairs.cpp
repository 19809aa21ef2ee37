#include "occ/FreeEdgePairs.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "geometry/NearestParameter.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/NearIsoparametricCurve.hpp"
#include "occ/PcurveFromEdgeCurve.hpp"
#include "tessellate/ForEachIndex.hpp"

namespace nurbslod::occ {

namespace {

// Samples along a free edge: its ends, the points between them that a partner must pass
// near, and a finer polygon for finding the nearest point of the curve.
struct EdgeSamples {
    TopoDS_Edge edge;
    int face = 0;
    gp_Pnt start, end;
    std::array<gp_Pnt, 3> inner;  // at a quarter, half and three quarters of the parameter
    std::vector<double> parameters;
    std::vector<gp_Pnt> polygon;
};

constexpr int kPolygonPoints = 32;

EdgeSamples samplesOf(const TopoDS_Edge& edge, int face) {
    EdgeSamples samples{edge, face, {}, {}, {}, {}, {}};
    const BRepAdaptor_Curve curve(edge);
    const double first = curve.FirstParameter(), last = curve.LastParameter();
    samples.start = curve.Value(first);
    samples.end = curve.Value(last);
    for (int k = 0; k < 3; ++k)
        samples.inner[k] = curve.Value(first + (last - first) * (k + 1) / 4);
    for (int k = 0; k <= kPolygonPoints; ++k) {
        const double t = first + (last - first) * k / kPolygonPoints;
        samples.parameters.push_back(t);
        samples.polygon.push_back(curve.Value(t));
    }
    return samples;
}

// The distance from `point` to the edge's curve (nearestParameter from its polygon). The curve
// is known to run within a tolerance of the point's own edge; this only has to tell that from a
// curve that does not.
double distanceToCurve(const EdgeSamples& samples, const BRepAdaptor_Curve& curve,
                       const gp_Pnt& point) {
    std::vector<double> sampled;
    for (const gp_Pnt& p : samples.polygon) sampled.push_back(p.SquareDistance(point));
    auto distance2 = [&](double t) { return curve.Value(t).SquareDistance(point); };
    return std::sqrt(distance2(nearestParameter(samples.parameters, sampled, distance2)));
}

bool sameEdge(const EdgeSamples& a, const EdgeSamples& b, double tolerance) {
    if (a.face == b.face) return false;
    const bool along = a.start.Distance(b.start) <= tolerance && a.end.Distance(b.end) <= tolerance;
    const bool against =
        a.start.Distance(b.end) <= tolerance && a.end.Distance(b.start) <= tolerance;
    if (!along && !against) return false;
    const BRepAdaptor_Curve curveA(a.edge), curveB(b.edge);
    for (const gp_Pnt& p : a.inner)
        if (!(distanceToCurve(b, curveB, p) <= tolerance)) return false;
    for (const gp_Pnt& p : b.inner)
        if (!(distanceToCurve(a, curveA, p) <= tolerance)) return false;
    return true;
}

}  // namespace

namespace {

// The free edges of the shape, each with the one face it bounds.
std::vector<std::pair<TopoDS_Edge, TopoDS_Face>> freeEdgesWithFaces(const TopoDS_Shape& shape) {
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    std::vector<std::pair<TopoDS_Edge, TopoDS_Face>> result;
    for (int i = 1; i <= facesOfEdge.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(facesOfEdge.FindKey(i));
        if (BRep_Tool::Degenerated(edge)) continue;
        const auto& faces = facesOfEdge(i);
        if (faces.Extent() != 1) continue;
        const TopoDS_Face& face = TopoDS::Face(faces.First());
        if (!BRep_Tool::IsClosed(edge, face)) result.emplace_back(edge, face);
    }
    return result;
}

}  // namespace

std::vector<TopoDS_Edge> freeEdges(const TopoDS_Shape& shape) {
    std::vector<TopoDS_Edge> result;
    for (const auto& [edge, face] : freeEdgesWithFaces(shape)) result.push_back(edge);
    return result;
}

FreeEdgeMatch matchFreeEdges(const TopoDS_Shape& shape, double tolerance) {
    const auto free = freeEdgesWithFaces(shape);
    if (free.empty()) return {};
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    // every face with a free edge, where the edges cannot be compared (the sewing decides)
    auto allLeft = [&] {
        FreeEdgeMatch all;
        for (const auto& [edge, face] : free) all.facesLeft.push_back(faces.FindIndex(face));
        std::sort(all.facesLeft.begin(), all.facesLeft.end());
        all.facesLeft.erase(std::unique(all.facesLeft.begin(), all.facesLeft.end()),
                            all.facesLeft.end());
        return all;
    };
    if (!(tolerance > 0) || !std::isfinite(tolerance)) return allLeft();
    std::vector<EdgeSamples> edges;
    try {
        OCC_CATCH_SIGNALS
        for (const auto& [edge, face] : free)
            edges.push_back(samplesOf(edge, faces.FindIndex(face)));
    } catch (const Standard_Failure&) {
        return allLeft();  // an edge without a curve
    }
    // Partners have ends within the tolerance, so their lower x of the two ends too: sorted by
    // it, each edge's candidates are a run of neighbours.
    auto lowX = [](const EdgeSamples& e) { return std::min(e.start.X(), e.end.X()); };
    std::vector<size_t> order(edges.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t i, size_t j) { return lowX(edges[i]) < lowX(edges[j]); });
    std::vector<bool> paired(edges.size(), false);
    FreeEdgeMatch match;
    try {
        OCC_CATCH_SIGNALS
        for (size_t i = 0; i < order.size(); ++i) {
            const EdgeSamples& a = edges[order[i]];
            if (paired[order[i]]) continue;
            for (size_t j = i + 1; j < order.size() && lowX(edges[order[j]]) <= lowX(a) + tolerance;
                 ++j) {
                if (paired[order[j]] || !sameEdge(a, edges[order[j]], tolerance)) continue;
                paired[order[i]] = paired[order[j]] = true;
                match.pairs.push_back({a.edge, edges[order[j]].edge});
                break;
            }
        }
    } catch (const Standard_Failure&) {
        return allLeft();
    }
    // An edge without a pair may be sewn to edges that paired (an edge met by two shorter ones,
    // one of which has a copy too): the faces of every free edge near one without a pair are
    // left to the sewing with it. Near: their boxes, each grown by its edge's and vertices'
    // tolerances (the sewing's reach), meet.
    std::vector<size_t> unpaired;
    for (size_t i = 0; i < edges.size(); ++i)
        if (!paired[i]) unpaired.push_back(i);
    if (unpaired.empty()) return match;
    try {
        OCC_CATCH_SIGNALS
        std::vector<Bnd_Box> boxes(edges.size());
        for (size_t i = 0; i < edges.size(); ++i) {
            BRepBndLib::Add(edges[i].edge, boxes[i]);
            double reach = std::max(tolerance, BRep_Tool::Tolerance(edges[i].edge));
            for (TopExp_Explorer it(edges[i].edge, TopAbs_VERTEX); it.More(); it.Next())
                reach = std::max(reach, BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
            boxes[i].Enlarge(reach);
            // an edge with no extent in space, or none that compares (NaN)
            if (boxes[i].IsVoid() || !std::isfinite(boxes[i].CornerMin().X()) ||
                !std::isfinite(boxes[i].CornerMax().X()))
                return allLeft();
        }
        // the unpaired boxes by their least x: those that may meet a box [x0, x1] in x have theirs
        // in [x0 - widest, x1]
        auto lowestX = [&](size_t j) { return boxes[j].CornerMin().X(); };
        std::sort(unpaired.begin(), unpaired.end(),
                  [&](size_t a, size_t b) { return lowestX(a) < lowestX(b); });
        double widest = 0;
        for (size_t j : unpaired)
            widest = std::max(widest, boxes[j].CornerMax().X() - boxes[j].CornerMin().X());
        for (size_t i = 0; i < edges.size(); ++i) {
            const double x0 = boxes[i].CornerMin().X() - widest, x1 = boxes[i].CornerMax().X();
            auto j = std::lower_bound(unpaired.begin(), unpaired.end(), x0,
                                      [&](size_t k, double x) { return lowestX(k) < x; });
            for (; j != unpaired.end() && lowestX(*j) <= x1; ++j)
                if (!boxes[i].IsOut(boxes[*j])) {
                    match.facesLeft.push_back(edges[i].face);
                    break;
                }
        }
    } catch (const Standard_Failure&) {
        return allLeft();
    }
    std::sort(match.facesLeft.begin(), match.facesLeft.end());
    match.facesLeft.erase(std::unique(match.facesLeft.begin(), match.facesLeft.end()),
                          match.facesLeft.end());
    return match;
}

std::vector<FreeEdgePair> pairFreeEdges(const TopoDS_Shape& shape, double tolerance) {
    FreeEdgeMatch match = matchFreeEdges(shape, tolerance);
    if (!match.facesLeft.empty()) return {};
    return std::move(match.pairs);
}

namespace {

// The curve c(s) over [from0, from1] as a curve of t over [to0, to1], s affine in t: s = from0
// at t = to0 (from1 there where `reversed`). A B-spline's knots map as its parameter does; run
// backwards, its knots and poles also come in reverse order.
BSplineCurve2d affinelyReparametrized(const BSplineCurve2d& curve, double from0, double from1,
                                      double to0, double to1, bool reversed) {
    const double scale = (to1 - to0) / (from1 - from0);
    std::vector<double> knots = curve.knots().knots();
    std::vector<HomogeneousPoint2> poles = curve.poles();
    for (double& k : knots) k = reversed ? to0 + (from1 - k) * scale : to0 + (k - from0) * scale;
    if (reversed) {
        std::reverse(knots.begin(), knots.end());
        std::reverse(poles.begin(), poles.end());
    }
    return BSplineCurve2d(KnotVector(curve.degree(), std::move(knots)), std::move(poles));
}

}  // namespace

// The joined face's curve follows the points the kept face's mesh has on the edge; each
// projection starts from the joined face's own pcurve at the nearest parameter.
void joinFreeEdgePairs(Model& model, const std::vector<std::pair<int, int>>& pairs,
                       const std::vector<Handle(Geom_BSplineSurface)>& surfaces, double accuracy,
                       int threads) {
    if (pairs.empty()) return;
    struct CurveUse {
        int face = -1, loop = -1, curve = -1;
    };
    const int edgeCount = static_cast<int>(model.edges.size());
    std::vector<CurveUse> useOf(model.edges.size());
    std::vector<int> useCount(model.edges.size(), 0);
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
        if (!model.faces[f].error.empty()) continue;
        const auto& loops = model.faces[f].loops;
        for (int l = 0; l < static_cast<int>(loops.size()); ++l)
            for (int c = 0; c < static_cast<int>(loops[l].curves.size()); ++c) {
                const int e = loops[l].curves[c].edge;
                if (e < 0 || e >= edgeCount) continue;
                useOf[e] = {f, l, c};
                ++useCount[e];
            }
    }
    std::vector<int> root(model.vertices.size());
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](int v) {
        while (root[v] != v) v = root[v] = root[root[v]];
        return v;
    };
    auto unite = [&](int a, int b) {
        if (a < 0 || b < 0) return;
        a = find(a), b = find(b);
        if (a != b) root[b] = a;
    };
    auto toPnt = [](const Point3& p) { return gp_Pnt(p.x(), p.y(), p.z()); };
    // Each pair's new curve is made from the kept curve and the joined face's own: no pair
    // changes what another reads (the pairs' edges are distinct, and only joined curves
    // change), so they are made first, in parallel where threads allow, and put in after.
    struct Joined {
        bool made = false;
        TrimCurve curve;       // the joined face's curve along the kept edge
        bool along = true;     // the copies run the same way
        double tolerance = 0;  // the kept edge's, covering the copies' gap
    };
    std::vector<Joined> joinedCurves(pairs.size());
    auto joinPair = [&](std::size_t i) {
        const auto [kept, joined] = pairs[i];
        if (kept < 0 || joined < 0 || kept >= edgeCount || joined >= edgeCount ||
            useCount[kept] != 1 || useCount[joined] != 1)
            return;
        const CurveUse a = useOf[kept], b = useOf[joined];
        if (a.face == b.face || surfaces[b.face].IsNull()) return;
        const TrimmedSurface& faceA = model.faces[a.face];
        const TrimmedSurface& faceB = model.faces[b.face];
        const TrimCurve& curveA = faceA.loops[a.loop].curves[a.curve];
        const TrimCurve& ownCurveB = faceB.loops[b.loop].curves[b.curve];
        if (curveA.degenerated || ownCurveB.degenerated || curveA.seam || ownCurveB.seam) return;
        const std::function<Point3(double)> onA = [&](double t) {
            const Point2 uv = curveA.pcurve.point(t);
            return faceA.surface.point(uv.x(), uv.y());
        };
        const BSplineCurve2d& ownB = ownCurveB.pcurve;
        const std::function<Point3(double)> onB = [&](double s) {
            const Point2 uv = ownB.point(s);
            return faceB.surface.point(uv.x(), uv.y());
        };
        const double copyTolerance =
            std::max(model.edges[kept].tolerance, model.edges[joined].tolerance);
        constexpr int kSamples = 32;
        std::vector<Point3> pointsA;
        for (int k = 0; k <= kSamples; ++k)
            pointsA.push_back(onA(curveA.first + (curveA.last - curveA.first) * k / kSamples));
        Joined& result = joinedCurves[i];
        result.curve = ownCurveB;
        // the rest of the joined curve, once its (u, v) curve is in place
        auto finish = [&](bool along, double gap) {
            result.along = along;
            result.curve.beforeStraightening.reset();  // a curve of the face's old parameter
            result.curve.first = curveA.first;
            result.curve.last = curveA.last;
            result.curve.edge = kept;
            if (!result.along) result.curve.reversed = !result.curve.reversed;
            result.tolerance = std::max(copyTolerance, gap);
            // the new curve follows the kept one's points: along an isoparametric line of its
            // own surface to within rounding, or as near as the copies are
            straightenNearIsoparametric(faceB.surface, result.curve, result.tolerance);
            result.made = true;
        };
        // Copies written with one parameter, either way round: b's point at the affine image of
        // each of a's samples is b's nearest to a's point, to 5e-9 of b's range (no nearer
        // point 1e-8 of it to either side). b then keeps its own curve, carried onto a's
        // parameter by that map, and the pair needs neither the nearest-point searches below
        // nor a curve remade from a's points: 92 of hammer.iges's 104 pairs, whose import took
        // 35.5 ms instead of 27.2 without this.
        const double rangeB = ownCurveB.last - ownCurveB.first;
        auto affineGap = [&](bool along) -> std::optional<double> {
            const double step = 1e-8 * rangeB;
            double gap = 0;
            for (int k = 0; k <= kSamples; ++k) {
                const double f = double(k) / kSamples;
                const double at =
                    along ? ownCurveB.first + rangeB * f : ownCurveB.last - rangeB * f;
                const double there = (onB(at) - pointsA[k]).squaredNorm();
                for (const double side : {at - step, at + step})
                    if (side >= ownCurveB.first && side <= ownCurveB.last &&
                        !((onB(side) - pointsA[k]).squaredNorm() >= there))
                        return std::nullopt;
                gap = std::max(gap, std::sqrt(there));
            }
            return gap;
        };
        if (rangeB > 0 && curveA.last > curveA.first)
            for (const bool along : {true, false})
                if (const auto gap = affineGap(along)) {
                    result.curve.pcurve = affinelyReparametrized(
                        ownB, ownCurveB.first, ownCurveB.last, curveA.first, curveA.last, !along);
                    finish(along, *gap);
                    return;
                }
        // b's parameter nearest to a's points, at evenly spaced parameters of a
        std::vector<double> parametersB, nearestB;
        std::vector<Point3> polygonB;
        for (int k = 0; k <= 2 * kSamples; ++k) {
            parametersB.push_back(ownCurveB.first +
                                  (ownCurveB.last - ownCurveB.first) * k / (2 * kSamples));
            polygonB.push_back(onB(parametersB.back()));
        }
        double gap = 0;
        for (int k = 0; k <= kSamples; ++k) {
            const Point3& p = pointsA[k];
            std::vector<double> sampled;
            for (const Point3& q : polygonB) sampled.push_back((q - p).squaredNorm());
            nearestB.push_back(nearestParameter(
                parametersB, sampled, [&](double s) { return (onB(s) - p).squaredNorm(); }));
            gap = std::max(gap, (onB(nearestB.back()) - p).norm());
        }
        // the copies run the same way where b's parameter grows with a's (read between the
        // ends: a closed edge's ends are one point, either end of b)
        const bool along = nearestB[3 * kSamples / 4] > nearestB[kSamples / 4];
        // A closed copy (a circle) has both its ends nearest to a's ends: the nearest found
        // may be the wrong one, and a guess running from b's last parameter back to its first
        // over a's first step slides the projection around the whole curve (the pair then
        // stayed open: a plate's hole and a cylinder written as loose faces).
        if (polygonB.front() == polygonB.back() ||
            (polygonB.front() - polygonB.back()).norm() <= std::max(copyTolerance, gap)) {
            nearestB.front() = along ? ownCurveB.first : ownCurveB.last;
            nearestB.back() = along ? ownCurveB.last : ownCurveB.first;
        }
        const auto guess = [&](double t) {
            const double x =
                std::clamp((t - curveA.first) / (curveA.last - curveA.first), 0.0, 1.0) * kSamples;
            const int k = std::min(static_cast<int>(x), kSamples - 1);
            const double s = nearestB[k] + (x - k) * (nearestB[k + 1] - nearestB[k]);
            const Point2 uv = ownB.point(s);
            return gp_Pnt2d(uv.x(), uv.y());
        };
        Handle(Geom2d_BSplineCurve) remade;
        try {
            OCC_CATCH_SIGNALS
            remade = pcurveFromCurve([&](double t) { return toPnt(onA(t)); }, surfaces[b.face],
                                     guess, curveA.first, curveA.last, accuracy);
        } catch (const Standard_Failure&) {
            remade.Nullify();
        }
        if (!remade.IsNull()) {
            keepIsoparametric(ownB, *remade);
            result.curve.pcurve = toCurve(remade);
            finish(along, gap);
            return;
        }
        // No curve could be remade (bearing.iges: 9 of its 431 pairs, whose projections gave
        // coinciding samples to the interpolation): b keeps its own curve on the affine map
        // after all, with the tolerance of how far its points then are from a's at one
        // parameter (measured at 129 points). Where that is more than twice the copies' own
        // gap, the map is no copy's and the pair stays open.
        double mappedGap = 0;
        constexpr int kAffineSamples = 4 * kSamples;
        for (int k = 0; k <= kAffineSamples; ++k) {
            const double f = double(k) / kAffineSamples;
            const double t = curveA.first + (curveA.last - curveA.first) * f;
            const double s = along ? ownCurveB.first + rangeB * f : ownCurveB.last - rangeB * f;
            mappedGap = std::max(mappedGap, (onB(s) - onA(t)).norm());
        }
        if (!(rangeB > 0 && curveA.last > curveA.first &&
              mappedGap <= 2 * std::max(copyTolerance, gap)))
            return;
        result.curve.pcurve = affinelyReparametrized(ownB, ownCurveB.first, ownCurveB.last,
                                                     curveA.first, curveA.last, !along);
        finish(along, mappedGap);
    };
    forEachIndex(pairs.size(), threads, joinPair);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const Joined& result = joinedCurves[i];
        if (!result.made) continue;
        const auto [kept, joined] = pairs[i];
        const CurveUse b = useOf[joined];
        model.faces[b.face].loops[b.loop].curves[b.curve] = result.curve;
        ModelEdge& edge = model.edges[kept];
        const ModelEdge& copy = model.edges[joined];
        edge.tolerance = result.tolerance;
        // the copy's ends onto the kept edge's nearer ones
        unite(edge.firstVertex, result.along ? copy.firstVertex : copy.lastVertex);
        unite(edge.lastVertex, result.along ? copy.lastVertex : copy.firstVertex);
    }
    // one vertex for each set of copies, its tolerance reaching every copy's
    std::vector<double> tolerance(model.vertices.size());
    for (size_t v = 0; v < model.vertices.size(); ++v) tolerance[v] = model.vertices[v].tolerance;
    for (size_t v = 0; v < model.vertices.size(); ++v) {
        const int r = find(static_cast<int>(v));
        tolerance[r] =
            std::max(tolerance[r], model.vertices[v].tolerance +
                                       (model.vertices[v].point - model.vertices[r].point).norm());
    }
    for (size_t v = 0; v < model.vertices.size(); ++v)
        model.vertices[v].tolerance = tolerance[find(int(v))];
    for (ModelEdge& edge : model.edges) {
        if (edge.firstVertex >= 0) edge.firstVertex = find(edge.firstVertex);
        if (edge.lastVertex >= 0) edge.lastVertex = find(edge.lastVertex);
    }
}

}  // namespace nurbslod::occ
