#pragma once

#include <Adaptor3d_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Edge.hxx>
#include <functional>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <vector>

namespace nurbslod::occ {

// Whether the pcurve, mapped onto the surface, stays within `within` of the edge's 3D curve at
// the same edge parameter (at 17 samples over [first, last]).
bool pcurveFollowsEdge(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                       const Handle(Geom2d_Curve) & pcurve, double first, double last,
                       double within);

// The edge's curve on a surface remade from its 3D curve, over the edge parameter range
// [first, last]: each 3D point is projected onto the surface by Newton steps from `guess` (the
// pcurve the file or the NURBS conversion gave, which keeps the right side of a seam; at a pole
// the guess stays), and a C2 cubic interpolates the projections, refined until it reproduces
// them to a hundredth of `accuracy` between its samples (a line of degree 1 where that cubic is
// one). Null where a projection slides far from the guess in (u, v) (onto another sheet) or the
// samples cannot be interpolated: the guess is then the better pcurve. Used where that pcurve
// is not good enough:
//  - an analytic surface's B-spline form has another parameter: the file's pcurve, in the
//    analytic one, is only the guess (and BRepBuilderAPI_NurbsConvert's approximations, where
//    it still runs, may stray by far more than the tolerance asked for: 0.19 on bottle.brep's
//    neck, or stay in the analytic angle beyond the one turn its surface covers);
//  - a sloppy file's pcurves of one edge disagree by its tolerance: following the 3D curve, the
//    faces of the edge meet again, where the file's exact face (its 3D edge) is.
Handle(Geom2d_BSplineCurve)
    pcurveFromEdgeCurve(const TopoDS_Edge& edge, const Handle(Geom_BSplineSurface) & surface,
                        const Handle(Geom2d_Curve) & guess, double first, double last,
                        double accuracy);

// The same for a 3D curve and a guess given as functions of the edge parameter: an edge whose
// parameter the importer changes (a circle's rational form) gives its points and guesses there.
// breaks: the parameters inside (first, last) where the 3D curve's smoothness breaks (the ends
// of its C2 intervals, in any order); the first samples split each piece between them evenly.
Handle(Geom2d_BSplineCurve)
    pcurveFromCurve(const std::function<gp_Pnt(double)>& curve,
                    const Handle(Geom_BSplineSurface) & surface,
                    const std::function<gp_Pnt2d(double)>& guess, double first, double last,
                    double accuracy, std::vector<double> breaks = {});

// The ends of the C2 intervals of a curve inside (first, last): the breaks pcurveFromCurve
// takes.
std::vector<double> smoothnessBreaks(const Adaptor3d_Curve& curve, double first, double last);

}  // namespace nurbslod::occ
