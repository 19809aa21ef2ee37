#pragma once

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

namespace nurbslod::occ {

// B-splines whose knots begin and end with multiplicity degree + 1 and do not repeat
// periodically, over the same parameter: the form the Bezier extraction and the tessellator
// read (a clamped knot vector's end poles are the curve's ends).
//
// OpenCASCADE's own SetNotPeriodic is not used: on a periodic B-spline whose closing knot has
// multiplicity `degree` (a C0 seam, as a STEP writer leaves a closed loft), OCCT 7.6 returns
// knots that still run past the period with multiplicity 1 at the ends, and for a surface all
// its weights 0. Segment over the wanted range inserts the end knots to full multiplicity
// instead, which is exact.

// `surface` itself where it is already clamped and not periodic, else a clamped copy over its
// own bounds (one period of a periodic direction).
Handle(Geom_BSplineSurface) clampedSurface(const Handle(Geom_BSplineSurface) & surface);

// `curve` itself where it is already clamped and not periodic, else a clamped copy: over
// [first, last] for a periodic curve (a range that may cross its period's end, as a closed
// edge's pcurve starting mid-period does), over its own bounds otherwise.
Handle(Geom2d_BSplineCurve)
    clampedCurve(const Handle(Geom2d_BSplineCurve) & curve, double first, double last);

// A curve converted from a trimmed conic over the edge's range [first, last], with its knots
// moved back onto that range where the conversion left them a whole number of periods away:
// OpenCASCADE's trimmed curves move a periodic basis's range into its first period
// (ElCLib::AdjustPeriodic), so a circle trimmed to [-pi, pi] (BRepPrimAPI's torus and
// revolutions make such edges) converts over [pi, 3 pi], and read at the edge's parameters it
// gave one point: the face lost its boundary and its triangles without a word. Null where the
// ranges differ otherwise (the caller's checks then take another way).
Handle(Geom_BSplineCurve)
    onEdgeRange(const Handle(Geom_BSplineCurve) & curve, double first, double last);
Handle(Geom2d_BSplineCurve)
    onEdgeRange(const Handle(Geom2d_BSplineCurve) & curve, double first, double last);

}  // namespace nurbslod::occ
