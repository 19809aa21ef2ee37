#pragma once

#include <BSplSLib_Cache.hxx>
#include <Geom_BSplineSurface.hxx>
#include <array>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace nurbslod::occ {

// A B-spline surface's point and first derivatives through the power-basis cache of the span
// last asked for (BSplSLib_Cache), rebuilt when a parameter leaves it. GeomAdaptor_Surface::D1
// caches the same way except on a knot line, where it redoes de Boor's algorithm
// (Geom_BSplineSurface::LocalD1, six times the cost): the projections that remake pcurves start
// and end on knot lines wherever an edge runs along a span's border, as every edge along a
// surface's boundary does (a third of trj7_b1-ec-214.stp's projections' time). On a knot line
// the span on one side is taken: both give the same point, and the same derivatives where the
// surface is C1 there; a projection's Newton steps need only a tangent plane, which a C0 knot
// line (a kink) has on either side.
//
// A few spans are held at once, the one used longest ago rebuilt: a pcurve's projections and
// the checks of its interpolant between them go back and forth between neighbouring spans
// (rebuilding one cache was an eighth of hammer.iges's import).
class SurfaceSpanCache {
public:
    explicit SurfaceSpanCache(const Handle(Geom_BSplineSurface) & surface);
    gp_Pnt value(double u, double v) const;
    void firstDerivatives(double u, double v, gp_Pnt& point, gp_Vec& du, gp_Vec& dv) const;

private:
    static constexpr int kHeldSpans = 4;
    const BSplSLib_Cache& spanOf(double u, double v) const;

    Handle(Geom_BSplineSurface) surface_;
    struct HeldSpan {
        Handle(BSplSLib_Cache) cache;
        bool built = false;
        long lastUse = 0;
    };
    mutable std::array<HeldSpan, kHeldSpans> spans_;
    mutable long uses_ = 0;
};

}  // namespace nurbslod::occ
