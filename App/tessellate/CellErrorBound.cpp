#include "tessellate/CellErrorBound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/BasisFunctions.hpp"
#include "geometry/BezierReparametrization.hpp"

namespace nurbslod {

namespace {

// E = S - B over the cell as a rational Bezier patch of degree (m+1, n+1): homogeneous points
// (c_IJ, w_IJ) with c the coefficients of N - w B and w the elevated weights. The product of
// B^m_i and B^1_k is (m+1-i)/(m+1) B^{m+1}_i for k = 0 and (i+1)/(m+1) B^{m+1}_{i+1} for k = 1,
// which also elevates N and w (degree elevation, NURBS Book section 5.5). E = sum c B / sum w B
// then has the positive weights w_IJ and the control points c_IJ / w_IJ, so its range lies in their
// convex hull (paper section 5.2 bounds the same difference by the unelevated net).
BezierPatch differencePatch(const BezierPatch& patch, const Point3 (&corner)[2][2]) {
    const int m = patch.degreeU(), n = patch.degreeV();
    BezierPatch difference(m + 1, n + 1);
    // the elevation's factors, each quotient taken once per cell instead of once per term
    double alpha[2][kMaxDegree + 2], beta[2][kMaxDegree + 2];
    for (int I = 0; I <= m + 1; ++I) {
        alpha[0][I] = (m + 1.0 - I) / (m + 1.0);
        alpha[1][I] = I / (m + 1.0);
    }
    for (int J = 0; J <= n + 1; ++J) {
        beta[0][J] = (n + 1.0 - J) / (n + 1.0);
        beta[1][J] = J / (n + 1.0);
    }
    for (int I = 0; I <= m + 1; ++I)
        for (int J = 0; J <= n + 1; ++J) {
            HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
            for (int k = 0; k <= 1; ++k) {
                const int i = I - k;
                if (i < 0 || i > m) continue;
                const double a = alpha[k][I];
                for (int l = 0; l <= 1; ++l) {
                    const int j = J - l;
                    if (j < 0 || j > n) continue;
                    const double b = beta[l][J];
                    const HomogeneousPoint3& p = patch.pole(i, j);
                    sum.head<3>() += a * b * (p.head<3>() - p[3] * corner[k][l]);
                    sum[3] += a * b * p[3];
                }
            }
            difference.pole(I, J) = sum;
        }
    return difference;
}

// Bounds on E's range from the control points of E cut into pieces x pieces equal parts: E on
// a part lies in the hull of that part's control points, E on the cell's sides in the hull of
// the border rows of the parts along the sides. The parts' corner points are points of E.
struct DifferenceRange {
    double interior = 0;       // largest |control point|
    double boundary = 0;       // largest |control point| on the cell's sides
    double spreadToEdges = 0;  // largest distance from a control point to one on the sides
    double spread = 0;         // largest distance between two control points
    double largestValue = 0;   // largest |E| at the parts' corners: a lower bound of max |E|
};

// How far each point of `from` can be from any point of `to`: |p - c| + R, with c the centre
// of `to`'s bounding box and R the largest |q - c| over `to`; and which point reaches farthest.
// Every kd-tree cell is bounded, most of them on nets of a few points: the vectors below are
// each thread's own and keep their capacity from cell to cell instead of being allocated anew
// (allocation was a tenth of the bound's time).
struct Reach {
    std::vector<double>& of;
    size_t farthest = 0;
};

Reach reachOf(const std::vector<Point3>& from, const std::vector<Point3>& to) {
    Point3 low = to.front(), high = to.front();
    for (const Point3& q : to) low = low.cwiseMin(q), high = high.cwiseMax(q);
    const Point3 centre = 0.5 * (low + high);
    double radius = 0;
    for (const Point3& q : to) radius = std::max(radius, (q - centre).norm());
    thread_local std::vector<double> of;
    of.assign(from.size(), 0.0);
    Reach reach{of};
    for (size_t i = 0; i < from.size(); ++i) {
        reach.of[i] = (from[i] - centre).norm() + radius;
        if (reach.of[i] > reach.of[reach.farthest]) reach.farthest = i;
    }
    return reach;
}

// The largest distance between a point of `from` and a point of `to`. Exact, without all the
// pairs: no pair with p is farther than p's reach (reachOf), so after the pairs of the point
// that reaches farthest only the points that can still beat the largest distance found are
// taken.
double farthestPair(const std::vector<Point3>& from, const std::vector<Point3>& to) {
    const Reach reach = reachOf(from, to);
    double farthest2 = 0;
    auto pairsOf = [&](size_t i) {
        for (const Point3& q : to) farthest2 = std::max(farthest2, (from[i] - q).squaredNorm());
    };
    pairsOf(reach.farthest);
    for (size_t i = 0; i < from.size(); ++i)
        if (i != reach.farthest && reach.of[i] * reach.of[i] > farthest2) pairsOf(i);
    return std::sqrt(farthest2);
}

// farthestPair(points, points) with each pair taken once: a pair (p_j, p_i), j before i, was
// taken with p_j's pairs, or p_j was passed over because no pair with it could beat the
// largest distance found, which only grows. Half the work of a trimmed cell's spread.
double diameter(const std::vector<Point3>& points) {
    const Reach reach = reachOf(points, points);
    double farthest2 = 0;
    for (const Point3& q : points)
        farthest2 = std::max(farthest2, (points[reach.farthest] - q).squaredNorm());
    for (size_t i = 0; i < points.size(); ++i) {
        if (i == reach.farthest || !(reach.of[i] * reach.of[i] > farthest2)) continue;
        for (size_t j = i + 1; j < points.size(); ++j)
            farthest2 = std::max(farthest2, (points[i] - points[j]).squaredNorm());
    }
    return std::sqrt(farthest2);
}

DifferenceRange rangeOf(const BezierPatch& difference, int pieces, bool trimmedCell) {
    const int degreeU = difference.degreeU(), degreeV = difference.degreeV();
    thread_local std::vector<Point3> points, sidePoints;
    points.clear();
    sidePoints.clear();
    DifferenceRange range;
    std::array<BezierPatch, 4> quarters;
    if (pieces == 2) quarters = difference.quarters();
    BezierPatch other;
    // largest squared norms, their roots taken once: the root is monotone and correctly rounded,
    // so the root of the largest square is the largest root, to the bit
    double largestValue2 = 0, interior2 = 0, boundary2 = 0;
    for (int a = 0; a < pieces; ++a)
        for (int b = 0; b < pieces; ++b) {
            const BezierPatch* part = &difference;
            if (pieces == 2) {
                part = &quarters[2 * a + b];
            } else if (pieces > 2) {
                other = difference.restricted(double(a) / pieces, double(a + 1) / pieces,
                                              double(b) / pieces, double(b + 1) / pieces);
                part = &other;
            }
            for (int i = 0; i <= degreeU; ++i)
                for (int j = 0; j <= degreeV; ++j) {
                    const Point3 p = part->pole3(i, j);
                    const double p2 = p.squaredNorm();
                    points.push_back(p);
                    interior2 = std::max(interior2, p2);
                    const bool onSide = (i == 0 && a == 0) || (i == degreeU && a == pieces - 1) ||
                                        (j == 0 && b == 0) || (j == degreeV && b == pieces - 1);
                    if (onSide) {
                        sidePoints.push_back(p);
                        boundary2 = std::max(boundary2, p2);
                    }
                    if ((i == 0 || i == degreeU) && (j == 0 || j == degreeV))
                        largestValue2 = std::max(largestValue2, p2);
                }
        }
    range.largestValue = std::sqrt(largestValue2);
    range.interior = std::sqrt(interior2);
    range.boundary = std::sqrt(boundary2);
    // only the one the cell needs is measured; the other keeps the plain triangle inequality
    range.spreadToEdges =
        trimmedCell ? range.interior + range.boundary : farthestPair(points, sidePoints);
    range.spread = trimmedCell ? diameter(points) : 2 * range.interior;
    return range;
}

// CellErrorBound::planarTwist's bound for the out-of-plane part w_perp of the twist, or
// infinity where the corners projected onto the plane of the sides at c00 do not make a strictly
// convex quadrilateral (c00, c10, c11, c01).
//
// The factor of |w_perp|: with B' the planar bilinear map, a = c10 - c00, b = c01 - c00 and
// w_par the in-plane part of the twist, the parameter x with B'(x) = sum lambda_k B'(p_k) is
// near the interpolated parameter x_l = sum lambda_k p_k: B'(x) - B'(x_l) =
// (sum lambda_k s_k t_k - s_l t_l) w_par, at most |w_par| / 4 (the twist term's quarter), and B'
// stretches no segment of the cell by less than sigma, so |x - x_l| <= |w_par| / (4 sigma). Then
//   |sum lambda_k s_k t_k - s t| <= 1/4 + |s_l t_l - s t| <= 1/4 + sqrt(2) |x - x_l|,
// and at most 1 (both lie in [0, 1]). sigma: B'(x) - B'(y) = J(m) (x - y) with J the Jacobian
// [a + t w_par, b + s w_par] at the midpoint m (J is affine in s and t), and the least singular
// value of J is |det J| over its largest, det J affine too (least at a corner: the turns of the
// quadrilateral below) and the largest at most the root of the largest squared columns. Near a
// parallelogram the factor is about a quarter, where it was 1: bug28366_fuselage.stp at relative
// 1e-4, 30,888 -> 29,800 triangles.
double twistOutOfPlane(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11) {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    const Point3 a = c10 - c00, b = c01 - c00, w = c00 - c10 - c01 + c11;
    const Point3 normal = a.cross(b);
    const double area = normal.norm();
    if (!(area > 1e-300) || !std::isfinite(area)) return kNone;
    const Point3 n = normal / area;
    const Point3 wNormal = w.dot(n) * n;
    // the quadrilateral c00, c10, c11 - wNormal, c01 in the plane: each turn the same way
    const Point3 corner[4] = {c00, c10, c11 - wNormal, c01};
    double leastTurn = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
        const Point3 side = corner[(k + 1) % 4] - corner[k];
        const Point3 next = corner[(k + 2) % 4] - corner[(k + 1) % 4];
        const double turn = side.cross(next).dot(n);
        if (!(turn > 1e-12 * side.norm() * next.norm())) return kNone;
        leastTurn = std::min(leastTurn, turn);
    }
    const Point3 wInPlane = w - wNormal;
    const double widest = std::sqrt(std::max(a.squaredNorm(), (a + wInPlane).squaredNorm()) +
                                    std::max(b.squaredNorm(), (b + wInPlane).squaredNorm()));
    const double least = leastTurn / widest;
    const double factor = std::min(1.0, 0.25 + std::sqrt(2.0) * 0.25 * wInPlane.norm() / least);
    return factor * wNormal.norm();
}

// The shortest side's length, where the other corners make a proper triangle: infinity
// otherwise. A cell with a side at a pole (a cone's column at its apex, a sphere's cell at its
// tip) has two equal corners, no plane of the sides at one of them, and a twist as large as its
// far side: without this it is split until that side is four times the target. Merge the
// side's corners, c' = c + d with |d| = delta the side's length: the bilinear map B'' of the
// merged corners maps the cell onto the triangle of the three others, each side onto a side or
// onto the merged corner, and B - B'' = g d with g (a product of s, t, 1 - s, 1 - t) in [0, 1].
// Triangles through points on the cell's sides, flattened by B'', have their corners in the
// cell's order on the triangle's border, so none turns the other way and they tile it (a fan
// from a merged pole has area zero at it). Then, as for planarTwist, a triangle point
// M = sum lambda_k S(p_k) has the x with B''(x) = sum lambda_k B''(p_k), and
//   M - S(x) = [sum lambda_k E(p_k) - E(x)] + d (sum lambda_k g(p_k) - g(x)),
// at most spreadToEdges + delta; a surface point S(x) has such an M the same way.
double collapsedSide(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11) {
    const Point3 corner[4] = {c00, c10, c11, c01};
    double shortest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
        const double delta = (corner[(k + 1) % 4] - corner[k]).norm();
        if (!(delta < shortest)) continue;
        // the triangle of corner k (the merged one) and the two beyond the side
        const Point3 a = corner[(k + 2) % 4] - corner[k], b = corner[(k + 3) % 4] - corner[k];
        const double area = a.cross(b).norm();
        if (area > 1e-12 * a.norm() * b.norm() && std::isfinite(area)) shortest = delta;
    }
    return shortest;
}

