#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "CellSamples.hpp"
#include "ParaboloidPatch.hpp"
#include "geometry/BezierReparametrization.hpp"
#include "geometry/SegmentDistance.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {
namespace {

using Parameter = std::array<double, 2>;

// testing::sampledTriangleDistance over the patch
double sampledTriangleDistance(const BezierPatch& patch, const Parameter& a, const Parameter& b,
                               const Parameter& c, int steps = 12) {
    return testing::sampledTriangleDistance([&](double s, double t) { return patch.point(s, t); },
                                            a, b, c, steps);
}

// A rational patch of the given degrees: a smooth bump with noise on the control points and
// weights from 0.3 to 3.
BezierPatch randomPatch(std::mt19937& random, int degreeU, int degreeV, double noise) {
    std::uniform_real_distribution<double> jitter(-noise, noise), weight(0.3, 3.0);
    BezierPatch patch(degreeU, degreeV);
    for (int i = 0; i <= degreeU; ++i)
        for (int j = 0; j <= degreeV; ++j) {
            const double s = double(i) / degreeU, t = double(j) / degreeV;
            const Point3 p(s + jitter(random), t + jitter(random),
                           0.3 * s * (1 - t) + 0.2 * t * t + jitter(random));
            const double w = weight(random);
            patch.pole(i, j) = HomogeneousPoint3(w * p.x(), w * p.y(), w * p.z(), w);
        }
    return patch;
}

// The bound is a true bound: never below a distance measured between the surface and triangles
// of the kinds the tessellator makes, with and without the subdivision that tightens it.
TEST(CellErrorBound, GuaranteedBoundIsNeverBelowAMeasuredDistance) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> anywhere(0, 1);
    int checked = 0;
    for (int degreeU : {1, 2, 3, 5})
        for (int degreeV : {1, 2, 3})
            for (double noise : {0.0, 0.05, 0.2})
                for (int trial = 0; trial < 4; ++trial) {
                    const BezierPatch patch = randomPatch(random, degreeU, degreeV, noise);
                    const double two =
                        std::max(sampledTriangleDistance(patch, {0, 0}, {1, 0}, {1, 1}),
                                 sampledTriangleDistance(patch, {0, 0}, {1, 1}, {0, 1}));
                    for (bool trimmedCell : {false, true}) {
                        const CellErrorBound coarse =
                            cellErrorBound(patch, ErrorMode::Guaranteed, 0, trimmedCell);
                        auto relevant = [&](const CellErrorBound& b) {
                            return trimmedCell ? b.trimmed() : b.untrimmed();
                        };
                        // targets that make the bound subdivide E or not
                        for (double fraction : {1.0, 0.8, 0.6, 0.45}) {
                            const double target = fraction * relevant(coarse);
                            const CellErrorBound bound =
                                cellErrorBound(patch, ErrorMode::Guaranteed, target, trimmedCell);
                            EXPECT_LE(relevant(bound), relevant(coarse) + 1e-15);
                            // the cell's two triangles
                            EXPECT_LE(two, bound.untrimmed() * (1 + 1e-9) + 1e-12);
                            // triangles with corners on the sides (a neighbour's points)
                            for (int k = 0; k < 6; ++k) {
                                const double d =
                                    sampledTriangleDistance(patch, testing::cellBorderPoint(random),
                                                            testing::cellBorderPoint(random),
                                                            testing::cellBorderPoint(random));
                                EXPECT_LE(d, bound.untrimmed() * (1 + 1e-9) + 1e-12);
                            }
                            // triangles with corners anywhere (trimming points)
                            for (int k = 0; k < 6; ++k) {
                                const double d = sampledTriangleDistance(
                                    patch, {anywhere(random), anywhere(random)},
                                    {anywhere(random), anywhere(random)},
                                    {anywhere(random), anywhere(random)});
                                EXPECT_LE(d, bound.trimmed() * (1 + 1e-9) + 1e-12);
                            }
                            ++checked;
                        }
                    }
                }
    EXPECT_EQ(checked, 4 * 3 * 3 * 4 * 2 * 4);
}

