#pragma once

#include <Geom_BSplineSurface.hxx>

namespace nurbslod::occ {

// A surface closed in u (or v), such as the NURBS form of a cylinder, covers one turn, while a
// face on it may run its pcurves over several turns (a helical thread). Returns the same
// surface repeated turn after turn, so that it covers [uMin, uMax] x [vMin, vMax] where the
// original only covered one turn: copy k is the original shifted by k periods in the
// parameter, joined to its neighbours at their common (closing) row of poles with a knot of
// multiplicity degree, which is exact. A direction that is not closed, or that already covers
// its range, is left as it is; the input is never modified.
Handle(Geom_BSplineSurface) unwrapClosedSurface(const Handle(Geom_BSplineSurface) & surface,
                                                double uMin, double uMax, double vMin, double vMax);

}  // namespace nurbslod::occ