double planarTwistOf(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11) {
    return std::min(twistOutOfPlane(c00, c10, c01, c11), collapsedSide(c00, c10, c01, c11));
}

// Split direction: the one in which the net bends more (second differences; paper section
// 5.2). The kd-tree then halves the cell in the middle, where the paper's Fig. 3 splits through
// the net point farthest from the bilinear patch: that point of a cubic span lies at 1/3 or 2/3
// of it, and the bound, which falls with the square of the side, is then 4/9 of the cell's on
// the larger piece against 1/4 on either half. A cell within 4 times its target settles in two
// halves and needed three pieces or more at 1/3 (bug28366_fuselage.stp at relative 1e-4:
// 20,438 -> 14,256 triangles). The display and the analysis overlays keep the paper's cut
// (farthestNetPointAt, TessellationOptions::middleSplits): their normal bounds were measured on it.
// A net's second differences are a degree's m (m - 1) times smaller than the bulge they make:
// the curve's second derivative is m (m - 1) times them over the interval squared (NURBS Book
// eq. 2.9 twice), and the bulge an eighth of it. Where the degrees differ the bends are so
// weighed: the loft of tests/bench/generated_shapes.py (degree 12 around, 2 along) bends 36
// times more around than its net says, and was halved along, where its cells' bound was already
// met along and a halving around would have settled them (47,520 triangles at relative 1e-4).
struct NetBends {
    double u = 0, v = 0;
};
NetBends netBends(const std::vector<Point3>& net, int m, int n) {
    double bendU = 0, bendV = 0;
    for (int i = 1; i < m; ++i)
        for (int j = 0; j <= n; ++j)
            bendU = std::max(bendU, (net[(i - 1) * (n + 1) + j] - 2 * net[i * (n + 1) + j] +
                                     net[(i + 1) * (n + 1) + j])
                                        .norm());
    for (int i = 0; i <= m; ++i)
        for (int j = 1; j < n; ++j)
            bendV = std::max(bendV, (net[i * (n + 1) + j - 1] - 2 * net[i * (n + 1) + j] +
                                     net[i * (n + 1) + j + 1])
                                        .norm());
    if (m != n) {
        bendU *= m * (m - 1.0);
        bendV *= n * (n - 1.0);
    }
    return {bendU, bendV};
}

