#include "occ/SurfaceSpanCache.hpp"

namespace nurbslod::occ {

SurfaceSpanCache::SurfaceSpanCache(const Handle(Geom_BSplineSurface) & surface)
    : surface_(surface) {}

const BSplSLib_Cache& SurfaceSpanCache::spanOf(double u, double v) const {
    ++uses_;
    HeldSpan* oldest = &spans_[0];
    for (HeldSpan& span : spans_) {
        if (span.built && span.cache->IsCacheValid(u, v)) {
            span.lastUse = uses_;
            return *span.cache;
        }
        if (!span.built || (oldest->built && span.lastUse < oldest->lastUse)) oldest = &span;
    }
    // made when first needed: most surfaces' pcurves stay in one or two spans
    if (oldest->cache.IsNull())
        oldest->cache = new BSplSLib_Cache(surface_->UDegree(), surface_->IsUPeriodic(),
                                           surface_->UKnotSequence(), surface_->VDegree(),
                                           surface_->IsVPeriodic(), surface_->VKnotSequence(),
                                           surface_->Weights());
    oldest->cache->BuildCache(u, v, surface_->UKnotSequence(), surface_->VKnotSequence(),
                              surface_->Poles(), surface_->Weights());
    oldest->built = true;
    oldest->lastUse = uses_;
    return *oldest->cache;
}

gp_Pnt SurfaceSpanCache::value(double u, double v) const {
    gp_Pnt point;
    spanOf(u, v).D0(u, v, point);
    return point;
}

void SurfaceSpanCache::firstDerivatives(double u, double v, gp_Pnt& point, gp_Vec& du,
                                        gp_Vec& dv) const {
    spanOf(u, v).D1(u, v, point, du, dv);
}

}  // namespace nurbslod::occ