// Triangles whose corners lie in a box of a fraction fu x fv of the cell (a trimmed region's
// piece) deviate by at most fu fv of the twist from the bilinear patch.
TEST(CellErrorBound, TrimmedPieceInASmallerBoxTakesThatFractionOfTheTwist) {
    // a saddle: all twist, no rest (E = 0); the triangle along a diagonal of the box is off by
    // exactly fu fv h / 4 at its middle
    const double h = 2.0;
    BezierPatch saddle(1, 1);
    saddle.pole(0, 0) = HomogeneousPoint3(0, 0, 0, 1);
    saddle.pole(1, 0) = HomogeneousPoint3(1, 0, 0, 1);
    saddle.pole(0, 1) = HomogeneousPoint3(0, 1, 0, 1);
    saddle.pole(1, 1) = HomogeneousPoint3(1, 1, h, 1);
    for (const auto& [u0, v0, fu, fv] : {std::array<double, 4>{0, 0, 1, 1},
                                         {0.25, 0.5, 0.5, 0.5},
                                         {0.1, 0, 0.2, 1},
                                         {0.6, 0.7, 0.4, 0.05}}) {
        const CellErrorBound bound =
            cellErrorBound(saddle, ErrorMode::Guaranteed, 0, true, true, fu * fv);
        const double diagonal =
            sampledTriangleDistance(saddle, {u0, v0}, {u0 + fu, v0 + fv}, {u0, v0 + fv}, 24);
        EXPECT_NEAR(bound.trimmed(), fu * fv * h / 4, 1e-12);
        EXPECT_LE(diagonal, bound.trimmed() * (1 + 1e-9));
        EXPECT_GE(diagonal, 0.99 * bound.trimmed());
    }

    // random rational patches and triangles with corners anywhere in random boxes
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0, 1);
    int checked = 0;
    for (int degreeU : {1, 2, 3})
        for (int degreeV : {1, 3})
            for (double noise : {0.0, 0.2})
                for (int trial = 0; trial < 4; ++trial) {
                    const BezierPatch patch = randomPatch(random, degreeU, degreeV, noise);
                    const double fu = 0.05 + 0.95 * unit(random), fv = 0.05 + 0.95 * unit(random);
                    const double u0 = (1 - fu) * unit(random), v0 = (1 - fv) * unit(random);
                    const CellErrorBound bound =
                        cellErrorBound(patch, ErrorMode::Guaranteed, 0, true, true, fu * fv);
                    auto inBox = [&]() -> Parameter {
                        return {u0 + fu * unit(random), v0 + fv * unit(random)};
                    };
                    for (int k = 0; k < 8; ++k) {
                        const double d = sampledTriangleDistance(patch, inBox(), inBox(), inBox());
                        EXPECT_LE(d, bound.trimmed() * (1 + 1e-9) + 1e-12);
                        ++checked;
                    }
                }
    EXPECT_EQ(checked, 3 * 2 * 2 * 4 * 8);
}

// A cylinder piece of 30 degrees (rational quadratic arc, middle weight cos 15 deg) bulges to
// one side only: its two triangles are off by the sagitta r (1 - cos 15 deg) at the middle.
// The sum of the largest deviations inside and on the sides (the bound before) is 2.7 times
// that; the spread of E's control points is 1.35 times, and 1.0 times after subdividing E.
TEST(CellErrorBound, CylinderPieceBoundIsClose) {
    const double r = 2.0, angle = M_PI / 6, w = std::cos(angle / 2);
    BezierPatch patch(2, 1);
    const Point3 arc[3] = {
        {r, 0, 0}, {r, r * std::tan(angle / 2), 0}, {r * std::cos(angle), r * std::sin(angle), 0}};
    const double weight[3] = {1, w, 1};
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 1; ++j) {
            const Point3 p = arc[i] + Point3(0, 0, 3.0 * j);
            patch.pole(i, j) = HomogeneousPoint3(weight[i] * p.x(), weight[i] * p.y(),
                                                 weight[i] * p.z(), weight[i]);
        }
    const double sagitta = r * (1 - std::cos(angle / 2));
    const double measured = std::max(sampledTriangleDistance(patch, {0, 0}, {1, 0}, {1, 1}, 64),
                                     sampledTriangleDistance(patch, {0, 0}, {1, 1}, {0, 1}, 64));
    EXPECT_NEAR(measured, sagitta, 1e-3 * sagitta);
    const CellErrorBound coarse = cellErrorBound(patch, ErrorMode::Guaranteed);
    EXPECT_GE(coarse.interior + coarse.boundary + coarse.twist, 2.6 * sagitta);
    EXPECT_GE(coarse.untrimmed(), sagitta);
    EXPECT_LE(coarse.untrimmed(), 1.4 * sagitta);
    const CellErrorBound coarseTrimmed = cellErrorBound(patch, ErrorMode::Guaranteed, 0, true);
    EXPECT_GE(coarseTrimmed.trimmed(), sagitta);
    EXPECT_LE(coarseTrimmed.trimmed(), 1.4 * sagitta);
    const CellErrorBound refined =
        cellErrorBound(patch, ErrorMode::Guaranteed, 0.99 * sagitta, true);
    EXPECT_GE(refined.untrimmed(), sagitta);
    EXPECT_LE(refined.trimmed(), 1.02 * sagitta);
}

// Distance from p to the triangle (a, b, c): to its plane where the foot is inside, else to
// the nearest side.
double distanceToTriangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
    const Point3 n = (b - a).cross(c - a).normalized();
    const Point3 foot = p - (p - a).dot(n) * n;
    auto inside = [&](const Point3& x, const Point3& y) {
        return (y - x).cross(foot - x).dot(n) >= 0;
    };
    if (inside(a, b) && inside(b, c) && inside(c, a)) return std::abs((p - a).dot(n));
    return std::min(
        {distanceToSegment(p, a, b), distanceToSegment(p, b, c), distanceToSegment(p, c, a)});
}

