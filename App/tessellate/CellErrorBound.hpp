#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/BezierPatch.hpp"
#include "tessellate/TessellationOptions.hpp"

namespace nurbslod {

// How far a kd-tree cell's surface piece may be from the triangles made over it, and where to
// split the cell if that is too far (paper section 5.2).
//
// Write S = B + E over the cell, B the bilinear interpolant of the four corners and E the rest.
// A triangle over the cell has surface points S(p_k) as corners, so at a point (u, v) with
// barycentric weights lambda_k the triangle is at sum lambda_k S(p_k), and
//   S(u, v) - sum lambda_k S(p_k) = [E(u, v) - sum lambda_k E(p_k)]
//                                 + [B(u, v) - sum lambda_k B(p_k)].
// The second bracket is the linear interpolation error of a bilinear map over a triangle inside
// the cell: at most |P00 - Pm0 - P0n + Pmn| / 4 (the paper's twist term, [Kah02]). The first is
// the difference of a point of E's range and a convex combination of points of E's range; E is
// a rational Bezier patch with positive weights, so its range lies in the convex hull of its
// projected control points, and the first bracket is at most the largest distance between two
// of them (`spread`), or between one of them and one on the cell's border when the corners p_k
// lie on the cell's sides (`spreadToEdges`). Bounding it by the largest |E| inside plus the
// largest |E| on the sides (or twice the largest inside) is about twice too much where E
// bulges to one side, as on a cylinder or a sphere.
struct CellErrorBound {
    // Bound on |S - B| over the cell, B the bilinear interpolant of the corners.
    double interior = 0;
    // Bound on |S - B| along the four cell edges: where the triangle corners are.
    double boundary = 0;
    // |P00 - Pm0 - P0n + Pmn| / 4: the most the two triangles (or any triangles inside the cell)
    // deviate from the bilinear patch (paper section 5.2, [Kah02]).
    double twist = 0;
    // Bound on |E(x) - E(y)|, x anywhere in the cell, y on its sides (at most interior +
    // boundary).
    double spreadToEdges = 0;
    // Bound on |E(x) - E(y)|, x and y anywhere in the cell (at most 2 interior).
    double spread = 0;
    // Where the four corners make a convex quadrilateral in a plane but for w_perp, the part of
    // w = P00 - Pm0 - P0n + Pmn normal to the plane of the sides at P00: |w_perp| times a factor
    // of at most 1; infinity otherwise. Every cell of a surface of revolution cut along its
    // meridians and parallels is an isosceles trapezoid (w_perp = 0), whose twist is a quarter of
    // the difference of its parallel sides: on a cone's column or a sphere's cell near the pole,
    // as large as the bulge itself. That twist moves the triangles within the trapezoid's plane
    // only, and the distance to the surface does not see it, both ways: write
    // B = B' + s t w_perp, B' the planar bilinear map onto the quadrilateral. Triangles through
    // points on the cell's sides, flattened by B', tile B'(cell); a triangle point
    // M = sum lambda_k S(p_k) then has the parameter x with B'(x) = sum lambda_k B'(p_k), and
    //   M - S(x) = [sum lambda_k E(p_k) - E(x)] + w_perp (sum lambda_k s_k t_k - s t),
    // at most spreadToEdges + |w_perp| |sum lambda_k s_k t_k - s t|; a surface point S(x) has the
    // triangle point M with that B'(x) the same way. The last factor is at most 1, and near a
    // parallelogram about 1/4 (twistOutOfPlane in CellErrorBound.cpp). A geometric bound, not at
    // equal parameters as `twist`: the verifier and the guarantee measure distances. Where a
    // side is short (delta; 0 at a pole, where the corners coincide and no plane of the sides is
    // found), its corners merged make a triangle of the other three, and the same argument holds
    // with delta for the out-of-plane term: the least of the two.
    double planarTwist = std::numeric_limits<double>::infinity();
    // Where the trimmed region's piece of the cell lies in a box of a fraction fu of the cell's
    // width and fv of its height, fu fv (1 for the whole cell): a triangle with its corners in
    // that box deviates from the bilinear patch by at most fu fv twist. In the box's own
    // coordinates (s = s0 + fu s', t = t0 + fv t') the product s t is fu fv s' t' plus terms
    // linear in s' and t', which a triangle interpolates exactly, and the twist bound holds for
    // s' t' over any triangle in the unit square.
    double pieceFraction = 1;
    // Preferred split direction (0 = u, 1 = v); the kd-tree halves the cell in the middle, or
    // cuts it at farthestNetPointAt where TessellationOptions::middleSplits is off.
    int splitDirection = 0;

