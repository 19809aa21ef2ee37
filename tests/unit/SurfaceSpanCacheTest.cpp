// A B-spline surface evaluated through the cache of its last span (SurfaceSpanCache) agrees
// with Geom_BSplineSurface's own D1 everywhere, on knot lines and the surface's border too,
// where GeomAdaptor_Surface would redo de Boor's algorithm.
#include <gtest/gtest.h>

#include <GeomConvert.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <random>

#include "occ/SurfaceSpanCache.hpp"

namespace nurbslod {
namespace {

TEST(SurfaceSpanCache, AgreesWithTheSurfaceOnAndBetweenKnotLines) {
    // a torus's rational form: quarter arcs both ways, C1 across its knots
    const Handle(Geom_Surface) torus = new Geom_RectangularTrimmedSurface(
        new Geom_ToroidalSurface(gp_Ax3(gp::XOY()), 10.0, 3.0), 0.0, 2 * M_PI, 0.0, 2 * M_PI);
    const Handle(Geom_BSplineSurface) surface = GeomConvert::SurfaceToBSplineSurface(torus);
    ASSERT_GT(surface->NbUKnots(), 2);
    const occ::SurfaceSpanCache cache(surface);
    std::vector<std::pair<double, double>> places;
    for (int i = 1; i <= surface->NbUKnots(); ++i)
        for (int j = 1; j <= surface->NbVKnots(); ++j)
            places.push_back({surface->UKnot(i), surface->VKnot(j)});
    std::mt19937 random(7);
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    std::uniform_real_distribution<double> u(u0, u1), v(v0, v1);
    for (int k = 0; k < 200; ++k) places.push_back({u(random), v(random)});
    for (int i = 1; i <= surface->NbUKnots(); ++i) places.push_back({surface->UKnot(i), v(random)});
    for (const auto& [s, t] : places) {
        gp_Pnt expected, point;
        gp_Vec expectedU, expectedV, du, dv;
        surface->D1(s, t, expected, expectedU, expectedV);
        cache.firstDerivatives(s, t, point, du, dv);
        EXPECT_LT(point.Distance(expected), 1e-12) << s << " " << t;
        EXPECT_LT(point.Distance(cache.value(s, t)), 1e-12) << s << " " << t;
        EXPECT_LT((du - expectedU).Magnitude(), 1e-10 * expectedU.Magnitude()) << s << " " << t;
        EXPECT_LT((dv - expectedV).Magnitude(), 1e-10 * expectedV.Magnitude()) << s << " " << t;
    }
}

}  // namespace
}  // namespace nurbslod