// A column of a cone cut along two generators (radius 12 at the bottom, 13.6 at the top, 2.26
// high: bug33398.step's face 1, 1/64 of a turn): its corners make an isosceles trapezoid, whose
// twist is a quarter of the difference of its parallel sides, 2.4 times the top's bulge here.
// The triangles lie in the trapezoid's plane, so the twist moves points within it and not away
// from the cone: measured as distances, both ways, the triangles are off by the bulge alone.
// The bound (planarTwist) is 1.33 times the bulge; with the twist it was 3.7 times, and at
// equal parameters the triangles are 2.6 times the bulge off.
TEST(CellErrorBound, ConeColumnIsBoundedByItsBulgeNotItsTwist) {
    const double r0 = 12.0, r1 = 13.6, height = 2.26, angle = M_PI / 32;
    const double w = std::cos(angle / 2);
    BezierPatch patch(2, 1);
    for (int j = 0; j <= 1; ++j) {
        const double r = j == 0 ? r0 : r1, z = j == 0 ? 0 : height;
        const Point3 arc[3] = {{r, 0, z},
                               {r, r * std::tan(angle / 2), z},
                               {r * std::cos(angle), r * std::sin(angle), z}};
        const double weight[3] = {1, w, 1};
        for (int i = 0; i <= 2; ++i)
            patch.pole(i, j) = HomogeneousPoint3(weight[i] * arc[i].x(), weight[i] * arc[i].y(),
                                                 weight[i] * arc[i].z(), weight[i]);
    }
    const Point3 c00 = patch.point(0, 0), c10 = patch.point(1, 0);
    const Point3 c01 = patch.point(0, 1), c11 = patch.point(1, 1);
    // distance from a point to the cone, in its meridian half-plane
    const Point3 bottom(r0, 0, 0), top(r1, 0, height);
    auto toCone = [&](const Point3& p) {
        const double rho = std::hypot(p.x(), p.y());
        const Point3 q(rho, 0, p.z());
        const Point3 along = (top - bottom).normalized();
        return ((q - bottom) - (q - bottom).dot(along) * along).norm();
    };
    double surfaceToTriangles = 0, trianglesToSurface = 0, atEqualParameters = 0;
    constexpr int steps = 64;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; j <= steps; ++j) {
            const double s = double(i) / steps, t = double(j) / steps;
            const Point3 p = patch.point(s, t);
            surfaceToTriangles =
                std::max(surfaceToTriangles, std::min(distanceToTriangle(p, c00, c10, c11),
                                                      distanceToTriangle(p, c00, c11, c01)));
            // the two triangles' points at barycentric grid positions
            if (i + j <= steps) {
                const double la = s, lb = t, lc = 1 - s - t;
                for (const auto& [a, b, c] :
                     {std::array<Point3, 3>{c00, c10, c11}, std::array<Point3, 3>{c00, c11, c01}})
                    trianglesToSurface =
                        std::max(trianglesToSurface, toCone(la * a + lb * b + lc * c));
            }
        }
    atEqualParameters = std::max(sampledTriangleDistance(patch, {0, 0}, {1, 0}, {1, 1}, steps),
                                 sampledTriangleDistance(patch, {0, 0}, {1, 1}, {0, 1}, steps));
    const double bulge = r1 * (1 - std::cos(angle / 2));
    const CellErrorBound bound = cellErrorBound(patch, ErrorMode::Guaranteed);
    EXPECT_LT(bound.planarTwist, 1e-12);
    EXPECT_GT(bound.twist, 2 * bulge);
    EXPECT_NEAR(surfaceToTriangles, bulge, 0.02 * bulge);
    EXPECT_LE(trianglesToSurface, bulge * (1 + 1e-9));
    EXPECT_LE(surfaceToTriangles, bound.untrimmed());
    EXPECT_LE(bound.untrimmed(), 1.4 * bulge);
    // at equal parameters the triangles are farther than the geometric bound: the twist term
    // is what that measure needs, and what the distance does not
    EXPECT_GT(atEqualParameters, 1.5 * bound.untrimmed());
    // A trimmed cell: the guaranteed bound keeps the twist, the approximate estimate takes the
    // distance (the bulge) whether trimming curves cross the cell or not.
    const CellErrorBound approximate = cellErrorBound(patch, ErrorMode::Approximate);
    EXPECT_GT(bound.measure(ErrorMode::Guaranteed, true), bound.twist);
    EXPECT_EQ(approximate.measure(ErrorMode::Approximate, true),
              approximate.measure(ErrorMode::Approximate, false));
    EXPECT_LE(approximate.measure(ErrorMode::Approximate, true), 1.4 * bulge);
}

