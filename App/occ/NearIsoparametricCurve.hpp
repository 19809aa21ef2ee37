#pragma once

#include "geometry/BSplineSurface.hpp"
#include "trim/TrimLoop.hpp"

namespace nurbslod::occ {

// A trimming curve that runs along an isoparametric line of its surface but a little off it
// (a sloppy file's pcurve fitted loosely to its edge) is put onto that line when the surface
// points move by no more than `within` (the edge's tolerance: the B-rep itself places the edge
// only that closely): its control points' u (or v) all become the one at its ends. The curve is
// then straight in (u, v) (CurveOnSurface::straightInParameterPlane), so its face's cells bound
// its chords and the face spends no trimming error on it; the file's curve is kept
// (TrimCurve::beforeStraightening). Returns how far the surface points moved (measured at 65
// parameters, with a margin for those between them); 0 and the curve unchanged where it is
// not near such a line or already on it.
double straightenNearIsoparametric(const BSplineSurface& surface, TrimCurve& curve, double within);

}  // namespace nurbslod::occ
