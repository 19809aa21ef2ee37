#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "CorpusMesh.hpp"
#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {
namespace {

double triangleDeviation(const BezierPatch& cell, const std::array<double, 2> (&c)[3],
                         const std::vector<Point3>& dense, bool equalParameter) {
    const Point3 p[3] = {cell.point(c[0][0], c[0][1]), cell.point(c[1][0], c[1][1]),
                         cell.point(c[2][0], c[2][1])};
    double worst = 0;
    const int n = 16;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const double a = double(i) / n, b = double(j) / n, g = 1 - a - b;
            const Point3 m = a * p[0] + b * p[1] + g * p[2];
            if (equalParameter) {
                const double s = a * c[0][0] + b * c[1][0] + g * c[2][0];
                const double t = a * c[0][1] + b * c[1][1] + g * c[2][1];
                worst = std::max(worst, (cell.point(s, t) - m).norm());
            } else {
                double best = 1e300;
                for (const auto& q : dense) best = std::min(best, (q - m).squaredNorm());
                worst = std::max(worst, std::sqrt(best));
            }
        }
    return worst;
}

TEST(Scratch, BoundAgainstDeviation) {
    const char* name = std::getenv("SCRATCH_MODEL");
    if (!name) GTEST_SKIP();
    const auto corpus = test::corpusModel(name);
    const int face = std::atoi(std::getenv("SCRATCH_FACE")) - 1;
    const double T = std::atof(std::getenv("SCRATCH_REL")) * corpus->model.boundingBoxDiagonal;
    const double target = std::atof(std::getenv("SCRATCH_TARGET")) * T;
    const int faceEnd = std::getenv("SCRATCH_FACE_END") ? std::atoi(std::getenv("SCRATCH_FACE_END")) : face + 1;
    for (int f = face; f < faceEnd; ++f) {
    const BezierPatchGrid grid(corpus->model.faces[f].surface);
    if (grid.spansU() != 1 || grid.spansV() != 1) continue;
    const BezierPatch& patch = grid.patch(0, 0);
    int firstBound = 0, firstEqual = 0, firstTrue = 0;
    for (int n = 1; n <= 16 && !firstBound; ++n) { const int nu = n, nv = n;
        double worstBound = 0, worstEqual = 0, worstTrue = 0, worstSpread = 0, worstTwist = 0,
               worstPlanar = 0;
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                const BezierPatch cell =
                    patch.restricted(double(i) / nu, double(i + 1) / nu, double(j) / nv,
                                     double(j + 1) / nv);
                const CellErrorBound b = cellErrorBound(cell, ErrorMode::Guaranteed, target);
                worstBound = std::max(worstBound, b.untrimmed());
                worstSpread = std::max(worstSpread, b.spreadToEdges);
                worstTwist = std::max(worstTwist, b.twist);
                worstPlanar = std::max(worstPlanar, b.planarTwist);
                // the dense samples reach a little past the cell: the surface beside it counts
                std::vector<Point3> dense;
                const int d = 40;
                for (int a = 0; a <= d; ++a)
                    for (int c = 0; c <= d; ++c)
                        dense.push_back(cell.point(-0.2 + 1.4 * a / d, -0.2 + 1.4 * c / d));
                double bestEqual = 1e300, bestTrue = 1e300;
                for (int diagonal = 0; diagonal < 2; ++diagonal) {
                    const std::array<double, 2> t0[3] = {{0, 0}, {1, 0}, {1, 1}},
                                                t1[3] = {{0, 0}, {1, 1}, {0, 1}},
                                                t2[3] = {{0, 0}, {1, 0}, {0, 1}},
                                                t3[3] = {{1, 0}, {1, 1}, {0, 1}};
                    const auto& a = diagonal ? t2 : t0;
                    const auto& c = diagonal ? t3 : t1;
                    bestEqual = std::min(bestEqual,
                                         std::max(triangleDeviation(cell, a, dense, true),
                                                  triangleDeviation(cell, c, dense, true)));
                    bestTrue = std::min(bestTrue, std::max(triangleDeviation(cell, a, dense, false),
                                                           triangleDeviation(cell, c, dense, false)));
                }
                worstEqual = std::max(worstEqual, bestEqual);
                worstTrue = std::max(worstTrue, bestTrue);
            }
        if (!firstBound && worstBound <= target) firstBound = n;
        if (!firstEqual && worstEqual <= target) firstEqual = n;
        if (!firstTrue && worstTrue <= target) firstTrue = n;
        if (std::getenv("SCRATCH_VERBOSE")) std::printf("%dx%d bound %.3f (spread %.3f twist %.3f planar %.3f) equal-param %.3f distance %.3f (T)\n",
                    nu, nv, worstBound / T, worstSpread / T, worstTwist / T,
                    std::min(9.99, worstPlanar / T), worstEqual / T, worstTrue / T);
    }
    std::printf("face %d: square grid settles at n = %d by the bound, %d at equal parameters, %d by distance\n", f + 1, firstBound, firstEqual, firstTrue);
    }
}

}  // namespace
}  // namespace nurbslod
