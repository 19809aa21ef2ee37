#include "tessellate/CellTriangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nurbslod {

namespace {

// The badness of a triangle: the cosine of its largest angle, negated (-1/2 for an equilateral
// triangle, towards 1 for a cap); infinite for a triangle without area or wound clockwise.
double capBadness(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c,
                  double scaleX, double scaleY) {
    // exact orientation first: cell coordinates lie within 0..2^30, so the products fit in 64 bits
    const std::int64_t cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (cross <= 0) return std::numeric_limits<double>::infinity();
    const double p[3][2] = {{double(a.x) * scaleX, double(a.y) * scaleY},
                            {double(b.x) * scaleX, double(b.y) * scaleY},
                            {double(c.x) * scaleX, double(c.y) * scaleY}};
    double worst = -1;
    for (int k = 0; k < 3; ++k) {
        const double* o = p[k];
        const double* q = p[(k + 1) % 3];
        const double* r = p[(k + 2) % 3];
        const double ux = q[0] - o[0], uy = q[1] - o[1], vx = r[0] - o[0], vy = r[1] - o[1];
        const double lengths = std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
        if (!(lengths > 0)) return std::numeric_limits<double>::infinity();
        worst = std::max(worst, -(ux * vx + uy * vy) / lengths);
    }
    return worst;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulateCellWithoutCaps(
    const std::vector<IntegerPoint2>& ring) {
    const std::size_t n = ring.size();
    std::vector<std::array<std::uint32_t, 3>> triangles;
    if (n < 3) return triangles;
    if (n > kMostCapFreePoints) return triangulatePolygon({ring}).triangles;
    std::int64_t x0 = ring[0].x, x1 = x0, y0 = ring[0].y, y1 = y0;
    for (const auto& p : ring) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    if (x1 == x0 || y1 == y0) return triangles;
    const double scaleX = 1.0 / double(x1 - x0), scaleY = 1.0 / double(y1 - y0);

    // worst[i][j]: the smallest largest-badness of a triangulation of the sub-polygon i..j;
    // total[i][j] the sum of its badnesses, which breaks ties towards better triangles overall
    const double infinity = std::numeric_limits<double>::infinity();
    std::vector<double> worst(n * n, infinity), total(n * n, infinity);
    std::vector<std::uint32_t> apex(n * n, 0);
    for (std::size_t i = 0; i + 1 < n; ++i) worst[i * n + i + 1] = total[i * n + i + 1] = 0;
    for (std::size_t length = 2; length < n; ++length)
        for (std::size_t i = 0; i + length < n; ++i) {
            const std::size_t j = i + length;
            double bestWorst = infinity, bestTotal = infinity;
            for (std::size_t k = i + 1; k < j; ++k) {
                const double left = worst[i * n + k], right = worst[k * n + j];
                if (left == infinity || right == infinity) continue;
                const double badness = capBadness(ring[i], ring[k], ring[j], scaleX, scaleY);
                const double w = std::max({left, right, badness});
                const double t = total[i * n + k] + total[k * n + j] + badness;
                if (w < bestWorst || (w == bestWorst && t < bestTotal)) {
                    bestWorst = w, bestTotal = t;
                    apex[i * n + j] = static_cast<std::uint32_t>(k);
                }
            }
            worst[i * n + j] = bestWorst;
            total[i * n + j] = bestTotal;
        }
    if (worst[n - 1] == infinity) return triangulatePolygon({ring}).triangles;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, n - 1}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2) continue;
        const std::size_t k = apex[i * n + j];
        triangles.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k),
                             static_cast<std::uint32_t>(j)});
        stack.push_back({i, k});
        stack.push_back({k, j});
    }
    return triangles;
}

}  // namespace nurbslod