// An oblique cone's column from its apex (a ruled patch whose first row of poles is one point,
// as trj7_b1-ec-214.stp's half cones): two corners coincide, so there is no plane of the sides
// at one of them, and the twist is a quarter of the far side, 5 times the bulge here. The
// corners are a triangle and the triangles over the cell lie in its plane: measured as
// distances, both ways, they are off by the bulge alone, for the cell's own triangles and for
// triangles through points on its sides. A side that is merely short (delta) costs its length.
TEST(CellErrorBound, ColumnAtAnApexIsBoundedByItsBulgeNotItsTwist) {
    const double radius = 4, angle = 0.4, w = std::cos(angle / 2);
    const Point3 apex(1.0, -0.5, 2.3);
    auto arcPole = [&](int i) {
        return i == 0   ? Point3(radius, 0, 0)
               : i == 1 ? Point3(radius, radius * std::tan(angle / 2), 0)
                        : Point3(radius * std::cos(angle), radius * std::sin(angle), 0);
    };
    // u along the arc (degree 2, rational), v from the apex row (spread by delta) to the arc
    auto column = [&](double delta) {
        BezierPatch patch(2, 1);
        for (int i = 0; i <= 2; ++i) {
            const double weight = i == 1 ? w : 1;
            const Point3 bottom = apex + Point3(delta * i / 2, 0, 0), top = arcPole(i);
            patch.pole(i, 0) = HomogeneousPoint3(weight * bottom.x(), weight * bottom.y(),
                                                 weight * bottom.z(), weight);
            patch.pole(i, 1) =
                HomogeneousPoint3(weight * top.x(), weight * top.y(), weight * top.z(), weight);
        }
        return patch;
    };
    // Distance from p to the patch: the nearest generator (v lines are straight) among fine
    // samples, refined by a ternary search around it.
    auto toSurface = [&](const BezierPatch& patch, const Point3& p) {
        auto onGenerator = [&](double s) {
            return distanceToSegment(p, patch.point(s, 0), patch.point(s, 1));
        };
        constexpr int samples = 400;
        int best = 0;
        for (int k = 1; k <= samples; ++k)
            if (onGenerator(double(k) / samples) < onGenerator(double(best) / samples)) best = k;
        double lo = std::max(0.0, (best - 1.0) / samples);
        double hi = std::min(1.0, (best + 1.0) / samples);
        for (int k = 0; k < 60; ++k) {
            const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
            if (onGenerator(a) < onGenerator(b))
                hi = b;
            else
                lo = a;
        }
        return std::min(onGenerator(0.5 * (lo + hi)), onGenerator(double(best) / samples));
    };
    auto toTriangle = [](const Point3& p, const std::array<Point3, 3>& triangle) {
        const auto& [a, b, c] = triangle;
        if ((b - a).cross(c - a).norm() > 1e-14) return distanceToTriangle(p, a, b, c);
        // a fan's triangle at the apex, two of its corners one point: a segment
        return std::min(
            {distanceToSegment(p, a, b), distanceToSegment(p, b, c), distanceToSegment(p, a, c)});
    };
    const double bulge = radius * (1 - std::cos(angle / 2));
    for (const double delta : {0.0, 0.1 * bulge}) {
        const BezierPatch patch = column(delta);
        const CellErrorBound bound = cellErrorBound(patch, ErrorMode::Guaranteed);
        EXPECT_LE(bound.planarTwist, delta * (1 + 1e-9) + 1e-12);
        EXPECT_GT(bound.twist, 4.5 * bulge);
        EXPECT_LE(bound.untrimmed(), 1.4 * bulge + delta);
        // the cell's two triangles, and triangles through points its neighbours put on its
        // sides: one on the arc, one on each generator
        const std::vector<std::vector<Parameter>> triangulations = {
            {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}},
            {{0, 0}, {1, 0}, {0.5, 1}, {1, 0}, {1, 1}, {0.5, 1}, {0, 0}, {0.5, 1}, {0, 1}},
            {{0, 0},
             {1, 0},
             {1, 0.5},
             {0, 0},
             {1, 0.5},
             {0, 0.5},
             {0, 0.5},
             {1, 0.5},
             {1, 1},
             {0, 0.5},
             {1, 1},
             {0, 1}}};
        for (const auto& corners : triangulations) {
            std::vector<std::array<Point3, 3>> triangles;
            for (std::size_t k = 0; k < corners.size(); k += 3)
                triangles.push_back({patch.point(corners[k][0], corners[k][1]),
                                     patch.point(corners[k + 1][0], corners[k + 1][1]),
                                     patch.point(corners[k + 2][0], corners[k + 2][1])});
            double surfaceToTriangles = 0, trianglesToSurface = 0;
            constexpr int steps = 24;
            for (int i = 0; i <= steps; ++i)
                for (int j = 0; j <= steps; ++j) {
                    const double s = double(i) / steps, t = double(j) / steps;
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const auto& triangle : triangles)
                        nearest = std::min(nearest, toTriangle(patch.point(s, t), triangle));
                    surfaceToTriangles = std::max(surfaceToTriangles, nearest);
                    if (i + j <= steps)
                        for (const auto& [a, b, c] : triangles)
                            trianglesToSurface =
                                std::max(trianglesToSurface,
                                         toSurface(patch, s * a + t * b + (1 - s - t) * c));
                }
            // off by the bulge, or by less where points on the generators halve the cell
            EXPECT_GT(surfaceToTriangles, 0.2 * bulge) << "delta " << delta;
            EXPECT_LE(surfaceToTriangles, bound.untrimmed()) << "delta " << delta;
            EXPECT_LE(trianglesToSurface, bound.untrimmed()) << "delta " << delta;
        }
    }
}

