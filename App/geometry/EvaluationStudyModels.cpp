#include "geometry/EvaluationStudyModels.hpp"

#include <cmath>
#include <numbers>

#include "geometry/BezierPatchGrid.hpp"
#include "geometry/UtahTeapot.hpp"

namespace nurbslod {

namespace {

// Clamped knots on [0, spans] with simple interior knots: maximal continuity, `spans` Bezier
// segments.
KnotVector uniformKnots(int degree, int spans) {
    std::vector<double> knots(degree + 1, 0.0);
    for (int k = 1; k < spans; ++k) knots.push_back(k);
    knots.insert(knots.end(), degree + 1, static_cast<double>(spans));
    return KnotVector(degree, std::move(knots));
}

// A rational wavy sheet over [0,1]^2 with the given degrees and span counts.
BSplineSurface wavySheet(int degreeU, int degreeV, int spansU, int spansV) {
    KnotVector u = uniformKnots(degreeU, spansU), v = uniformKnots(degreeV, spansV);
    const int nu = u.controlPointCount(), nv = v.controlPointCount();
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double x = static_cast<double>(i) / (nu - 1),
                         y = static_cast<double>(j) / (nv - 1);
            const double z = 0.15 * std::sin(7 * x + 1) * std::cos(5 * y) + 0.1 * x * y;
            const double w = 1.0 + 0.3 * std::sin(3 * x + 4 * y);
            poles.emplace_back(w * x, w * y, w * z, w);
        }
    return BSplineSurface(std::move(u), std::move(v), nu, nv, std::move(poles));
}

// A full circle as rational quadratic arcs: control points (x, y) and weights, the knots.
struct RationalCircle {
    std::vector<double> x, y, w;
    KnotVector knots;
};

RationalCircle rationalCircle(int arcs) {
    RationalCircle c;
    const double step = 2 * std::numbers::pi / arcs;
    const double half = std::cos(step / 2);
    std::vector<double> knots = {0, 0, 0};
    for (int k = 0; k < arcs; ++k) {
        const double a = k * step;
        c.x.push_back(std::cos(a));
        c.y.push_back(std::sin(a));
        c.w.push_back(1.0);
        // the middle point of the arc: on the bisector at 1/cos(half angle), weight cos
        c.x.push_back(std::cos(a + step / 2) / half);
        c.y.push_back(std::sin(a + step / 2) / half);
        c.w.push_back(half);
        if (k > 0) knots.insert(knots.end(), {double(k), double(k)});
    }
    c.x.push_back(1.0);
    c.y.push_back(0.0);
    c.w.push_back(1.0);
    knots.insert(knots.end(), {double(arcs), double(arcs), double(arcs)});
    c.knots = KnotVector(2, std::move(knots));
    return c;
}

// The surface of revolution about z of a profile with points (r_j, z_j) and weights w_j.
BSplineSurface revolve(const RationalCircle& circle, const KnotVector& profileKnots,
                       const std::vector<double>& r, const std::vector<double>& z,
                       const std::vector<double>& w) {
    const int nu = static_cast<int>(circle.x.size()), nv = static_cast<int>(r.size());
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double weight = circle.w[i] * w[j];
            poles.emplace_back(weight * r[j] * circle.x[i], weight * r[j] * circle.y[i],
                               weight * z[j], weight);
        }
    return BSplineSurface(circle.knots, profileKnots, nu, nv, std::move(poles));
}

}  // namespace

EvaluationModel surface15x15() {
    return {"Sup.15x15", {wavySheet(15, 15, 8, 8)}, 5000};
}
EvaluationModel surface10x10() {
    return {"Sup.10x10", {wavySheet(10, 10, 5, 5)}, 9000};
}
EvaluationModel surface5x5() {
    return {"Sup.5x5", {wavySheet(5, 5, 17, 1)}, 10000};
}
EvaluationModel teapot() {
    return {"Utah teapot", utahTeapot(), 5500};
}

EvaluationModel goblet() {
    // base disc from the axis, a thin stem, a cup flaring out and a lip turned back
    const std::vector<double> r = {0.0, 0.9, 1.0, 0.25, 0.12, 0.12, 0.3, 1.0, 1.35, 1.45, 1.4, 1.3};
    const std::vector<double> z = {0.0, 0.0, 0.08, 0.2, 0.6, 1.4, 1.8, 2.1, 2.8, 3.5, 3.62, 3.55};
    const std::vector<double> w(r.size(), 1.0);
    return {"Goblet", {revolve(rationalCircle(8), uniformKnots(3, 9), r, z, w)}, 40000};
}

EvaluationModel torus() {
    const RationalCircle tube = rationalCircle(4);
    std::vector<double> r, z;
    for (size_t j = 0; j < tube.x.size(); ++j) {
        r.push_back(2.0 + 0.6 * tube.x[j]);
        z.push_back(0.6 * tube.y[j]);
    }
    return {"Torus", {revolve(rationalCircle(4), tube.knots, r, z, tube.w)}, 40000};
}

std::vector<EvaluationModel> evaluationStudyModels() {
    return {surface15x15(), surface10x10(), surface5x5(), teapot(), goblet(), torus()};
}

std::vector<BSplineSurface> adjacentSurfaces(int continuity) {
    // one bicubic B-spline, two spans along v with the interior knot repeated 3 - continuity
    // times, cut into its Bezier pieces
    std::vector<double> knotsV = {0, 0, 0, 0};
    knotsV.insert(knotsV.end(), 3 - continuity, 1.0);
    knotsV.insert(knotsV.end(), {2, 2, 2, 2});
    KnotVector u = uniformKnots(3, 1), v(3, knotsV);
    const int nu = u.controlPointCount(), nv = v.controlPointCount();
    std::vector<HomogeneousPoint3> poles;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double x = i / 3.0, y = 2.0 * j / (nv - 1);
            poles.emplace_back(x, y, 0.4 * std::sin(2.5 * x + 1.7 * y) + 0.2 * x * y, 1.0);
        }
    const BSplineSurface whole(u, v, nu, nv, std::move(poles));
    const BezierPatchGrid pieces(whole);
    std::vector<BSplineSurface> out;
    const std::vector<double> bezierKnots = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int b = 0; b < pieces.spansV(); ++b) {
        std::vector<HomogeneousPoint3> piecePoles;
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) piecePoles.push_back(pieces.patch(0, b).pole(i, j));
        out.emplace_back(KnotVector(3, bezierKnots), KnotVector(3, bezierKnots), 4, 4,
                         std::move(piecePoles));
    }
    return out;
}

}  // namespace nurbslod