    // Bound for triangles whose corners are cell corners or lie on the cell edges.
    double untrimmed() const { return spreadToEdges + std::min(twist, planarTwist); }
    // Bound for triangles with corners anywhere in the cell (trimming points).
    double trimmed() const { return spread + pieceFraction * twist; }
    // What the kd-tree compares with its target: in mode Approximate the paper's estimate
    // (interior + twist, the twist of a flat cell taken as planarTwist, as in untrimmed()),
    // otherwise the bound for a cell the trimming curves may cross or not. The estimate takes
    // planarTwist in trimmed cells too: the twist it leaves out moves the triangles within the
    // cell's plane, away from the surface nowhere, trimmed or not. Only the bound needs more
    // there (trimmed() keeps the twist): a triangle point's nearest surface point may lie
    // beyond the trimming curve, and no proof yet bounds how far. On the corpus at relative
    // 1e-4 this takes hammer.iges from 10,392 triangles to 7,384 and wing.brep from 2,799 to
    // 396, the thin trimmed columns of cones and tori no longer split for a twist the surface
    // does not have.
    double measure(ErrorMode mode, bool trimmedCell) const {
        if (mode == ErrorMode::Approximate) return interior + std::min(twist, planarTwist);
        return trimmedCell ? trimmed() : untrimmed();
    }
    // Bounds on |dS/ds| and |dS/dt| over the cell, s and t its own parameters in [0, 1]
    // (parameterSpeed).
    struct Speed {
        double s = 0, t = 0;
    };
    // Bound for the triangles of a cell whose boundary runs a hair inside its sides (a sloppy
    // edge's points, moved to where two surfaces meet, beside the iso-line a cell side lies on):
    // every corner p_k of its polygon can be moved onto the cell's border, p'_k, by at most
    // `nearU` of the cell's width along u or `nearV` of its height along v, the p'_k keeping the
    // polygon's order around the border (FaceTessellator's nearSideOffsets). trimmed() would take
    // the spread and the twist of the whole cell.
    //  - The moved triangles S(p'_k) have their corners on the cell's sides, in order, so they
    //    are within untrimmed() of the surface over the cell both ways: they are a triangulation
    //    of points on a convex border in the border's order, whose flattened triangles tile the
    //    flattened cell (a limit of strictly convex positions where they do), as for a cell the
    //    region fills (planarTwist).
    //  - A triangle point M = sum lambda_k S(p_k) is off its moved point M' by at most
    //    nu = nearU speed.s + nearV speed.t (no corner moves farther than nearU in s and nearV
    //    in t; one in a corner of the cell moves in both).
    //  - The surface over the cell is within nu of the surface over the polygon: the polygon's
    //    boundary lies within the bands along the sides, so every point of the cell is within
    //    nearU in s and nearV in t of the polygon (which holds the cell but for those bands).
    // Mesh to face: M, M', a point of the surface over the cell, one over the polygon. Face to
    // mesh: S(x), a point M' of a moved triangle, its M. Both within untrimmed() + 2 nu.
    double nearSides(const Speed& speed, double nearU, double nearV) const {
        return untrimmed() + 2 * (nearU * speed.s + nearV * speed.t);
    }
};

// Conservative (mode Guaranteed): from the control net of E = (N - w B) / w written in the
// degree-elevated Bernstein basis, where the weights are the elevated weights; when the bound
// for `trimmedCell` is above `target` but within twice of it, E is subdivided at its middle
// (de Casteljau) and the bound taken over the pieces' control points, which converges to E's
// true range, unless a surface point already shows that no subdivision can bring it under
// `target`. A cell bounded for corners on its sides (not `trimmedCell`, `byDistance`) whose
// bound is still above `target`, within 8 times, is bounded again under the even-speed
// parameter (BezierReparametrization), the smaller kept.
// Approximate: the control points replaced by surface points at the control points' parameters
// (paper section 5.2) and between them; where that is above `target`, the same samples under
// the even-speed parameter, the smaller kept.
// With `byDistance` false, planarTwist stays infinite: the bounds hold at equal parameters.
// `pieceFraction`: CellErrorBound::pieceFraction, for trimmed().
CellErrorBound cellErrorBound(const BezierPatch& patch, ErrorMode mode, double target = 0,
                              bool trimmedCell = false, bool byDistance = true,
                              double pieceFraction = 1);

// A bound on how far the patch S is from the affine map A(s, t) = a00 + s (a10 - a00) +
// t (a01 - a00) over [0, 1]^2: the largest |control point| of E = S - A (differencePatch, A being
// a bilinear map without twist), which holds E's range (positive weights); a part above `target`
// is cut in quarters and bounded again, three times at most. A triangle whose corners X_k lie over
// parameters q_k of the patch, with A the affine map through the (q_k, X_k), has the point A(q)
// over each q of its (u, v) triangle, so it is within that bound of the surface both ways: no
// spread and no twist term, which a kd-tree cell needs for triangles it does not know yet.
// Only the parts that meet `triangle` (in the patch's own [0, 1]^2) count where it is cut: the
// affine map leaves the surface fastest beyond the triangle.
double affineDeviation(const BezierPatch& patch, const Point3& a00, const Point3& a10,
                       const Point3& a01, double target, const std::array<Point2, 3>& triangle);

// The bilinear patch of the corners c00, c10, c01, c11 at (s, t): B of the bounds below.
inline Point3 bilinearAt(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11,
                         double s, double t) {
    return (1 - s) * ((1 - t) * c00 + t * c01) + s * ((1 - t) * c10 + t * c11);
}

// One Bezier span's part of a kd-tree cell that reaches across span borders: the span's patch
// restricted to the part, and the part's place [s0, s1] x [t0, t1] in the cell's own parameters
// (the parts tile [0, 1]^2; a part on the cell's border has its s0, s1, t0 or t1 exactly 0 or 1).
struct SpanPiece {
    BezierPatch patch;
    double s0 = 0, s1 = 1, t0 = 0, t1 = 1;
};

// cellErrorBound for a cell made of several spans' pieces, which the kd-tree otherwise cuts at
// every span border first: a B-spline with many knots (a fitted or scanned surface, one face of
// 77 x 80 bicubic spans in OpenCASCADE's MAT.brep sample) took at least one cell a span, twice
// the triangles BRepMesh needs there. B is the bilinear patch of the cell's four corners, and
// on each piece E = S - B is the piece's rational Bezier patch less B restricted to the piece
// (itself bilinear, with the corners B(s0, t0) ... B(s1, t1)), so E over the cell lies in the
// union of the pieces' hulls: the spreads are the largest distances between control points of
// all the pieces (to those on the cell's border for spreadToEdges), and the twist terms are the
// corners' alone, as for one patch (the argument in CellErrorBound holds for any E with that
// hull property). Where that is above `target` but within twice of it, each piece's E is cut
// into quarters (de Casteljau) and the bound taken over their control points, as for one patch.
// Mode Approximate: the pieces' sample grids against B. No reparametrisation: a cell that does
// not settle is cut at its span borders as before.
CellErrorBound cellErrorBoundAcrossSpans(const std::vector<SpanPiece>& pieces, ErrorMode mode,
                                         double target, bool trimmedCell, bool byDistance,
                                         double pieceFraction);

// The twist part of CellErrorBound::measure for a cell with these corners (its bilinear patch
// B): min(twist, planarTwist), or pieceFraction twist for a trimmed cell in mode Guaranteed.
// Every measure is at least |S - B| at any point of the cell plus this term (E = S - B is 0 at
// the corners, which lie on the sides): a lower bound that rules a cell out cheaply.
double twistTerm(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11,
                 ErrorMode mode, bool trimmedCell, bool byDistance, double pieceFraction);

// CellErrorBound::Speed of a patch. With poles P_ij, weights w_ij > 0 and W = sum w_ij B_ij,
//   dS/ds = sum_ij w_ij (dB_ij/ds) (P_ij - S) / W
//         = m / W sum_kj B_k,m-1 B_j (w_k+1,j (P_k+1,j - S) - w_kj (P_kj - S)),
// each bracket at most w_k+1,j |P_k+1,j - P_kj| + |w_k+1,j - w_kj| |P_kj - S|, where |P_kj - S|
// is at most the diagonal of the net's box (S lies in the net's hull) and W at least the least
// weight. For equal weights: m max |P_k+1,j - P_kj|. The same along t.
CellErrorBound::Speed parameterSpeed(const BezierPatch& patch);

// |S - B| at the cell's centre, S the patch and B the bilinear interpolant of its corners, or
// less, |S(alpha(1/2), beta(1/2)) - B(1/2, 1/2)| under the even-speed parameter that the bound
// for corners on the sides also takes (evenSpeed): a lower bound of every measure in mode
// Guaranteed (E = S - B is 0 at the corners, which lie on the sides, so spreadToEdges and
// spread are at least |E| anywhere, and the same for E'). A cell above its target here is split
// whatever its bound, which the kd-tree then does not compute.
double centreDeviation(const BezierPatch& patch);
// centreDeviation(patch) > target, without the even-speed point where the plain centre is
// within the target (most cells: the kd-tree asks this of every cell it bounds).
bool centreBeyond(const BezierPatch& patch, double target);

// The direction in which cellErrorBound in mode Guaranteed would split the cell
// (splitDirection).
int preferredSplitDirection(const BezierPatch& patch);
// Where the paper (section 5.2, Fig. 3) cuts the cell in `direction`: through the control point
// farthest from the bilinear patch of the corners, as a local position in (0, 1), or the middle
// where that point lies on the cell's border in that direction or the net does not bend.
double farthestNetPointAt(const BezierPatch& patch, int direction);

// The direction to halve a cell: the one the bound prefers (`preferred`), or the other where
// halving in the preferred direction leaves a half above `target` and halving in the other
// settles both halves (each half measured as cellErrorBound does in `mode` with the other
// arguments). A cell whose bound is larger along one direction (a parameter running unevenly
// along a straight line: bug28366_fuselage.stp's long span) while its surface bends along the
// other settles in two pieces where the preferred halving needed three or more. Only cells
// within 4 target at the centre are tried: halving a side quarters the bilinear deviation (the
// bound of section 5.2 falls with the square of the side), so the halves of a cell farther off
// hardly settle, and the test costs four patch restrictions and up to four bounds.
// `halves`, where given, takes the bounds it measured of the two halves in the direction it
// returns (patch.restricted(0, 0.5, 0, 1) and (0.5, 1, 0, 1) along u), each where measured: the
// kd-tree's children of a cut through the middle are those halves, and need not be bounded again.
// `centreWithinTarget`: the caller found centreBeyond(patch, target) false (the centre is then
// within 4 target, and is not sampled again).
using HalfBounds = std::array<std::optional<CellErrorBound>, 2>;
int settlingSplitDirection(const BezierPatch& patch, int preferred, double target, bool trimmedCell,
                           bool byDistance, double pieceFraction, ErrorMode mode,
                           HalfBounds* halves = nullptr, bool centreWithinTarget = false);

}  // namespace nurbslod