// A cell whose corners are a convex quadrilateral but for an out-of-plane part w_perp of the
// twist w (a near parallelogram, bent a little out of its plane, on a bulging surface): its
// triangles are within spreadToEdges + |w_perp| (1/4 + sqrt 2 |w_par| / (4 sigma)) of the
// surface both ways, measured as distances, sigma the least stretch of the flattened map. Near a
// parallelogram that is about a quarter of |w_perp|, where the bound took all of it.
TEST(CellErrorBound, FlatCellsOutOfPlaneTwistCountsAboutAQuarter) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1), anywhere(0, 1);
    // distance from p to the patch over the cell: the nearest of a grid, refined twice around it
    auto toSurface = [](const BezierPatch& patch, const Point3& p) {
        double bestS = 0.5, bestT = 0.5, best = std::numeric_limits<double>::infinity();
        double half = 0.5;
        for (int level = 0; level < 4; ++level) {
            const double s0 = bestS, t0 = bestT;
            constexpr int n = 16;
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    const double s = std::clamp(s0 + half * (2.0 * i / n - 1), 0.0, 1.0);
                    const double t = std::clamp(t0 + half * (2.0 * j / n - 1), 0.0, 1.0);
                    const double d = (patch.point(s, t) - p).norm();
                    if (d < best) best = d, bestS = s, bestT = t;
                }
            half *= 2.0 / 16;
        }
        return best;
    };
    int tighter = 0, checked = 0;
    for (int trial = 0; trial < 24; ++trial) {
        // corners: a parallelogram 2 x 1 moved by up to 0.15 in the plane and `lift` out of it
        const double lift = 0.02 + 0.04 * anywhere(random);
        Point3 corners[2][2];
        for (int i = 0; i <= 1; ++i)
            for (int j = 0; j <= 1; ++j)
                corners[i][j] = Point3(2.0 * i + 0.5 * j + 0.15 * unit(random),
                                       1.0 * j + 0.15 * unit(random), lift * unit(random));
        // a biquadratic patch: the bilinear map of the corners plus a bulge up to 0.02
        BezierPatch patch(2, 2);
        const double bulge = 0.02 * anywhere(random);
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; j <= 2; ++j) {
                const double s = i / 2.0, t = j / 2.0;
                Point3 p = (1 - s) * ((1 - t) * corners[0][0] + t * corners[0][1]) +
                           s * ((1 - t) * corners[1][0] + t * corners[1][1]);
                if (i == 1 || j == 1) p.z() += 2 * bulge * (i == 1 && j == 1 ? 2 : 1);
                patch.pole(i, j) = HomogeneousPoint3(p.x(), p.y(), p.z(), 1);
            }
        const CellErrorBound bound = cellErrorBound(patch, ErrorMode::Guaranteed);
        ASSERT_TRUE(std::isfinite(bound.planarTwist));
        const Point3 w = corners[0][0] - corners[1][0] - corners[0][1] + corners[1][1];
        const Point3 n =
            (corners[1][0] - corners[0][0]).cross(corners[0][1] - corners[0][0]).normalized();
        tighter += bound.planarTwist < 0.5 * std::abs(w.dot(n));
        // the cell's two triangles, and triangles through points on its sides
        std::vector<std::array<Parameter, 3>> triangles = {{{{0, 0}, {1, 0}, {1, 1}}},
                                                           {{{0, 0}, {1, 1}, {0, 1}}}};
        for (int k = 0; k < 4; ++k)
            triangles.push_back({testing::cellBorderPoint(random), testing::cellBorderPoint(random),
                                 testing::cellBorderPoint(random)});
        double surfaceToTriangles = 0, trianglesToSurface = 0;
        constexpr int steps = 10;
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; j <= steps; ++j) {
                const Point3 p = patch.point(double(i) / steps, double(j) / steps);
                // the two triangles cover the cell: the nearest of them
                surfaceToTriangles =
                    std::max(surfaceToTriangles,
                             std::min(distanceToTriangle(p, patch.point(0, 0), patch.point(1, 0),
                                                         patch.point(1, 1)),
                                      distanceToTriangle(p, patch.point(0, 0), patch.point(1, 1),
                                                         patch.point(0, 1))));
                if (i + j > steps) continue;
                const double la = double(i) / steps, lb = double(j) / steps, lc = 1 - la - lb;
                for (const auto& [a, b, c] : triangles)
                    trianglesToSurface = std::max(
                        trianglesToSurface, toSurface(patch, la * patch.point(a[0], a[1]) +
                                                                 lb * patch.point(b[0], b[1]) +
                                                                 lc * patch.point(c[0], c[1])));
            }
        EXPECT_LE(surfaceToTriangles, bound.untrimmed() * (1 + 1e-9)) << "trial " << trial;
        EXPECT_LE(trianglesToSurface, bound.untrimmed() * (1 + 1e-9)) << "trial " << trial;
        ++checked;
    }
    EXPECT_EQ(checked, 24);
    EXPECT_GE(tighter, 20);
}

