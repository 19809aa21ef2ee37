#include "tessellate/CellTriangulation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace nurbslod {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The cosine of the largest angle of the triangle p[0] p[1] p[2], negated (-1/2 for an
// equilateral triangle, towards 1 for a cap); infinite for a side of no length.
double largestAngleBadness(const double (&p)[3][2]) {
    double worst = -1;
    for (int k = 0; k < 3; ++k) {
        const double* o = p[k];
        const double* q = p[(k + 1) % 3];
        const double* r = p[(k + 2) % 3];
        const double ux = q[0] - o[0], uy = q[1] - o[1], vx = r[0] - o[0], vy = r[1] - o[1];
        const double lengths = std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
        if (!(lengths > 0)) return kInfinity;
        worst = std::max(worst, -(ux * vx + uy * vy) / lengths);
    }
    return worst;
}

// Twice the signed area of a b c, exact: cell coordinates lie within 0..2^30, so the products
// fit in 64 bits.
std::int64_t twiceArea(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The badness of a triangle: its largestAngleBadness in the cell scaled to the unit square;
// infinite for a triangle without area or wound clockwise.
double capBadness(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c,
                  double scaleX, double scaleY) {
    if (twiceArea(a, b, c) <= 0) return kInfinity;
    const double p[3][2] = {{double(a.x) * scaleX, double(a.y) * scaleY},
                            {double(b.x) * scaleX, double(b.y) * scaleY},
                            {double(c.x) * scaleX, double(c.y) * scaleY}};
    return largestAngleBadness(p);
}

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// The triangulation of the convex polygon 0..n-1 whose largest badness is the smallest
// (dynamic programming, O(n^3)); ties go to the smaller sum of badnesses, i.e. to better
// triangles overall. Empty where every triangulation has a triangle of infinite badness.
Triangles leastBadTriangulation(
    std::size_t n, const std::function<double(std::size_t, std::size_t, std::size_t)>& badness) {
    // worst[i][j]: the smallest largest-badness of a triangulation of the sub-polygon i..j;
    // total[i][j] the sum of its badnesses
    std::vector<double> worst(n * n, kInfinity), total(n * n, kInfinity);
    std::vector<std::uint32_t> apex(n * n, 0);
    for (std::size_t i = 0; i + 1 < n; ++i) worst[i * n + i + 1] = total[i * n + i + 1] = 0;
    for (std::size_t length = 2; length < n; ++length)
        for (std::size_t i = 0; i + length < n; ++i) {
            const std::size_t j = i + length;
            double bestWorst = kInfinity, bestTotal = kInfinity;
            for (std::size_t k = i + 1; k < j; ++k) {
                const double left = worst[i * n + k], right = worst[k * n + j];
                if (left == kInfinity || right == kInfinity) continue;
                const double b = badness(i, k, j);
                const double w = std::max({left, right, b});
                const double t = total[i * n + k] + total[k * n + j] + b;
                if (w < bestWorst || (w == bestWorst && t < bestTotal)) {
                    bestWorst = w, bestTotal = t;
                    apex[i * n + j] = static_cast<std::uint32_t>(k);
                }
            }
            worst[i * n + j] = bestWorst;
            total[i * n + j] = bestTotal;
        }
    Triangles triangles;
    if (worst[n - 1] == kInfinity) return triangles;
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

struct Box {
    std::int64_t x0, y0, x1, y1;
};

Box boxOf(const std::vector<IntegerPoint2>& ring) {
    Box b{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
    for (const auto& p : ring) {
        b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

}  // namespace

Triangles triangulateCellWithoutCaps(const std::vector<IntegerPoint2>& ring) {
    const std::size_t n = ring.size();
    if (n < 3) return {};
    if (n > kMostCapFreePoints) return triangulatePolygon({ring}).triangles;
    const Box box = boxOf(ring);
    if (box.x1 == box.x0 || box.y1 == box.y0) return {};
    const double scaleX = 1.0 / double(box.x1 - box.x0), scaleY = 1.0 / double(box.y1 - box.y0);
    Triangles triangles =
        leastBadTriangulation(n, [&](std::size_t i, std::size_t k, std::size_t j) {
            return capBadness(ring[i], ring[k], ring[j], scaleX, scaleY);
        });
    if (triangles.empty()) return triangulatePolygon({ring}).triangles;
    return triangles;
}

Triangles triangulateCellAtPole(const std::vector<IntegerPoint2>& ring,
                                const std::vector<char>& atPole) {
    const std::size_t n = ring.size();
    if (n < 3 || n > kMostCapFreePoints || atPole.size() != n) return {};
    const Box box = boxOf(ring);
    if (box.x1 == box.x0 || box.y1 == box.y0) return {};
    // every point on the cell's sides: the ring is convex, as the dynamic programming needs
    for (const auto& p : ring)
        if (p.x != box.x0 && p.x != box.x1 && p.y != box.y0 && p.y != box.y1) return {};
    // the pole: one whole side, both its corners included
    int poleSide = -1;  // 0: x = x0, 1: x = x1, 2: y = y0, 3: y = y1
    auto onSide = [&](const IntegerPoint2& p, int side) {
        return side == 0   ? p.x == box.x0
               : side == 1 ? p.x == box.x1
               : side == 2 ? p.y == box.y0
                           : p.y == box.y1;
    };
    for (int side = 0; side < 4; ++side) {
        bool all = true;
        std::int64_t low = std::numeric_limits<std::int64_t>::max(), high = -low;
        for (std::size_t i = 0; i < n; ++i)
            if (atPole[i]) {
                all &= onSide(ring[i], side);
                const std::int64_t along = side < 2 ? ring[i].y : ring[i].x;
                low = std::min(low, along), high = std::max(high, along);
            }
        const bool whole =
            side < 2 ? low == box.y0 && high == box.y1 : low == box.x0 && high == box.x1;
        if (all && whole) poleSide = side;
    }
    if (poleSide < 0) return {};
    // The cell in the frame of a wedge: the pole side shrinks to the apex, the side opposite
    // keeps its unit length, and the two sides through the pole become the wedge's two
    // meridians, as the surface is near its pole (geodesic polar coordinates). Three points of
    // one meridian (the pole and two points of a side) are then collinear, as they are in
    // space: such a triangle lies in the meridian's plane, flat against the surface.
    const bool poleAlongX = poleSide >= 2;  // the pole side runs along x
    std::vector<std::array<double, 2>> wedge(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = double(ring[i].x - box.x0) / double(box.x1 - box.x0);
        const double y = double(ring[i].y - box.y0) / double(box.y1 - box.y0);
        const double along = poleAlongX ? x : y, across = poleAlongX ? y : x;
        const double fromPole = (poleSide == 0 || poleSide == 2) ? across : 1 - across;
        // mirrored where the map would turn the ring clockwise (pole at x0 or at y1)
        const double mirror = (poleSide == 0 || poleSide == 3) ? -1 : 1;
        wedge[i] = {mirror * (along - 0.5) * fromPole, fromPole};
    }
    Triangles triangles =
        leastBadTriangulation(n, [&](std::size_t i, std::size_t k, std::size_t j) {
            if (twiceArea(ring[i], ring[k], ring[j]) <= 0) return kInfinity;
            // two corners at the pole: the triangle vanishes in space (its corners weld)
            if (int(atPole[i]) + int(atPole[k]) + int(atPole[j]) >= 2) return -1.0;
            const double p[3][2] = {
                {wedge[i][0], wedge[i][1]}, {wedge[k][0], wedge[k][1]}, {wedge[j][0], wedge[j][1]}};
            // the wedge frame is a continuous map of the cell's sides that keeps their order, so
            // the ring stays convex there; a triangle of three points of one wedge side is flat
            const double ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1];
            const double vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1];
            const double cross = ux * vy - uy * vx;
            if (!(cross > 1e-9 * std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy))))
                return kInfinity;
            return largestAngleBadness(p);
        });
    return triangles;
}

}  // namespace nurbslod
