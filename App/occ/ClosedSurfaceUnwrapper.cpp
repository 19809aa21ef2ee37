#include "occ/ClosedSurfaceUnwrapper.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
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

}  // namespace nurbslod::occ