int splitDirectionOfNet(const std::vector<Point3>& net, int m, int n, const Point3& c00,
                        const Point3& c10, const Point3& c01, const Point3& c11) {
    const auto [bendU, bendV] = netBends(net, m, n);
    if (bendU == 0 && bendV == 0) {
        // only twist: split the longer side in the middle
        const double lengthU = ((c10 - c00).norm() + (c11 - c01).norm());
        const double lengthV = ((c01 - c00).norm() + (c11 - c10).norm());
        return lengthU >= lengthV ? 0 : 1;
    }
    return bendU >= bendV ? 0 : 1;
}

// The net point farthest from the bilinear patch of the corners (the first of equals), and
// its distance.
struct FarthestNetPoint {
    double distance = -1;
    int i = 0, j = 0;
};
FarthestNetPoint farthestFromBilinear(const std::vector<Point3>& net, int m, int n,
                                      const Point3& c00, const Point3& c10, const Point3& c01,
                                      const Point3& c11) {
    FarthestNetPoint farthest;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            const double s = static_cast<double>(i) / m, t = static_cast<double>(j) / n;
            const double d = (net[i * (n + 1) + j] - bilinearAt(c00, c10, c01, c11, s, t)).norm();
            if (d > farthest.distance) farthest = {d, i, j};
        }
    return farthest;
}

