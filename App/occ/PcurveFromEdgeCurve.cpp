#include "occ/PcurveFromEdgeCurve.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_map>
#include <vector>

#include "occ/SurfaceSpanCache.hpp"

namespace nurbslod::occ {

namespace {

// A point where one derivative is this much shorter than the other is taken as on a pole.
constexpr double kPoleRatio = 1e-4;
// How far (as a fraction of the surface's domain) a projection may move a pcurve point.
constexpr double kLargestSlide = 0.25;
// The share of the accuracy that a remade pcurve meets between its samples: 3e-8 of the model's
// diagonal with the importer's accuracy, 3e-4 of the finest tolerance the benchmarks ask for.
// A hundredth took a tenth more of trj7_b1-ec-214.stp's import (0.137 s instead of 0.127) and a
// sixth more of hammer.iges's, and 78 more triangles over 496 corpus and sample runs; a tenth
// left 4 open edges in CAP_50SGV_8_10.stp at relative 1e-4, where there were none.
constexpr double kFitShare = 0.03;
// The first samples split each smooth piece of the 3D curve into this many segments. Most
// edges are one cubic piece, whose pcurve a cubic through 9 samples follows to kFitShare; the
// refinement adds samples only where the midpoints miss. 32 even segments cost trj7_b1-ec-
// 214.stp 72,800 projections over 1,059 pcurves (8: 29,000), most of them never needed.
constexpr int kSegmentsPerPiece = 8;
constexpr int kLargestFirstSamples = 256;

// The surface's point and first derivatives at one (u, v).
struct SurfaceFirstDerivatives {
    gp_Pnt point;
    gp_Vec du, dv;
};

// The (u, v) of the surface point nearest to `point`, by Gauss-Newton steps from `start`, where
// the surface's derivatives are `atStart` (the caller has them already), staying within the
// parameter box [u0, u1] x [v0, v1]. The derivatives come through a span cache:
// Geom_BSplineSurface::D1 would redo de Boor's algorithm at every step (40% of a STEP model's
// import).
gp_Pnt2d projectNear(const SurfaceSpanCache& surface, double u0, double u1, double v0, double v1,
                     const gp_Pnt& point, gp_Pnt2d start, const SurfaceFirstDerivatives& atStart) {
    double u = start.X(), v = start.Y();
    for (int iteration = 0; iteration < 50; ++iteration) {
        gp_Pnt p = atStart.point;
        gp_Vec du = atStart.du, dv = atStart.dv;
        if (iteration > 0) surface.firstDerivatives(u, v, p, du, dv);
        const gp_Vec r(p, point);
        const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv);
        const double ru = du.Dot(r), rv = dv.Dot(r);
        const double det = a * c - b * b;
        if (!(std::abs(det) > 1e-300)) break;
        const double stepU = (c * ru - b * rv) / det, stepV = (a * rv - b * ru) / det;
        if (!std::isfinite(stepU) || !std::isfinite(stepV)) break;
        const double nextU = std::clamp(u + stepU, u0, u1), nextV = std::clamp(v + stepV, v0, v1);
        // Converged once the step is rounding noise: near an off-surface point (a sloppy
        // edge's 3D curve) the steps of a converged projection keep swinging by a few 1e-15
        // (trj7_b1-ec-214.stp: a fifth of its 74,000 projections took all 50 steps, two thirds
        // of its import's time). A step of 1e-12 of the parameters moves the point by far less
        // than any tolerance; the quadratic convergence before it makes the last steps tiny.
        const bool converged =
            std::abs(nextU - u) + std::abs(nextV - v) < 1e-12 * (1 + std::abs(u) + std::abs(v));
        u = nextU;
        v = nextV;
        if (converged) break;
    }
    // A foot within rounding of the box's border is on it: an edge along the surface's border
    // (a seam, a boundary circle) then keeps its parameter exactly, as the tessellator's tests of
    // loops along a cell's side expect. Which side the steps end on is a matter of the last bits
    // of the derivatives (generated filleted_box.brep at relative 1e-4: 12,730 triangles without
    // this, 11,528 with it).
    auto onBorder = [](double x, double low, double high) {
        const double within = 1e-12 * (1 + std::abs(low) + std::abs(high));
        if (std::abs(x - low) <= within) return low;
        if (std::abs(x - high) <= within) return high;
        return x;
    };
    return {onBorder(u, u0, u1), onBorder(v, v0, v1)};
}

// The straight B-spline of degree 1 from a at `first` to b at `last`.
Handle(Geom2d_BSplineCurve)
    lineOver(const gp_Pnt2d& a, const gp_Pnt2d& b, double first, double last) {
    TColgp_Array1OfPnt2d poles(1, 2);
    poles(1) = a, poles(2) = b;
    TColStd_Array1OfReal ends(1, 2);
    ends(1) = first, ends(2) = last;
    TColStd_Array1OfInteger multiplicities(1, 2);
    multiplicities(1) = multiplicities(2) = 2;
    return new Geom2d_BSplineCurve(poles, ends, multiplicities, 1);
}

// The interpolant has a knot at every sample. Where the pcurve is a line in the edge parameter
// (a circle's pcurve on a surface whose rational arcs match the edge's: u = s), a line of
// degree 1 replaces it: the 3D curve on the surface then keeps the surface's degree, and the
// edge discretiser needs no span per sample. A B-spline is a linear function exactly when each
// pole is that function at its Greville abscissa (the mean of the degree knots after it).
Handle(Geom2d_BSplineCurve) asLineWherePossible(const Handle(Geom2d_BSplineCurve) & curve) {
    if (curve->IsRational()) return curve;
    const int n = curve->NbPoles(), degree = curve->Degree();
    TColStd_Array1OfReal knots(1, n + degree + 1);
    curve->KnotSequence(knots);
    const double first = curve->FirstParameter(), last = curve->LastParameter();
    const gp_Pnt2d a = curve->Value(first), b = curve->Value(last);
    double extent = 0;
    for (int i = 1; i <= n; ++i)
        extent = std::max({extent, std::abs(curve->Pole(i).X()), std::abs(curve->Pole(i).Y())});
    const double tolerance = 1e-10 * std::max(1.0, extent);
    for (int i = 1; i <= n; ++i) {
        double greville = 0;
        for (int k = i + 1; k <= i + degree; ++k) greville += knots(k);
        const double s = (greville / degree - first) / (last - first);
        if (curve->Pole(i).Distance(gp_Pnt2d(a.XY() + s * (b.XY() - a.XY()))) > tolerance)
            return curve;
    }
    return lineOver(a, b, first, last);
}

// The line from a to b over [first, last], where the surface maps it onto `curve` within
// `within` at 63 evenly spaced parameters between the ends (the middle first: most curves that
// are not such a line fail there); none otherwise.
Handle(Geom2d_BSplineCurve)
    lineThroughEnds(const std::function<gp_Pnt(double)>& curve, const SurfaceSpanCache& surface,
                    double first, double last, const gp_Pnt2d& a, const gp_Pnt2d& b,
                    double within) {
    if (!(last > first) || !std::isfinite(a.X()) || !std::isfinite(a.Y()) ||
        !std::isfinite(b.X()) || !std::isfinite(b.Y()))
        return {};
    constexpr int kChecks = 64;
    auto mapsOnto = [&](int k) {
        const double s = double(k) / kChecks;
        const gp_Pnt2d uv(a.XY() + s * (b.XY() - a.XY()));
        return surface.value(uv.X(), uv.Y()).Distance(curve(first + (last - first) * s)) <= within;
    };
    try {
        OCC_CATCH_SIGNALS
        if (!mapsOnto(kChecks / 2)) return {};
        for (int k = 1; k < kChecks; ++k)
            if (k != kChecks / 2 && !mapsOnto(k)) return {};
    } catch (const Standard_Failure&) {
        return {};  // a curve the surface cannot take: the interpolation decides
    }
    return lineOver(a, b, first, last);
}

}  // namespace

