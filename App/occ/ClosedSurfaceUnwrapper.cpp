#include "occ/ClosedSurfaceUnwrapper.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <algorithm>
#include <cmath>
#include <vector>

namespace nurbslod::occ {

namespace {

// More turns than any real face winds; a pcurve that claims more is broken and stays clamped.
constexpr int kMaxCopies = 64;

// The first and last rows of poles (along u) are the same homogeneous points: the surface
// closes on itself in u and its turns can be chained.
bool closedInU(const Handle(Geom_BSplineSurface) & s) {
    const int n = s->NbUPoles();
    double size = 0;
    for (int i = 1; i <= n; ++i)
        for (int j = 1; j <= s->NbVPoles(); ++j)
            size = std::max(size, s->Pole(i, j).XYZ().Modulus());
    const double eps = 1e-12 * std::max(1.0, size);
    for (int j = 1; j <= s->NbVPoles(); ++j) {
        if (s->Pole(1, j).Distance(s->Pole(n, j)) > eps) return false;
        if (std::abs(s->Weight(1, j) - s->Weight(n, j)) > 1e-12 * s->Weight(1, j)) return false;
    }
    return true;
}

Handle(Geom_BSplineSurface)
    unwrapU(const Handle(Geom_BSplineSurface) & s, double uMin, double uMax) {
    double a, b, v0, v1;
    s->Bounds(a, b, v0, v1);
    const double period = b - a;
    if (!(period > 0) || !std::isfinite(uMin) || !std::isfinite(uMax)) return s;
    const double slack = 1e-9 * period;
    const int first = uMin < a - slack ? static_cast<int>(std::floor((uMin - a) / period)) : 0;
    const int last = uMax > b + slack ? static_cast<int>(std::ceil((uMax - b) / period)) : 0;
    if (first == 0 && last == 0) return s;
    if (s->IsUPeriodic() || !closedInU(s)) return s;
    const int copies = last - first + 1;
    if (copies > kMaxCopies) return s;

    const int degree = s->UDegree();
    const int knots = s->NbUKnots(), n = s->NbUPoles(), m = s->NbVPoles();
    std::vector<double> knotValues;
    std::vector<int> multiplicities;
    for (int c = 0; c < copies; ++c) {
        const double shift = (first + c) * period;
        for (int k = 1; k <= knots; ++k) {
            if (c > 0 && k == 1) continue;  // the joint is the previous copy's last knot
            knotValues.push_back(s->UKnot(k) + shift);
            int multiplicity = s->UMultiplicity(k);
            if (k == knots && c + 1 < copies) multiplicity = degree;  // C0 joint
            multiplicities.push_back(multiplicity);
        }
    }
    const int rows = copies * (n - 1) + 1;
    TColgp_Array2OfPnt poles(1, rows, 1, m);
    TColStd_Array2OfReal weights(1, rows, 1, m);
    for (int c = 0; c < copies; ++c)
        for (int i = (c == 0 ? 1 : 2); i <= n; ++i) {
            const int row = c * (n - 1) + i;
            for (int j = 1; j <= m; ++j) {
                poles(row, j) = s->Pole(i, j);
                weights(row, j) = s->Weight(i, j);
            }
        }
    TColStd_Array1OfReal uKnots(1, static_cast<int>(knotValues.size()));
    TColStd_Array1OfInteger uMults(1, static_cast<int>(knotValues.size()));
    for (size_t k = 0; k < knotValues.size(); ++k) {
        uKnots(static_cast<int>(k) + 1) = knotValues[k];
        uMults(static_cast<int>(k) + 1) = multiplicities[k];
    }
    TColStd_Array1OfReal vKnots(1, s->NbVKnots());
    TColStd_Array1OfInteger vMults(1, s->NbVKnots());
    s->VKnots(vKnots);
    s->VMultiplicities(vMults);
    return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, degree,
                                   s->VDegree(), Standard_False, Standard_False);
}

}  // namespace

Handle(Geom_BSplineSurface)
    unwrapClosedSurface(const Handle(Geom_BSplineSurface) & surface, double uMin, double uMax,
                        double vMin, double vMax) {
    Handle(Geom_BSplineSurface) result = unwrapU(surface, uMin, uMax);
    // v: the same on the surface with u and v exchanged
    Handle(Geom_BSplineSurface) exchanged = Handle(Geom_BSplineSurface)::DownCast(result->Copy());
    exchanged->ExchangeUV();
    Handle(Geom_BSplineSurface) unwrapped = unwrapU(exchanged, vMin, vMax);
    if (unwrapped == exchanged) return result;
    unwrapped->ExchangeUV();
    return unwrapped;
}

namespace {

// The (u, v) of the surface point nearest to `point`, by Gauss-Newton steps from `start`.
gp_Pnt2d projectNear(const Handle(Geom_BSplineSurface) & surface, const gp_Pnt& point,
                     gp_Pnt2d start) {
    double u = start.X(), v = start.Y();
    for (int iteration = 0; iteration < 50; ++iteration) {
        gp_Pnt p;
        gp_Vec du, dv;
        surface->D1(u, v, p, du, dv);
        const gp_Vec r(p, point);
        const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv);
        const double ru = du.Dot(r), rv = dv.Dot(r);
        const double det = a * c - b * b;
        if (!(std::abs(det) > 1e-300)) break;
        const double stepU = (c * ru - b * rv) / det, stepV = (a * rv - b * ru) / det;
        u += stepU;
        v += stepV;
        if (std::abs(stepU) + std::abs(stepV) < 1e-15 * (1 + std::abs(u) + std::abs(v))) break;
    }
    return {u, v};
}

}  // namespace

Handle(Geom2d_BSplineCurve)
    pcurveOnUnwrappedSurface(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                             const Handle(Geom2d_Curve) & guess, double first, double last) {
    const BRepAdaptor_Curve curve(edge);
    double size = 1;
    for (int i = 1; i <= surface->NbUPoles(); ++i)
        for (int j = 1; j <= surface->NbVPoles(); ++j)
            size = std::max(size, surface->Pole(i, j).XYZ().Modulus());
    auto sampleAt = [&](double t) { return projectNear(surface, curve.Value(t), guess->Value(t)); };
    for (int samples = 64; samples <= 16384; samples *= 2) {
        Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, samples + 1);
        Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, samples + 1);
        for (int k = 0; k <= samples; ++k) {
            const double t = first + (last - first) * k / samples;
            parameters->SetValue(k + 1, t);
            points->SetValue(k + 1, sampleAt(t));
        }
        Geom2dAPI_Interpolate interpolate(points, parameters, Standard_False, 1e-12);
        interpolate.Perform();
        if (!interpolate.IsDone()) break;
        Handle(Geom2d_BSplineCurve) result = interpolate.Curve();
        double worst = 0;
        for (int k = 0; k < samples; ++k) {
            const double t = first + (last - first) * (k + 0.5) / samples;
            const gp_Pnt2d uv = result->Value(t);
            worst = std::max(worst, surface->Value(uv.X(), uv.Y()).Distance(curve.Value(t)));
        }
        if (worst <= 1e-9 * size || samples == 16384) return result;
    }
    throw Standard_Failure("a trimming curve could not be carried onto the unwrapped surface");
}

}  // namespace nurbslod::occ