// A cell whose bound for corners on its sides is above its target but within this factor of
// it is bounded again under the even-speed reparametrisation (evenSpeed), where its tangential
// drift can be most of E.
constexpr double kWorthReparametrizing = 8.0;

// The patch's even-speed parameter (evenSpeed), where it moves the parameter at all and the
// composed patch's difference (degree 2m + 1) stays within kMaxDegree.
std::optional<EvenSpeed> usableEvenSpeed(const BezierPatch& patch) {
    if (2 * patch.degreeU() + 1 > kMaxDegree || 2 * patch.degreeV() + 1 > kMaxDegree) return {};
    const EvenSpeed even = evenSpeed(patch);
    if (even.a == 0 && even.b == 0) return {};
    return even;
}

// The largest distance between the patch under the even-speed parameter, S(alpha(s), beta(t)),
// and the bilinear patch of its corners, B(s, t), at s = i / 2m, t = j / 2n: samples of |E'|.
double largestEvenSample(const BezierPatch& patch, const EvenSpeed& even) {
    const int m = patch.degreeU(), n = patch.degreeV();
    const Point3 c00 = patch.pole3(0, 0), c10 = patch.pole3(m, 0);
    const Point3 c01 = patch.pole3(0, n), c11 = patch.pole3(m, n);
    std::vector<double> us(static_cast<size_t>(2 * m + 1)), vs(static_cast<size_t>(2 * n + 1));
    for (int i = 0; i <= 2 * m; ++i) {
        const double s = static_cast<double>(i) / (2 * m);
        us[i] = s + even.a * s * (1 - s);
    }
    for (int j = 0; j <= 2 * n; ++j) {
        const double t = static_cast<double>(j) / (2 * n);
        vs[j] = t + even.b * t * (1 - t);
    }
    const std::vector<Point3> samples = patch.gridPointsAt(us, vs);
    double largest = 0;
    for (int i = 0; i <= 2 * m; ++i)
        for (int j = 0; j <= 2 * n; ++j) {
            const double s = static_cast<double>(i) / (2 * m);
            const double t = static_cast<double>(j) / (2 * n);
            largest = std::max(
                largest,
                (samples[i * (2 * n + 1) + j] - bilinearAt(c00, c10, c01, c11, s, t)).norm());
        }
    return largest;
}

// Subdivision of E pays only near the target: far above it the cell is split anyway.
constexpr double kWorthRefining = 2.0;
// Parts per side tried: 1 (E's own net), then 2; 4 parts were measured to save under 0.1 % of
// the triangles on the corpus at about 5 % more time.
constexpr int kMostPieces = 2;

}  // namespace

