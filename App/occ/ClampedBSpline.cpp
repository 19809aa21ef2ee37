#include "occ/ClampedBSpline.hpp"

#include <TColStd_Array1OfReal.hxx>
#include <algorithm>
#include <cmath>

namespace nurbslod::occ {

namespace {

bool clampedU(const Geom_BSplineSurface& s) {
    return !s.IsUPeriodic() && s.UMultiplicity(1) == s.UDegree() + 1 &&
           s.UMultiplicity(s.NbUKnots()) == s.UDegree() + 1;
}

bool clampedV(const Geom_BSplineSurface& s) {
    return !s.IsVPeriodic() && s.VMultiplicity(1) == s.VDegree() + 1 &&
           s.VMultiplicity(s.NbVKnots()) == s.VDegree() + 1;
}

template <class Curve>
Handle(Curve) movedOntoRange(const Handle(Curve) & curve, double first, double last) {
    if (curve.IsNull()) return curve;
    const double slack = 1e-9 * std::max({1.0, std::abs(first), std::abs(last)});
    const double shift = curve->FirstParameter() - first;
    if (std::abs(shift) <= slack) return curve;
    const double periods = shift / (2 * M_PI);
    if (curve->IsPeriodic() || std::abs(periods - std::round(periods)) * 2 * M_PI > slack ||
        std::abs(curve->LastParameter() - shift - last) > slack)
        return nullptr;
    Handle(Curve) result = Handle(Curve)::DownCast(curve->Copy());
    TColStd_Array1OfReal knots(1, result->NbKnots());
    result->Knots(knots);
    for (int k = knots.Lower(); k <= knots.Upper(); ++k) knots(k) -= shift;
    result->SetKnots(knots);
    return result;
}

}  // namespace

Handle(Geom_BSplineCurve)
    onEdgeRange(const Handle(Geom_BSplineCurve) & curve, double first, double last) {
    return movedOntoRange(curve, first, last);
}

Handle(Geom2d_BSplineCurve)
    onEdgeRange(const Handle(Geom2d_BSplineCurve) & curve, double first, double last) {
    return movedOntoRange(curve, first, last);
}

Handle(Geom_BSplineSurface) clampedSurface(const Handle(Geom_BSplineSurface) & surface) {
    if (clampedU(*surface) && clampedV(*surface)) return surface;
    Handle(Geom_BSplineSurface) result = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());
    double u0, u1, v0, v1;
    result->Bounds(u0, u1, v0, v1);
    result->Segment(u0, u1, v0, v1);
    return result;
}

Handle(Geom2d_BSplineCurve)
    clampedCurve(const Handle(Geom2d_BSplineCurve) & curve, double first, double last) {
    const int end = curve->Degree() + 1;
    if (!curve->IsPeriodic() && curve->Multiplicity(1) == end &&
        curve->Multiplicity(curve->NbKnots()) == end)
        return curve;
    Handle(Geom2d_BSplineCurve) result = Handle(Geom2d_BSplineCurve)::DownCast(curve->Copy());
    if (result->IsPeriodic())
        result->Segment(first, last);
    else
        result->Segment(result->FirstParameter(), result->LastParameter());
    return result;
}

}  // namespace nurbslod::occ
