#include "occ/SurfaceSpanCache.hpp"

namespace nurbslod::occ {

SurfaceSpanCache::SurfaceSpanCache(const Handle(Geom_BSplineSurface) & surface)
    : surface_(surface),
      cache_(new BSplSLib_Cache(
          surface->UDegree(), surface->IsUPeriodic(), surface->UKnotSequence(), surface->VDegree(),
          surface->IsVPeriodic(), surface->VKnotSequence(), surface->Weights())) {}

void SurfaceSpanCache::holdSpanOf(double u, double v) const {
    if (built_ && cache_->IsCacheValid(u, v)) return;
    cache_->BuildCache(u, v, surface_->UKnotSequence(), surface_->VKnotSequence(),
                       surface_->Poles(), surface_->Weights());
    built_ = true;
}

gp_Pnt SurfaceSpanCache::value(double u, double v) const {
    holdSpanOf(u, v);
    gp_Pnt point;
    cache_->D0(u, v, point);
    return point;
}

void SurfaceSpanCache::firstDerivatives(double u, double v, gp_Pnt& point, gp_Vec& du,
                                        gp_Vec& dv) const {
    holdSpanOf(u, v);
    cache_->D1(u, v, point, du, dv);
}

}  // namespace nurbslod::occ