CellErrorBound cellErrorBound(const BezierPatch& patch, ErrorMode mode, double target,
                              bool trimmedCell, bool byDistance, double pieceFraction) {
    const int m = patch.degreeU(), n = patch.degreeV();
    const Point3 c00 = patch.pole3(0, 0), c10 = patch.pole3(m, 0);
    const Point3 c01 = patch.pole3(0, n), c11 = patch.pole3(m, n);
    auto bilinear = [&](double s, double t) { return bilinearAt(c00, c10, c01, c11, s, t); };
    CellErrorBound bound;
    bound.twist = 0.25 * (c00 - c10 - c01 + c11).norm();
    if (byDistance) bound.planarTwist = planarTwistOf(c00, c10, c01, c11);
    bound.pieceFraction = std::clamp(pieceFraction, 0.0, 1.0);

    // Points standing for the surface: control points (conservative) or surface points at the
    // control points' parameters (approximate).
    // The approximate measure also samples between those parameters (below): one grid of
    // (2m + 1) x (2n + 1) surface points holds both.
    std::vector<Point3> samples;
    if (mode == ErrorMode::Approximate) samples = patch.gridPoints(2 * m, 2 * n);
    thread_local std::vector<Point3> net;
    net.resize(static_cast<size_t>((m + 1) * (n + 1)));
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
            net[i * (n + 1) + j] = mode == ErrorMode::Guaranteed
                                       ? patch.pole3(i, j)
                                       : samples[(2 * i) * (2 * n + 1) + 2 * j];

    if (mode == ErrorMode::Approximate) {
        // The paper's measure samples the surface at the control points' parameters only,
        // and misses bulges between them (measured up to 1.2 T on the corpus); the midpoints
        // between those parameters are sampled too, at about 4x the cost of this estimate.
        double between = 0;
        for (int i = 0; i <= 2 * m; ++i)
            for (int j = 0; j <= 2 * n; ++j) {
                if (i % 2 == 0 && j % 2 == 0) continue;  // a control point's parameter: done
                const double s = static_cast<double>(i) / (2 * m);
                const double t = static_cast<double>(j) / (2 * n);
                between = std::max(between, (samples[i * (2 * n + 1) + j] - bilinear(s, t)).norm());
            }
        bound.interior =
            std::max(farthestFromBilinear(net, m, n, c00, c10, c01, c11).distance, between);
        // The same samples under the even-speed parameter (as the bound below takes it): where
        // the parameter runs unevenly along the surface, the samples' drift within the surface
        // is most of their distance to the bilinear patch, and the triangles do not see it.
        std::optional<EvenSpeed> even;
        if (byDistance && bound.measure(mode, trimmedCell) > target &&
            (even = usableEvenSpeed(patch))) {
            bound.interior = std::min(bound.interior, largestEvenSample(patch, *even));
        }
        bound.boundary = 0;  // the approximate measure samples the edges with the interior
        bound.spreadToEdges = bound.spread = bound.interior;
    } else {
        const Point3 corner[2][2] = {{c00, c01}, {c10, c11}};
        const BezierPatch difference = differencePatch(patch, corner);
        auto keep = [&](const DifferenceRange& range) {
            // each subdivision gives true bounds on the same quantities: keep the smallest
            bound.interior = std::min(bound.interior, range.interior);
            bound.boundary = std::min(bound.boundary, range.boundary);
            bound.spreadToEdges = std::min(bound.spreadToEdges, range.spreadToEdges);
            bound.spread = std::min(bound.spread, range.spread);
        };
        bound.interior = bound.boundary = bound.spreadToEdges = bound.spread =
            std::numeric_limits<double>::infinity();
        keep(rangeOf(difference, 1, trimmedCell));
        auto relevant = [&] { return trimmedCell ? bound.trimmed() : bound.untrimmed(); };
        for (int pieces = 2;
             pieces <= kMostPieces && relevant() > target && relevant() <= kWorthRefining * target;
             pieces *= 2) {
            const DifferenceRange range = rangeOf(difference, pieces, trimmedCell);
            keep(range);
            // both bounds are at least max |E| plus their twist term (E = 0 at the corners, which
            // are on the sides): a surface point that far off means no subdivision can reach the
            // target
            const double twistTerm = trimmedCell ? bound.pieceFraction * bound.twist
                                                 : std::min(bound.twist, bound.planarTwist);
            if (range.largestValue + twistTerm > target) break;
        }
        // The bound for corners on the sides holds for any parameter of the same surface piece
        // that keeps its corners and each side onto itself: the triangles' corners are the same
        // surface points, at parameters q_k = phi^-1(p_k) still on the sides in the same order,
        // so the argument above runs for S o phi, its E' = S o phi - B (B unchanged: the same
        // corners) and x = sum lambda_k q_k. Where the parameter runs unevenly along the
        // surface (a B-spline's uneven knots or poles), E is mostly that drift within the
        // surface and E' far smaller: a bicubic plate's cells measured 0.21 -> 0.05 against a
        // normal distance of 0.049. Only the bound at equal parameters (byDistance false) and
        // the trimmed bound (corners anywhere in the cell, its piece's box in the old
        // parameter) keep E.
        if (byDistance && !trimmedCell && bound.untrimmed() > target &&
            bound.untrimmed() <= kWorthReparametrizing * target)
            if (const auto even = usableEvenSpeed(patch)) {
                // The bound under that parameter is at least |E'| anywhere (E' lies in the
                // hull of its net, whose corner points are 0, and spreadToEdges takes the
                // farthest net point from them): where sampled |E'| and the twist term already
                // pass the target, it cannot settle the cell, and its nets, the costliest part
                // of the bound, are not made (trj7_b1-ec-214.stp at relative 1e-4 made them for
                // 2,298 cells, 15% of its tessellation, and 8 settled). Only the value of a
                // bound above its target changes. The slack covers the samples' rounding.
                const double scale =
                    std::max({c00.cwiseAbs().maxCoeff(), c10.cwiseAbs().maxCoeff(),
                              c01.cwiseAbs().maxCoeff(), c11.cwiseAbs().maxCoeff()});
                const double slack = 1e-9 * target + 1e-12 * scale;
                if (largestEvenSample(patch, *even) + std::min(bound.twist, bound.planarTwist) <=
                    target + slack) {
                    const BezierPatch evenDifference =
                        differencePatch(reparametrized(patch, even->a, even->b), corner);
                    for (int pieces = 1; pieces <= kMostPieces && bound.untrimmed() > target;
                         pieces *= 2)
                        bound.spreadToEdges =
                            std::min(bound.spreadToEdges,
                                     rangeOf(evenDifference, pieces, false).spreadToEdges);
                }
            }
    }

    bound.splitDirection = splitDirectionOfNet(net, m, n, c00, c10, c01, c11);
    return bound;
}