// A saddle (a bilinear patch: no bulge at all) is off its two triangles by its twist alone, and
// no side of it may stand in for that twist.
TEST(CellErrorBound, SaddleKeepsItsTwist) {
    BezierPatch patch(1, 1);
    patch.pole(0, 0) = HomogeneousPoint3(0, 0, 0, 1);
    patch.pole(1, 0) = HomogeneousPoint3(1, 0, 0, 1);
    patch.pole(0, 1) = HomogeneousPoint3(0, 1, 0, 1);
    patch.pole(1, 1) = HomogeneousPoint3(1, 1, 1, 1);
    const CellErrorBound bound = cellErrorBound(patch, ErrorMode::Guaranteed);
    const Point3 c00 = patch.point(0, 0), c10 = patch.point(1, 0);
    const Point3 c01 = patch.point(0, 1), c11 = patch.point(1, 1);
    double surfaceToTriangles = 0;
    for (int i = 0; i <= 32; ++i)
        for (int j = 0; j <= 32; ++j) {
            const Point3 p = patch.point(i / 32.0, j / 32.0);
            surfaceToTriangles =
                std::max(surfaceToTriangles, std::min(distanceToTriangle(p, c00, c10, c11),
                                                      distanceToTriangle(p, c00, c11, c01)));
        }
    EXPECT_GT(surfaceToTriangles, 0.1);
    EXPECT_LE(surfaceToTriangles, bound.untrimmed());
    EXPECT_NEAR(bound.untrimmed(), 0.25, 1e-12);
}

// z = a s (1 - s) + b t (1 - t) over the unit square, as a patch of degree 6 in s and 2 in t:
// the control points of a quadratic raised to degree d are its blossom at (0, .., 1, ..), so
// z_i = a (i / d - i (i - 1) / (d (d - 1))) along s, the same along t.
BezierPatch bulges(double a, double b) {
    const int m = 6, n = 2;
    BezierPatch patch(m, n);
    auto raised = [](double bulge, int k, int d) {
        return bulge * (double(k) / d - double(k) * (k - 1) / (double(d) * (d - 1)));
    };
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
            patch.pole(i, j) = HomogeneousPoint3(double(i) / m, double(j) / n,
                                                 raised(a, i, m) + raised(b, j, n), 1);
    return patch;
}

// The surface bulges a / 4 across s and b / 4 across t, but the net's second differences are
// 2a / (m (m - 1)) and 2b / (n (n - 1)): with a = 4b, a degree-6 net bends a quarter as much
// along s as a degree-2 net along t, and a split by the plain second differences halved t,
// where halving s is what lowers the bound. Weighed by m (m - 1) (splitOfNet) the split is
// along s, and each half's bound is then lower than either half's of the split along t.
TEST(CellErrorBound, SplitGoesAcrossTheLargerBulgeWhateverTheDegrees) {
    const BezierPatch patch = bulges(4.0, 1.0);
    EXPECT_NEAR(patch.point(0.5, 0.25).z() - patch.point(0.5, 0).z(), 0.1875, 1e-12);
    EXPECT_NEAR(patch.point(0.5, 0).z() - patch.point(0, 0).z(), 1.0, 1e-12);
    EXPECT_EQ(preferredSplitDirection(patch), 0);
    EXPECT_EQ(cellErrorBound(patch, ErrorMode::Guaranteed).splitDirection, 0);
    auto largestHalf = [&](int direction) {
        double largest = 0;
        for (const auto& [low, high] : {std::pair{0.0, 0.5}, std::pair{0.5, 1.0}}) {
            const BezierPatch half = direction == 0 ? patch.restricted(low, high, 0, 1)
                                                    : patch.restricted(0, 1, low, high);
            largest = std::max(largest, cellErrorBound(half, ErrorMode::Guaranteed).untrimmed());
        }
        return largest;
    };
    EXPECT_LT(largestHalf(0), 0.6 * largestHalf(1)) << largestHalf(0) << " vs " << largestHalf(1);
    // equal degrees keep the plain second differences: the same bulges on a net of degree 2
    // both ways are split along s
    BezierPatch square(2, 2);
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
            square.pole(i, j) =
                HomogeneousPoint3(i / 2.0, j / 2.0, (i == 1 ? 2.0 : 0.0) + (j == 1 ? 0.5 : 0.0), 1);
    EXPECT_EQ(preferredSplitDirection(square), 0);
}

}  // namespace
// The kd-tree splits a cell whose centre is off by more than its target without computing the
// bound: sound only if that deviation is below every measure, with any subdivision and piece
// box, and if the split is the one the bound would choose.
TEST(CellErrorBound, CentreDeviationIsBelowEveryMeasureAndTheSplitIsTheBounds) {
    std::mt19937 random(23);
    int checked = 0;
    for (int degreeU : {1, 2, 3, 5})
        for (int degreeV : {1, 2, 3, 4})
            for (double noise : {0.0, 0.05, 0.3})
                for (int trial = 0; trial < 6; ++trial) {
                    const BezierPatch patch = randomPatch(random, degreeU, degreeV, noise);
                    const double centre = centreDeviation(patch);
                    const Point3 bilinearCentre =
                        0.25 * (patch.pole3(0, 0) + patch.pole3(degreeU, 0) +
                                patch.pole3(0, degreeV) + patch.pole3(degreeU, degreeV));
                    const EvenSpeed even = evenSpeed(patch);
                    EXPECT_NEAR(centre,
                                std::min((patch.point(0.5, 0.5) - bilinearCentre).norm(),
                                         (patch.point(0.5 + 0.25 * even.a, 0.5 + 0.25 * even.b) -
                                          bilinearCentre)
                                             .norm()),
                                1e-12);
                    // what the kd-tree asks: the same answer, with or without the even point
                    for (double target : {0.0, 0.5 * centre, centre, 2 * centre,
                                          (patch.point(0.5, 0.5) - bilinearCentre).norm()})
                        EXPECT_EQ(centreBeyond(patch, target), centre > target);
                    const int direction = preferredSplitDirection(patch);
                    for (bool trimmedCell : {false, true})
                        for (double fraction : {1.0, 0.5, 0.1, 0.0})
                            for (double target : {0.0, 0.5 * centre, centre, 2 * centre}) {
                                const CellErrorBound bound =
                                    cellErrorBound(patch, ErrorMode::Guaranteed, target,
                                                   trimmedCell, true, fraction);
                                EXPECT_LE(centre,
                                          bound.measure(ErrorMode::Guaranteed, trimmedCell) *
                                                  (1 + 1e-12) +
                                              1e-15);
                                EXPECT_EQ(direction, bound.splitDirection);
                                ++checked;
                            }
                }
    EXPECT_EQ(checked, 4 * 4 * 3 * 6 * 2 * 4 * 4);
}

