#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {
namespace {

using Parameter = std::array<double, 2>;

// Largest distance between the surface and the flat triangle over the parameter triangle
// (a, b, c) whose corners are surface points, sampled on a barycentric grid.
double sampledTriangleDistance(const BezierPatch& patch, const Parameter& a, const Parameter& b,
                               const Parameter& c, int steps = 12) {
    const Point3 pa = patch.point(a[0], a[1]), pb = patch.point(b[0], b[1]);
    const Point3 pc = patch.point(c[0], c[1]);
    double worst = 0;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            const double la = double(i) / steps, lb = double(j) / steps, lc = 1 - la - lb;
            const double s = la * a[0] + lb * b[0] + lc * c[0];
            const double t = la * a[1] + lb * b[1] + lc * c[1];
            worst = std::max(worst, (patch.point(s, t) - (la * pa + lb * pb + lc * pc)).norm());
        }
    return worst;
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

// A point on the cell's border, one of the four sides at random.
Parameter onBorder(std::mt19937& random) {
    std::uniform_real_distribution<double> along(0, 1);
    const double x = along(random);
    switch (std::uniform_int_distribution<int>(0, 3)(random)) {
        case 0:
            return {x, 0};
        case 1:
            return {1, x};
        case 2:
            return {x, 1};
        default:
            return {0, x};
    }
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
                                const double d = sampledTriangleDistance(
                                    patch, onBorder(random), onBorder(random), onBorder(random));
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

}  // namespace
}  // namespace nurbslod