CellErrorBound cellErrorBoundAcrossSpans(const std::vector<SpanPiece>& pieces, ErrorMode mode,
                                         double target, bool trimmedCell, bool byDistance,
                                         double pieceFraction) {
    CellErrorBound bound;
    bound.interior = bound.boundary = bound.spreadToEdges = bound.spread =
        std::numeric_limits<double>::infinity();
    // the cell's corners: the corner poles of the pieces at the cell's corners
    Point3 corner[2][2];
    bool found[2][2] = {{false, false}, {false, false}};
    for (const SpanPiece& piece : pieces) {
        const int m = piece.patch.degreeU(), n = piece.patch.degreeV();
        for (int a = 0; a <= 1; ++a)
            for (int b = 0; b <= 1; ++b)
                if ((a == 0 ? piece.s0 == 0 : piece.s1 == 1) &&
                    (b == 0 ? piece.t0 == 0 : piece.t1 == 1)) {
                    corner[a][b] = piece.patch.pole3(a * m, b * n);
                    found[a][b] = true;
                }
    }
    if (!(found[0][0] && found[0][1] && found[1][0] && found[1][1])) return bound;
    const Point3 &c00 = corner[0][0], &c10 = corner[1][0], &c01 = corner[0][1], &c11 = corner[1][1];
    bound.twist = 0.25 * (c00 - c10 - c01 + c11).norm();
    if (byDistance) bound.planarTwist = planarTwistOf(c00, c10, c01, c11);
    bound.pieceFraction = std::clamp(pieceFraction, 0.0, 1.0);
    auto bilinear = [&](double s, double t) { return bilinearAt(c00, c10, c01, c11, s, t); };

    if (mode == ErrorMode::Approximate) {
        double largest = 0;
        for (const SpanPiece& piece : pieces) {
            const int m = piece.patch.degreeU(), n = piece.patch.degreeV();
            const std::vector<Point3> samples = piece.patch.gridPoints(2 * m, 2 * n);
            for (int i = 0; i <= 2 * m; ++i)
                for (int j = 0; j <= 2 * n; ++j) {
                    const double s = piece.s0 + (piece.s1 - piece.s0) * i / (2 * m);
                    const double t = piece.t0 + (piece.t1 - piece.t0) * j / (2 * n);
                    largest =
                        std::max(largest, (samples[i * (2 * n + 1) + j] - bilinear(s, t)).norm());
                }
        }
        bound.interior = bound.spreadToEdges = bound.spread = largest;
        bound.boundary = 0;
        return bound;
    }
    std::vector<BezierPatch> differences;
    differences.reserve(pieces.size());
    for (const SpanPiece& piece : pieces) {
        const Point3 part[2][2] = {{bilinear(piece.s0, piece.t0), bilinear(piece.s0, piece.t1)},
                                   {bilinear(piece.s1, piece.t0), bilinear(piece.s1, piece.t1)}};
        differences.push_back(differencePatch(piece.patch, part));
    }
    // E's control points over all pieces, each piece's difference cut into `parts` x `parts`
    // (as rangeOf does for one patch), and those on the cell's border
    thread_local std::vector<Point3> points, sidePoints;
    auto measure = [&](int parts) {
        points.clear();
        sidePoints.clear();
        double interior2 = 0, boundary2 = 0;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            const SpanPiece& piece = pieces[k];
            std::array<BezierPatch, 4> quarters;
            if (parts == 2) quarters = differences[k].quarters();
            for (int a = 0; a < parts; ++a)
                for (int b = 0; b < parts; ++b) {
                    const BezierPatch& part = parts == 2 ? quarters[2 * a + b] : differences[k];
                    const int m = part.degreeU(), n = part.degreeV();
                    for (int i = 0; i <= m; ++i)
                        for (int j = 0; j <= n; ++j) {
                            const Point3 p = part.pole3(i, j);
                            points.push_back(p);
                            interior2 = std::max(interior2, p.squaredNorm());
                            if ((i == 0 && a == 0 && piece.s0 == 0) ||
                                (i == m && a == parts - 1 && piece.s1 == 1) ||
                                (j == 0 && b == 0 && piece.t0 == 0) ||
                                (j == n && b == parts - 1 && piece.t1 == 1)) {
                                sidePoints.push_back(p);
                                boundary2 = std::max(boundary2, p.squaredNorm());
                            }
                        }
                }
        }
        // each subdivision gives true bounds on the same quantities: keep the smallest
        const double interior = std::sqrt(interior2), boundary = std::sqrt(boundary2);
        bound.interior = std::min(bound.interior, interior);
        bound.boundary = std::min(bound.boundary, boundary);
        bound.spreadToEdges =
            std::min(bound.spreadToEdges,
                     trimmedCell ? interior + boundary : farthestPair(points, sidePoints));
        bound.spread = std::min(bound.spread, trimmedCell ? diameter(points) : 2 * interior);
    };
    measure(1);
    const double reached = bound.measure(mode, trimmedCell);
    if (reached > target && reached <= kWorthRefining * target) measure(2);
    return bound;
}