bool pcurveFollowsEdge(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                       const Handle(Geom2d_Curve) & pcurve, double first, double last,
                       double within) {
    // the adaptors evaluate through their span caches; the B-splines' own Value redoes de
    // Boor's algorithm at every sample (2% of trj7_b1-ec-214.stp's whole run)
    const BRepAdaptor_Curve curve(edge);
    const GeomAdaptor_Surface onSurface(surface);
    const Geom2dAdaptor_Curve inParameters(pcurve);
    // The middle first, then the quarters, eighths, sixteenths and the ends: a pcurve that
    // strays (most of a sloppy file's: trj7_b1-ec-214.stp remakes 1,059) shows it at the first
    // few, and the rest are not measured.
    constexpr int kSamples = 16;
    auto followsAt = [&](int k) {
        const double t = first + (last - first) * k / kSamples;
        const gp_Pnt2d uv = inParameters.Value(t);
        return onSurface.Value(uv.X(), uv.Y()).Distance(curve.Value(t)) <= within;
    };
    for (int step = kSamples / 2; step >= 1; step /= 2)
        for (int k = step; k < kSamples; k += 2 * step)
            if (!followsAt(k)) return false;
    return followsAt(0) && followsAt(kSamples);
}

Handle(Geom2d_BSplineCurve)
    pcurveFromEdgeCurve(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                        const Handle(Geom2d_Curve) & guess, double first, double last,
                        double accuracy) {
    const BRepAdaptor_Curve curve(edge);
    return pcurveFromCurve([&](double t) { return curve.Value(t); }, surface,
                           [&](double t) { return guess->Value(t); }, first, last, accuracy,
                           smoothnessBreaks(curve, first, last));
}

