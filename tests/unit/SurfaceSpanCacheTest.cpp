// A B-spline surface evaluated through the caches of its last spans (SurfaceSpanCache) agrees
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

TEST(SurfaceSpanCache, HeldSpansGiveWhatAFreshCacheGives) {
    // back and forth over more spans than are held at once, each answer bit for bit the one
    // of a cache made for that point alone: a held span is never used for a point outside it
    const Handle(Geom_Surface) torus = new Geom_RectangularTrimmedSurface(
        new Geom_ToroidalSurface(gp_Ax3(gp::XOY()), 10.0, 3.0), 0.0, 2 * M_PI, 0.0, 2 * M_PI);
    const Handle(Geom_BSplineSurface) surface = GeomConvert::SurfaceToBSplineSurface(torus);
    const occ::SurfaceSpanCache cache(surface);
    std::mt19937 random(3);
    std::uniform_int_distribution<int> span(1, surface->NbUKnots() - 1);
    std::uniform_real_distribution<double> within(0.0, 1.0);
    for (int k = 0; k < 400; ++k) {
        const int i = span(random), j = span(random);
        const double u =
            surface->UKnot(i) + within(random) * (surface->UKnot(i + 1) - surface->UKnot(i));
        const double v =
            surface->VKnot(j) + within(random) * (surface->VKnot(j + 1) - surface->VKnot(j));
        gp_Pnt point, fresh;
        gp_Vec du, dv, freshU, freshV;
        cache.firstDerivatives(u, v, point, du, dv);
        occ::SurfaceSpanCache(surface).firstDerivatives(u, v, fresh, freshU, freshV);
        EXPECT_EQ(point.X(), fresh.X());
        EXPECT_EQ(point.Y(), fresh.Y());
        EXPECT_EQ(point.Z(), fresh.Z());
        EXPECT_EQ(du.X(), freshU.X());
        EXPECT_EQ(dv.Z(), freshV.Z());
        EXPECT_EQ(cache.value(u, v).Y(), occ::SurfaceSpanCache(surface).value(u, v).Y());
    }
}

}  // namespace
}  // namespace nurbslod