double twistTerm(const Point3& c00, const Point3& c10, const Point3& c01, const Point3& c11,
                 ErrorMode mode, bool trimmedCell, bool byDistance, double pieceFraction) {
    const double twist = 0.25 * (c00 - c10 - c01 + c11).norm();
    if (mode == ErrorMode::Guaranteed && trimmedCell)
        return std::clamp(pieceFraction, 0.0, 1.0) * twist;
    return byDistance ? std::min(twist, planarTwistOf(c00, c10, c01, c11)) : twist;
}

CellErrorBound::Speed parameterSpeed(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    double lowest = std::numeric_limits<double>::infinity();
    Point3 low = patch.pole3(0, 0), high = low;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            lowest = std::min(lowest, patch.pole(i, j)[3]);
            low = low.cwiseMin(patch.pole3(i, j));
            high = high.cwiseMax(patch.pole3(i, j));
        }
    constexpr double kInfinite = std::numeric_limits<double>::infinity();
    if (!(lowest > 0)) return {kInfinite, kInfinite};
    const double reach = (high - low).norm();
    // degree / W times the largest bracket between neighbours (di, dj) apart
    auto along = [&](int di, int dj, int degree) {
        if (degree == 0) return 0.0;
        double largest = 0;
        for (int i = 0; i + di <= m; ++i)
            for (int j = 0; j + dj <= n; ++j) {
                const double w0 = patch.pole(i, j)[3], w1 = patch.pole(i + di, j + dj)[3];
                const double step = (patch.pole3(i + di, j + dj) - patch.pole3(i, j)).norm();
                largest = std::max(largest, w1 * step + std::abs(w1 - w0) * reach);
            }
        return degree * largest / lowest;
    };
    return {along(1, 0, m), along(0, 1, n)};
}

namespace {

// |S - B| at the cell's centre, and B's centre there.
struct PlainCentre {
    double deviation = 0;
    Point3 bilinear;
};
PlainCentre plainCentre(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    // Bernstein polynomials at 1/2: C(d, k) / 2^d
    auto half = [](int degree, double* values) {
        values[0] = std::ldexp(1.0, -degree);
        for (int k = 1; k <= degree; ++k) values[k] = values[k - 1] * (degree - k + 1) / k;
    };
    double bu[kMaxDegree + 1], bv[kMaxDegree + 1];
    half(m, bu);
    half(n, bv);
    HomogeneousPoint3 sum = HomogeneousPoint3::Zero();
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) sum += bu[i] * bv[j] * patch.pole(i, j);
    PlainCentre centre;
    centre.bilinear =
        0.25 * (patch.pole3(0, 0) + patch.pole3(m, 0) + patch.pole3(0, n) + patch.pole3(m, n));
    centre.deviation = (projectHomogeneous(sum) - centre.bilinear).norm();
    return centre;
}

// Under the even-speed parameter the bound's E' is S(alpha(1/2), beta(1/2)) - B there; infinity
// where the bound does not take that parameter.
double evenCentreDeviation(const BezierPatch& patch, const Point3& bilinearCentre) {
    const auto even = usableEvenSpeed(patch);
    if (!even) return std::numeric_limits<double>::infinity();
    return (patch.point(0.5 + 0.25 * even->a, 0.5 + 0.25 * even->b) - bilinearCentre).norm();
}

}  // namespace

double centreDeviation(const BezierPatch& patch) {
    const PlainCentre centre = plainCentre(patch);
    return std::min(centre.deviation, evenCentreDeviation(patch, centre.bilinear));
}

bool centreBeyond(const BezierPatch& patch, double target) {
    // min(a, b) > target: b only where a is
    const PlainCentre centre = plainCentre(patch);
    return centre.deviation > target && evenCentreDeviation(patch, centre.bilinear) > target;
}

namespace {

// The patch's control points, projected, at i * (n + 1) + j: the net both split helpers read.
// One buffer per thread, valid until the next call.
const std::vector<Point3>& poleNet(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    thread_local std::vector<Point3> net;
    net.resize(static_cast<size_t>((m + 1) * (n + 1)));
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) net[i * (n + 1) + j] = patch.pole3(i, j);
    return net;
}

}  // namespace

namespace {

// Whether the triangle and the box [s0, s1] x [t0, t1] meet (separating axes: the box's two and
// the triangle's three).
bool triangleMeetsBox(const std::array<Point2, 3>& triangle, double s0, double s1, double t0,
                      double t1) {
    const Point2 low = triangle[0].cwiseMin(triangle[1]).cwiseMin(triangle[2]);
    const Point2 high = triangle[0].cwiseMax(triangle[1]).cwiseMax(triangle[2]);
    if (high.x() < s0 || low.x() > s1 || high.y() < t0 || low.y() > t1) return false;
    const std::array<Point2, 4> box{Point2(s0, t0), Point2(s1, t0), Point2(s1, t1), Point2(s0, t1)};
    for (int k = 0; k < 3; ++k) {
        const Point2& a = triangle[k];
        const Point2& b = triangle[(k + 1) % 3];
        const Point2& c = triangle[(k + 2) % 3];
        const Point2 normal(b.y() - a.y(), a.x() - b.x());
        const double inside = normal.dot(c - a);
        bool allOutside = true;
        for (const Point2& q : box)
            if (normal.dot(q - a) * inside >= 0) allOutside = false;
        if (allOutside) return false;
    }
    return true;
}

}  // namespace

