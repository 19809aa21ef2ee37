#pragma once

#include <BSplSLib_Cache.hxx>
#include <Geom_BSplineSurface.hxx>
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
class SurfaceSpanCache {
public:
    explicit SurfaceSpanCache(const Handle(Geom_BSplineSurface) & surface);
    gp_Pnt value(double u, double v) const;
    void firstDerivatives(double u, double v, gp_Pnt& point, gp_Vec& du, gp_Vec& dv) const;

private:
    void holdSpanOf(double u, double v) const;

    Handle(Geom_BSplineSurface) surface_;
    Handle(BSplSLib_Cache) cache_;
    mutable bool built_ = false;
};

}  // namespace nurbslod::occ