// Under the even-speed parameter the bound for corners on the sides is a bound on distances,
// not at equal parameters: checked as distances, both ways, on patches whose parameter runs
// unevenly (poles crowded to one end, as uneven knots leave them). Mesh to surface: each
// triangle point's distance to a fine triangulation of the patch, less that triangulation's
// own bound, cannot pass the true distance. Surface to mesh: exact, to the triangles.
TEST(CellErrorBound, EvenSpeedBoundIsNeverBelowAMeasuredDistance) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> jitter(-0.03, 0.03), weight(0.5, 2.0);
    constexpr int kFine = 32;
    int tighter = 0, checked = 0;
    for (int degreeU : {2, 3, 5})
        for (int degreeV : {1, 2, 3})
            for (int trial = 0; trial < 4; ++trial) {
                BezierPatch patch(degreeU, degreeV);
                const double crowd = 1.0 + trial;  // poles at (i / m)^crowd along u
                for (int i = 0; i <= degreeU; ++i)
                    for (int j = 0; j <= degreeV; ++j) {
                        const double s = std::pow(double(i) / degreeU, crowd);
                        const double t = std::pow(double(j) / degreeV, 2 - 0.25 * trial);
                        const Point3 p(s + jitter(random), t + jitter(random),
                                       0.25 * std::sin(3 * s) * std::cos(2 * t) + jitter(random));
                        const double w = trial % 2 ? weight(random) : 1.0;
                        patch.pole(i, j) = HomogeneousPoint3(w * p.x(), w * p.y(), w * p.z(), w);
                    }
                const CellErrorBound coarse = cellErrorBound(patch, ErrorMode::Guaranteed, 0);
                // the fine triangulation and how far it may be from the patch
                std::vector<std::array<Point3, 3>> fine;
                double fineBound = 0;
                for (int a = 0; a < kFine; ++a)
                    for (int b = 0; b < kFine; ++b) {
                        const double s0 = double(a) / kFine, s1 = double(a + 1) / kFine;
                        const double t0 = double(b) / kFine, t1 = double(b + 1) / kFine;
                        const BezierPatch piece = patch.restricted(s0, s1, t0, t1);
                        fineBound = std::max(
                            fineBound, cellErrorBound(piece, ErrorMode::Guaranteed, 0, false, false)
                                           .untrimmed());
                        const Point3 p00 = patch.point(s0, t0), p10 = patch.point(s1, t0);
                        const Point3 p01 = patch.point(s0, t1), p11 = patch.point(s1, t1);
                        fine.push_back({p00, p10, p11});
                        fine.push_back({p00, p11, p01});
                    }
                auto toFine = [&](const Point3& q) {
                    double d = std::numeric_limits<double>::infinity();
                    for (const auto& t : fine)
                        d = std::min(d, distanceToTriangle(q, t[0], t[1], t[2]));
                    return d;
                };
                for (double fraction : {0.9, 0.6, 0.4}) {
                    const double target = fraction * coarse.untrimmed();
                    const CellErrorBound bound =
                        cellErrorBound(patch, ErrorMode::Guaranteed, target, false, true);
                    EXPECT_LE(bound.untrimmed(), coarse.untrimmed() * (1 + 1e-12));
                    tighter += bound.spreadToEdges < 0.95 * coarse.spreadToEdges;
                    // the cell's two triangles and two with corners on the sides
                    std::vector<std::array<Parameter, 3>> triangles = {
                        {Parameter{0, 0}, Parameter{1, 0}, Parameter{1, 1}},
                        {Parameter{0, 0}, Parameter{1, 1}, Parameter{0, 1}}};
                    for (int k = 0; k < 2; ++k)
                        triangles.push_back({testing::cellBorderPoint(random),
                                             testing::cellBorderPoint(random),
                                             testing::cellBorderPoint(random)});
                    for (const auto& t : triangles) {
                        const Point3 a = patch.point(t[0][0], t[0][1]);
                        const Point3 b = patch.point(t[1][0], t[1][1]);
                        const Point3 c = patch.point(t[2][0], t[2][1]);
                        for (int i = 0; i <= 6; ++i)
                            for (int j = 0; i + j <= 6; ++j) {
                                const double la = i / 6.0, lb = j / 6.0, lc = 1 - la - lb;
                                EXPECT_LE(toFine(la * a + lb * b + lc * c) - fineBound,
                                          bound.untrimmed() * (1 + 1e-9) + 1e-12);
                            }
                    }
                    // every surface point is within the bound of the cell's two triangles
                    const Point3 c00 = patch.pole3(0, 0), c10 = patch.pole3(degreeU, 0);
                    const Point3 c01 = patch.pole3(0, degreeV), c11 = patch.pole3(degreeU, degreeV);
                    for (int i = 0; i <= 16; ++i)
                        for (int j = 0; j <= 16; ++j) {
                            const Point3 q = patch.point(i / 16.0, j / 16.0);
                            const double d = std::min(distanceToTriangle(q, c00, c10, c11),
                                                      distanceToTriangle(q, c00, c11, c01));
                            EXPECT_LE(d, bound.untrimmed() * (1 + 1e-9) + 1e-12);
                        }
                    ++checked;
                }
            }
    EXPECT_EQ(checked, 3 * 3 * 4 * 3);
    EXPECT_GT(tighter, checked / 4);  // the even speed does take most of them in
}