double affineDeviation(const BezierPatch& patch, const Point3& a00, const Point3& a10,
                       const Point3& a01, double target, const std::array<Point2, 3>& triangle) {
    const Point3 corner[2][2] = {{a00, a01}, {a10, a10 + a01 - a00}};
    auto largest = [](const BezierPatch& part) {
        double largest2 = 0;
        for (int i = 0; i <= part.degreeU(); ++i)
            for (int j = 0; j <= part.degreeV(); ++j)
                largest2 = std::max(largest2, part.pole3(i, j).squaredNorm());
        return std::sqrt(largest2);
    };
    // quarters of the parts over the target that meet the triangle, three times at most: a part
    // within the target is done
    struct Part {
        BezierPatch difference;
        double s0, s1, t0, t1;
        int depth;
    };
    constexpr int kDeepest = 3;
    std::vector<Part> pending{{differencePatch(patch, corner), 0, 1, 0, 1, 0}};
    double bound = 0;
    while (!pending.empty()) {
        Part part = std::move(pending.back());
        pending.pop_back();
        if (part.depth > 0 && !triangleMeetsBox(triangle, part.s0, part.s1, part.t0, part.t1))
            continue;
        const double value = largest(part.difference);
        if (value <= target || part.depth == kDeepest) {
            bound = std::max(bound, value);
            continue;
        }
        const auto quarters = part.difference.quarters();
        const double sm = 0.5 * (part.s0 + part.s1), tm = 0.5 * (part.t0 + part.t1);
        const std::array<std::array<double, 4>, 4> boxes{{{part.s0, sm, part.t0, tm},
                                                          {part.s0, sm, tm, part.t1},
                                                          {sm, part.s1, part.t0, tm},
                                                          {sm, part.s1, tm, part.t1}}};
        for (int q = 0; q < 4; ++q)
            pending.push_back(
                {quarters[q], boxes[q][0], boxes[q][1], boxes[q][2], boxes[q][3], part.depth + 1});
    }
    return bound;
}

int preferredSplitDirection(const BezierPatch& patch) {
    const int m = patch.degreeU(), n = patch.degreeV();
    const std::vector<Point3>& net = poleNet(patch);
    const Point3 c00 = net[0], c10 = net[m * (n + 1)], c01 = net[n], c11 = net[m * (n + 1) + n];
    return splitDirectionOfNet(net, m, n, c00, c10, c01, c11);
}

double farthestNetPointAt(const BezierPatch& patch, int direction) {
    const int m = patch.degreeU(), n = patch.degreeV();
    const std::vector<Point3>& net = poleNet(patch);
    const NetBends bends = netBends(net, m, n);
    if (bends.u == 0 && bends.v == 0) return 0.5;
    const Point3 c00 = net[0], c10 = net[m * (n + 1)], c01 = net[n], c11 = net[m * (n + 1) + n];
    const FarthestNetPoint farthest = farthestFromBilinear(net, m, n, c00, c10, c01, c11);
    if (direction == 0)
        return farthest.i > 0 && farthest.i < m ? static_cast<double>(farthest.i) / m : 0.5;
    return farthest.j > 0 && farthest.j < n ? static_cast<double>(farthest.j) / n : 0.5;
}

int settlingSplitDirection(const BezierPatch& patch, int preferred, double target, bool trimmedCell,
                           bool byDistance, double pieceFraction, ErrorMode mode,
                           HalfBounds* halves, bool centreWithinTarget) {
    if (!centreWithinTarget && centreDeviation(patch) > 4 * target) return preferred;
    HalfBounds measured[2];  // by direction
    // as the kd-tree would find it of the half (a centre beyond the target is not bounded; in
    // approximate mode, whose kd-tree measures such a cell, the half counts as unsettled too,
    // which only keeps the preferred direction more often)
    auto settles = [&](const std::array<BezierPatch, 2>& pair, int direction, int k) {
        if (centreBeyond(pair[k], target)) return false;
        return measured[direction][k]
                   .emplace(cellErrorBound(pair[k], mode, target, trimmedCell, byDistance,
                                           pieceFraction))
                   .measure(mode, trimmedCell) <= target;
    };
    auto chosen = [&](int direction) {
        if (halves) *halves = std::move(measured[direction]);
        return direction;
    };
    // the other halving's centres first: most cells fail there, before any bound is computed
    const int other = 1 - preferred;
    const auto otherHalves = patch.halves(other);
    if (centreBeyond(otherHalves[0], target) || centreBeyond(otherHalves[1], target))
        return preferred;
    const auto preferredHalves = patch.halves(preferred);
    if (settles(preferredHalves, preferred, 0) && settles(preferredHalves, preferred, 1))
        return chosen(preferred);
    return settles(otherHalves, other, 0) && settles(otherHalves, other, 1) ? chosen(other)
                                                                            : chosen(preferred);
}

}  // namespace nurbslod
