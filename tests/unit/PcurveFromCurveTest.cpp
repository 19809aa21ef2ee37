// Pcurves remade from an edge's 3D curve (pcurveFromCurve): a curve that a surface's straight
// (u, v) line maps onto comes out as that line of degree 1, without the interpolation; any
// other stays a cubic interpolant. Both follow the curve within the accuracy asked for.
#include <gtest/gtest.h>

#include <GeomAdaptor_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <cmath>
#include <functional>

#include "occ/PcurveFromEdgeCurve.hpp"

namespace nurbslod {
namespace {

// A cylinder of radius 5 and height 10 in its rational B-spline form (quarter arcs), and the
// edge parameter range the tests use: the middle 0.8 of its u range.
struct Cylinder {
    Handle(Geom_BSplineSurface) surface;
    double first = 0, last = 0;
    Cylinder() {
        const Handle(Geom_Surface) trimmed = new Geom_RectangularTrimmedSurface(
            new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 5.0), 0.0, 2 * M_PI, 0.0, 10.0);
        surface = GeomConvert::SurfaceToBSplineSurface(trimmed);
        double u0, u1, v0, v1;
        surface->Bounds(u0, u1, v0, v1);
        first = u0 + 0.1 * (u1 - u0);
        last = u0 + 0.9 * (u1 - u0);
    }
};

// The largest distance, at 200 parameters, between the remade pcurve on the surface and the
// curve it was made from.
double largestMiss(const Handle(Geom2d_BSplineCurve) & pcurve,
                   const Handle(Geom_BSplineSurface) & surface,
                   const std::function<gp_Pnt(double)>& curve, double first, double last) {
    double worst = 0;
    for (int k = 0; k <= 200; ++k) {
        const double s = first + (last - first) * k / 200;
        const gp_Pnt2d uv = pcurve->Value(s);
        worst = std::max(worst, surface->Value(uv.X(), uv.Y()).Distance(curve(s)));
    }
    return worst;
}

TEST(PcurveFromCurve, LineInParametersComesOutAsALine) {
    const Cylinder cylinder;
    const Handle(Geom_BSplineSurface)& surface = cylinder.surface;
    const double first = cylinder.first, last = cylinder.last;
    constexpr double accuracy = 1e-6;
    // an iso-line (a circle) and a slanted line (a helix), each from a guess a little off
    for (const double slope : {0.0, 0.4}) {
        auto uv = [&](double s) { return gp_Pnt2d(s, 2.0 + slope * (s - first)); };
        auto curve = [&](double s) {
            const gp_Pnt2d p = uv(s);
            return surface->Value(p.X(), p.Y());
        };
        auto guess = [&](double s) { return gp_Pnt2d(uv(s).X() + 1e-3, uv(s).Y() - 1e-3); };
        const Handle(Geom2d_BSplineCurve) pcurve =
            occ::pcurveFromCurve(curve, surface, guess, first, last, accuracy);
        ASSERT_FALSE(pcurve.IsNull()) << "slope " << slope;
        EXPECT_EQ(pcurve->Degree(), 1) << "slope " << slope;
        EXPECT_EQ(pcurve->NbPoles(), 2) << "slope " << slope;
        EXPECT_LE(largestMiss(pcurve, surface, curve, first, last), 1e-4 * accuracy);
    }
}

TEST(PcurveFromCurve, CurveInParametersStaysACubic) {
    const Cylinder cylinder;
    const Handle(Geom_BSplineSurface)& surface = cylinder.surface;
    const double first = cylinder.first, last = cylinder.last;
    constexpr double accuracy = 1e-6;
    // a wave in v: the line through its ends' projections is tried and refused, its middle
    // a millimetre off the curve
    auto uv = [&](double s) { return gp_Pnt2d(s, 2.0 + 0.2 * std::sin(2 * (s - first))); };
    auto curve = [&](double s) {
        const gp_Pnt2d p = uv(s);
        return surface->Value(p.X(), p.Y());
    };
    auto guess = [&](double s) { return uv(s); };
    const Handle(Geom2d_BSplineCurve) pcurve =
        occ::pcurveFromCurve(curve, surface, guess, first, last, accuracy);
    ASSERT_FALSE(pcurve.IsNull());
    EXPECT_EQ(pcurve->Degree(), 3);
    EXPECT_LE(largestMiss(pcurve, surface, curve, first, last), accuracy);
}

// A line along the surface's seam (u = u0) and one along its top circle (v = v1), each from a
// guess a rounding error off: their projections land on the border exactly, not within a bit
// of it on either side (the tessellator tests loops along a cell's side exactly).
TEST(PcurveFromCurve, ProjectionsOnTheBorderStayOnIt) {
    const Cylinder cylinder;
    const Handle(Geom_BSplineSurface)& surface = cylinder.surface;
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    struct Case {
        std::function<gp_Pnt2d(double)> uv;
        int axis;
        double border;
    };
    const Case cases[] = {{[&](double s) { return gp_Pnt2d(u0, s); }, 0, u0},
                          {[&](double s) { return gp_Pnt2d(s, v1); }, 1, v1}};
    for (const Case& c : cases) {
        const double first = c.axis == 0 ? v0 + 1 : cylinder.first;
        const double last = c.axis == 0 ? v1 - 1 : cylinder.last;
        auto curve = [&](double s) {
            const gp_Pnt2d p = c.uv(s);
            return surface->Value(p.X(), p.Y());
        };
        auto guess = [&](double s) {
            gp_Pnt2d p = c.uv(s);
            p.SetCoord(c.axis + 1, p.Coord(c.axis + 1) + (c.axis == 0 ? 1e-15 : -1e-15));
            return p;
        };
        const Handle(Geom2d_BSplineCurve) pcurve =
            occ::pcurveFromCurve(curve, surface, guess, first, last, 1e-6);
        ASSERT_FALSE(pcurve.IsNull()) << c.axis;
        for (int i = 1; i <= pcurve->NbPoles(); ++i)
            EXPECT_EQ(pcurve->Pole(i).Coord(c.axis + 1), c.border) << c.axis << " pole " << i;
    }
}

// A curve of smooth pieces (a cubic B-spline with a double knot: C1 there, C2 elsewhere) has
// its breaks at those knots, inside the range asked only.
TEST(PcurveFromCurve, SmoothnessBreaksAreTheCurvesC2Joints) {
    TColgp_Array1OfPnt poles(1, 7);
    for (int i = 1; i <= 7; ++i) poles(i) = gp_Pnt(i, (i % 2) * 0.5, 0);
    TColStd_Array1OfReal knots(1, 4);
    knots(1) = 0, knots(2) = 0.3, knots(3) = 0.6, knots(4) = 1;
    TColStd_Array1OfInteger multiplicities(1, 4);
    multiplicities(1) = multiplicities(4) = 4, multiplicities(2) = 1, multiplicities(3) = 2;
    const GeomAdaptor_Curve curve(new Geom_BSplineCurve(poles, knots, multiplicities, 3));
    // the single knot at 0.3 leaves the curve C2, the double one at 0.6 does not
    EXPECT_EQ(occ::smoothnessBreaks(curve, 0, 1), std::vector<double>{0.6});
    EXPECT_TRUE(occ::smoothnessBreaks(curve, 0.65, 1).empty());
    EXPECT_TRUE(occ::smoothnessBreaks(curve, 0, 0.6).empty());
}

// The first samples split each piece between the breaks evenly: the interpolant has a knot at
// every break (a sample there), and follows the curve within the accuracy on each piece.
TEST(PcurveFromCurve, SamplesStartAtTheBreaks) {
    const Cylinder cylinder;
    const Handle(Geom_BSplineSurface)& surface = cylinder.surface;
    const double first = cylinder.first, last = cylinder.last;
    auto uv = [&](double s) { return gp_Pnt2d(s, 2.0 + 0.2 * std::sin(3 * (s - first))); };
    auto curve = [&](double s) {
        const gp_Pnt2d p = uv(s);
        return surface->Value(p.X(), p.Y());
    };
    constexpr double accuracy = 1e-6;
    const std::vector<double> breaks{first + 0.58 * (last - first), first + 0.21 * (last - first)};
    const Handle(Geom2d_BSplineCurve) pcurve =
        occ::pcurveFromCurve(curve, surface, uv, first, last, accuracy, breaks);
    ASSERT_FALSE(pcurve.IsNull());
    EXPECT_EQ(pcurve->Degree(), 3);
    EXPECT_LE(largestMiss(pcurve, surface, curve, first, last), accuracy);
    for (const double at : breaks) {
        bool knot = false;
        for (int i = 1; i <= pcurve->NbKnots(); ++i) knot = knot || pcurve->Knot(i) == at;
        EXPECT_TRUE(knot) << "no sample at the break " << at;
    }
}

}  // namespace
}  // namespace nurbslod
