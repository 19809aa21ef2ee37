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

#include <Geom2d_BSplineCurve.hxx>
#include <TopoDS_Edge.hxx>

namespace nurbslod::occ {

// The edge's curve on an unwrapped surface, over the edge parameter range [first, last]. The
// pcurves that BRepBuilderAPI_NurbsConvert makes are right only over the turn its surface
// covers (beyond it they keep the analytic surface's angle as the parameter, which the NURBS
// form does not use), so the pcurve is made again: the edge's 3D points are projected onto the
// unwrapped surface by Newton steps from `guess` (the converted pcurve: on its first turn the
// answer, beyond it within a fraction of a turn), and a C2 cubic interpolates the projections,
// refined until it reproduces the edge to 1e-9 of the model's size between its samples.
Handle(Geom2d_BSplineCurve)
    pcurveOnUnwrappedSurface(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                             const Handle(Geom2d_Curve) & guess, double first, double last);

}  // namespace nurbslod::occ
