#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/BSplineCurve2d.hpp"
#include "geometry/BSplineSurface.hpp"

namespace nurbslod {

// The 3D curve S(c(t)) traced on a surface by a trimming curve c, over the trimming curve's
// parameter range [first, last] reached through a normalised parameter s in [0, 1].
class CurveOnSurface {
public:
    CurveOnSurface(const BSplineSurface& surface, const BSplineCurve2d& pcurve, double first,
                   double last)
        : surface_(&surface), pcurve_(&pcurve), first_(first), last_(last) {}

    double parameter(double s) const { return first_ + s * (last_ - first_); }
    Point2 uv(double s) const { return pcurve_->point(parameter(s)); }
    Point3 point(double s) const {
        const Point2 p = uv(s);
        return surface_->point(p.x(), p.y());
    }
    // The degree of the 3D Bezier pieces of this curve (paper section 4: d_2d (d_u + d_v)).
    int bezierDegree() const {
        return pcurve_->degree() * (surface_->degreeU() + surface_->degreeV());
    }
    const BSplineSurface& surface() const { return *surface_; }
    const BSplineCurve2d& pcurve() const { return *pcurve_; }
    // Whether the trimming curve runs along one straight line in the (u, v) plane, one way
    // (an iso-parameter line of a cylinder, a cone, a plane). Then the surface maps every
    // (u, v) segment between two of its points onto the curve itself: a chord's error is the
    // surface's error over the segment, which the kd-tree cells bound.
    bool straightInParameterPlane() const;
    // The parameter s in [s0, s1] where the trimming curve's `coordinate` (0: u, 1: v) equals
    // `value`, for a piece along which that coordinate is monotone and brackets the value (a
    // piece of a straight curve); the nearer end where it does not bracket it.
    double parameterWhere(int coordinate, double value, double s0, double s1) const;

private:
    const BSplineSurface* surface_;
    const BSplineCurve2d* pcurve_;
    double first_, last_;
};

// An upper bound of the distance between the curve's piece over [s0, s1] and the chord between
// its end points (paper section 5.1). The piece is elevated to a 3D Bezier curve by
// interpolation at equally spaced parameters (paper section 4, solved by SVD); by the convex
// hull property the piece lies within the largest distance of a control point from the chord.
// Where the piece is not a polynomial of the chosen degree (rational surfaces, knots inside
// the piece, degree capped for speed) the interpolation residual, measured at the midpoints,
// is added and reported so the caller can subdivide until it is negligible.
//
// The interpolant's degree is the piece's true degree up to kMaxChordDegree. The paper caps it
// (e.g. 20) because the SVD grows with the degree; a cap of 3 is far lower for a reason of
// where the bound is asked: the pieces that end up as chords are short, and there a cubic
// follows the curve to O(h^4) while the chord's distance is O(h^2), so the residual is a small
// part of the bound whatever the true degree. Longer pieces of higher degree show a residual
// above a quarter of the chord's share and are halved (flatEnough). Each piece's bound costs about
// twice its degree in surface points: the cap cut the instructions of bottle.brep at relative 1e-4
// by 17% and of trj7 by 14%, against a cap of 9, for 0.1% more triangles; a cap of 2 took bolt's
// triangles at 1e-3 from 236 to 304. A cubic's residual at the midpoints is also nearer its
// largest: for a smooth curve the residual goes as t (t - 1/3) (t - 2/3) (t - 1), whose largest
// value in an end interval is 1.07 times the one at its midpoint (1.27 times for degree 9).
constexpr int kMaxChordDegree = 3;
struct ChordBound {
    double bound = 0;     // control-net distance to the chord + residual
    double residual = 0;  // interpolation residual at the sample midpoints
};
ChordBound chordBound(const CurveOnSurface& curve, double s0, double s1);

// A curve's points by parameter, each evaluated once. Midpoint subdivision asks chordBound for
// a piece's samples at s0 + (s1 - s0) i / n and midway between them; a half's samples are its
// parent's samples and midpoints. For the left half they are the same numbers (same start,
// lengths powers of two), so it evaluates only its own midpoints; the right half's are
// rounded from another start and hit where they come out the same.
class CurvePoints {
public:
    // `evaluations`, where given, counts the points evaluated (for tests)
    explicit CurvePoints(const CurveOnSurface& curve, std::size_t* evaluations = nullptr)
        : curve_(&curve), evaluations_(evaluations) {}
    const CurveOnSurface& curve() const { return *curve_; }
    Point3 operator()(double s);

private:
    // Open addressing in one array: a node-based map allocated every point, which was most of
    // the edges' time spent in malloc. A slot is empty while its key is kEmpty, a NaN that no
    // parameter is (a NaN parameter is evaluated and not kept). The slots hold the points'
    // indices, the points lie in order of evaluation: a slot of 16 bytes instead of 32 halves
    // what each growth writes and rehashes (a thread's helix takes thousands of points, and
    // growing the tables was a third of the points' time on bottle.brep at relative 1e-4).
    struct Slot {
        std::uint64_t key;
        std::uint32_t index;
    };
    static constexpr std::uint64_t kEmpty = 0x7ff8dead0000beefULL;
    void grow();
    const CurveOnSurface* curve_;
    std::size_t* evaluations_;
    std::vector<Slot> slots_;
    std::vector<Point3> points_;
};
ChordBound chordBound(CurvePoints& points, double s0, double s1);

}  // namespace nurbslod