using testing::unitParaboloid;

// A triangle's affine map leaves the surface fastest beyond the triangle: over the small
// triangle (0, 0), (1/2, 0), (0, 1/2) of the paraboloid, with the map through its corners'
// points (z = s/2 + t/2), the surface is at most 1/8 off (at (1/4, 1/4)), while over the whole
// square the same map is 1 off at (1, 1). The bound holds the triangle's 1/8 and stays well
// under the square's once the target asks for it; a target it already meets takes the first,
// whole-square bound; a patch the map reproduces is bounded by 0.
TEST(AffineDeviation, BoundsTheTriangleNotItsBox) {
    const BezierPatch paraboloid = unitParaboloid();
    const std::array<Point2, 3> triangle{Point2(0, 0), Point2(0.5, 0), Point2(0, 0.5)};
    const Point3 a00(0, 0, 0), a10(1, 0, 0.5), a01(0, 1, 0.5);
    const double fine = affineDeviation(paraboloid, a00, a10, a01, 1e-3, triangle);
    EXPECT_GE(fine, 0.125 - 1e-12);
    EXPECT_LE(fine, 0.2);
    const double coarse = affineDeviation(paraboloid, a00, a10, a01, 10.0, triangle);
    EXPECT_GE(coarse, 1.0 - 1e-12);
    // the plane z = 2 s + 3 t and its own affine map
    BezierPatch plane(2, 2);
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
            plane.pole(i, j) = HomogeneousPoint3(i / 2.0, j / 2.0, i + 1.5 * j, 1);
    EXPECT_LE(
        affineDeviation(plane, Point3(0, 0, 0), Point3(1, 0, 2), Point3(0, 1, 3), 1e-9, triangle),
        1e-12);
}

// For triangles of random points on a random rational patch, the bound is at least the distance
// of the surface from the triangle's map at sampled points of the triangle.
TEST(AffineDeviation, HoldsAtEverySampledPointOfTheTriangle) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const BezierPatch patch = randomPatch(random, 3, 3, 0.3);
    int checked = 0;
    for (int trial = 0; trial < 50; ++trial) {
        std::array<Point2, 3> triangle;
        for (auto& q : triangle) q = Point2(unit(random), unit(random));
        Eigen::Matrix2d across;
        across << triangle[1].x() - triangle[0].x(), triangle[2].x() - triangle[0].x(),
            triangle[1].y() - triangle[0].y(), triangle[2].y() - triangle[0].y();
        if (std::abs(across.determinant()) < 1e-3) continue;
        const Point3 origin = patch.point(triangle[0].x(), triangle[0].y());
        Eigen::Matrix<double, 3, 2> differences;
        differences << patch.point(triangle[1].x(), triangle[1].y()) - origin,
            patch.point(triangle[2].x(), triangle[2].y()) - origin;
        const Eigen::Matrix<double, 3, 2> gradient = differences * across.inverse();
        auto affineAt = [&](const Point2& q) -> Point3 {
            return origin + gradient * (q - triangle[0]);
        };
        const double bound = affineDeviation(patch, affineAt(Point2(0, 0)), affineAt(Point2(1, 0)),
                                             affineAt(Point2(0, 1)), 1e-4, triangle);
        for (int a = 0; a <= 10; ++a)
            for (int b = 0; a + b <= 10; ++b) {
                const Point2 q = triangle[0] + a / 10.0 * (triangle[1] - triangle[0]) +
                                 b / 10.0 * (triangle[2] - triangle[0]);
                EXPECT_LE((patch.point(q.x(), q.y()) - affineAt(q)).norm(), bound * (1 + 1e-12));
            }
        ++checked;
    }
    EXPECT_GT(checked, 40);
}

}  // namespace nurbslod