std::vector<double> smoothnessBreaks(const Adaptor3d_Curve& curve, double first, double last) {
    const int count = curve.NbIntervals(GeomAbs_C2);
    std::vector<double> breaks;
    if (count < 2) return breaks;
    TColStd_Array1OfReal ends(1, count + 1);
    curve.Intervals(ends, GeomAbs_C2);
    for (int i = 2; i <= count; ++i)
        if (ends(i) > first && ends(i) < last) breaks.push_back(ends(i));
    return breaks;
}

Handle(Geom2d_BSplineCurve)
    pcurveFromCurve(const std::function<gp_Pnt(double)>& curve,
                    const Handle(Geom_BSplineSurface) & surface,
                    const std::function<gp_Pnt2d(double)>& guess, double first, double last,
                    double accuracy, std::vector<double> breaks) {
    // A projection far from the guess in (u, v) is no correction but a slide along a pole or a
    // jump to another sheet: the pcurve is then kept as it was (nothing is returned).
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    const double reachU = kLargestSlide * (u1 - u0), reachV = kLargestSlide * (v1 - v0);
    const SurfaceSpanCache spans(surface);
    bool slid = false;
    // each round's midpoints are the next round's samples: projected once
    struct Projection {
        gp_Pnt2d uv;
        gp_Pnt point;
        bool evaluated = false;
    };
    std::unordered_map<double, Projection> projections;
    auto project = [&](double t) {
        const gp_Pnt2d start = guess(t);
        const gp_Pnt point = curve(t);
        // At a pole (a row of poles collapsed to a point) a projection would slide freely along
        // the row: the guess stays there.
        SurfaceFirstDerivatives atStart;
        spans.firstDerivatives(start.X(), start.Y(), atStart.point, atStart.du, atStart.dv);
        const double shorter = std::min(atStart.du.Magnitude(), atStart.dv.Magnitude());
        const double longer = std::max(atStart.du.Magnitude(), atStart.dv.Magnitude());
        if (!(shorter > kPoleRatio * longer)) return start;
        const gp_Pnt2d foot = projectNear(spans, u0, u1, v0, v1, point, start, atStart);
        if (!(std::abs(foot.X() - start.X()) <= reachU && std::abs(foot.Y() - start.Y()) <= reachV))
            slid = true;
        return foot;
    };
    auto projectionAt = [&](double t) -> Projection& {
        auto known = projections.find(t);
        if (known == projections.end())
            known = projections.emplace(t, Projection{project(t), gp_Pnt(), false}).first;
        return known->second;
    };
    auto sampleAt = [&](double t) { return projectionAt(t).uv; };
    // the surface point of a projection, evaluated once: a midpoint whose interval is not
    // refined is compared again in the next round
    auto surfacePointOf = [&](Projection& projection) {
        if (!projection.evaluated) {
            projection.point = spans.value(projection.uv.X(), projection.uv.Y());
            projection.evaluated = true;
        }
        return projection.point;
    };
    // Samples are added where the interpolant misses, not everywhere: the pcurve of a circle's
    // or a helix's edge on a surface's rational form has a kink in its speed wherever it
    // crosses a knot of the surface (the arcs' joints), and a cubic's error there only falls
    // with the square of the spacing; uniform doubling would spend the samples on the smooth
    // stretches (and was capped before reaching the accuracy on bottle.brep's thread alone).
    constexpr size_t kMostSamples = 4096;
    // A curve whose pcurve is a line in its parameter (a circle on a cylinder, a cone or a torus
    // whose rational arcs match the edge's: u = s, v fixed) is that line through its ends'
    // projections wherever the surface maps it onto the curve, checked at 63 points between
    // them: bottle.brep's import made 206 of its 214 remade pcurves so, bug33398.step's 995 of
    // 1,373, each from 65 or more projections and an interpolant that came out a line anyway.
    if (const auto line = lineThroughEnds(curve, spans, first, last, sampleAt(first),
                                          sampleAt(last), 1e-4 * accuracy);
        line && !slid)
        return line;
    std::erase_if(breaks, [&](double t) { return !(t > first && t < last); });
    std::sort(breaks.begin(), breaks.end());
    breaks.push_back(last);
    // a curve of many pieces takes fewer samples on each (two at least), as the refinement
    // starts from 256 segments at most where it can
    const int segments =
        std::clamp(kLargestFirstSamples / static_cast<int>(breaks.size()), 2, kSegmentsPerPiece);
    std::vector<double> parameters{first};
    for (const double end : breaks) {
        const double start = parameters.back();
        for (int k = 1; k <= segments; ++k)
            parameters.push_back(k == segments ? end : start + (end - start) * k / segments);
    }
    double previousWorst = std::numeric_limits<double>::infinity();
    while (true) {
        const int count = static_cast<int>(parameters.size());
        Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, count);
        Handle(TColStd_HArray1OfReal) knots = new TColStd_HArray1OfReal(1, count);
        for (int k = 0; k < count; ++k) {
            knots->SetValue(k + 1, parameters[k]);
            points->SetValue(k + 1, sampleAt(parameters[k]));
        }
        if (slid) return {};
        Handle(Geom2d_BSplineCurve) result;
        try {
            OCC_CATCH_SIGNALS
            Geom2dAPI_Interpolate interpolate(points, knots, Standard_False, 1e-15);
            interpolate.Perform();
            if (!interpolate.IsDone()) return {};
            result = interpolate.Curve();
        } catch (const Standard_Failure&) {
            return {};  // samples that coincide (a curve that stands still): keep the guess
        }
        // the interpolant against the projections between its samples
        double worst = 0;
        std::vector<double> refined{parameters.front()};
        const Geom2dAdaptor_Curve fittedCurve(result);  // evaluates through its span cache
        for (int k = 0; k + 1 < count; ++k) {
            const double t = 0.5 * (parameters[k] + parameters[k + 1]);
            Projection& projected = projectionAt(t);
            const gp_Pnt2d fitted = fittedCurve.Value(t);
            const double miss =
                spans.value(fitted.X(), fitted.Y()).Distance(surfacePointOf(projected));
            worst = std::max(worst, miss);
            if (miss > kFitShare * accuracy && t > parameters[k] && t < parameters[k + 1])
                refined.push_back(t);
            refined.push_back(parameters[k + 1]);
        }
        // kFitShare of the accuracy asked for is far below any tolerance; a curve that does not
        // get there (a kink in the 3D curve) is kept if it is within the accuracy itself, as
        // soon as more samples stop bringing it closer
        if (worst <= kFitShare * accuracy) return asLineWherePossible(result);
        if (worst <= accuracy && worst > 0.5 * previousWorst) return asLineWherePossible(result);
        if (refined.size() > kMostSamples || refined.size() == parameters.size())
            return worst <= accuracy ? asLineWherePossible(result) : Handle(Geom2d_BSplineCurve)();
        previousWorst = worst;
        parameters = std::move(refined);
    }
}

}  // namespace nurbslod::occ
