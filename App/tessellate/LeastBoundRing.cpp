#include "tessellate/LeastBoundRing.hpp"

#include <algorithm>
#include <limits>

namespace nurbslod {

namespace ring {

double facingOf(const FaceMesh& mesh, const std::vector<RingTriangle>& triangles) {
    double facing = 0;
    for (const RingTriangle& t : triangles) {
        const auto& a = mesh.vertices[t[0]];
        const auto& b = mesh.vertices[t[1]];
        const auto& c = mesh.vertices[t[2]];
        facing += (b.position - a.position)
                      .cross(c.position - a.position)
                      .dot(a.normal + b.normal + c.normal);
    }
    return facing >= 0 ? 1.0 : -1.0;
}

void dropRemoved(std::vector<RingTriangle>& triangles, const std::vector<char>& removed) {
    std::size_t out = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (!removed[t]) triangles[out++] = triangles[t];
    triangles.resize(out);
}

double cross(const Point2& a, const Point2& b, const Point2& c) {
    const Point2 ab = b - a, ac = c - a;
    return ab.x() * ac.y() - ab.y() * ac.x();
}

bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
    const double c1 = cross(a, b, c), c2 = cross(a, b, d), c3 = cross(c, d, a), c4 = cross(c, d, b);
    return ((c1 > 0 && c2 < 0) || (c1 < 0 && c2 > 0)) && ((c3 > 0 && c4 < 0) || (c3 < 0 && c4 > 0));
}

std::vector<RingTriangle> trianglesOfSplits(const std::vector<std::uint32_t>& ring,
                                            const std::vector<std::size_t>& split) {
    const std::size_t size = ring.size();
    std::vector<RingTriangle> triangles;
    std::vector<std::pair<std::size_t, std::size_t>> pending{{0, size - 1}};
    while (!pending.empty()) {
        const auto [i, j] = pending.back();
        pending.pop_back();
        if (j < i + 2) continue;
        const std::size_t k = split[i * size + j];
        triangles.push_back({ring[i], ring[k], ring[j]});
        pending.push_back({i, k});
        pending.push_back({k, j});
    }
    return triangles;
}

}  // namespace ring

using ring::emptyRingTriangle;
using ring::segmentsCross;
using ring::trianglesOfSplits;

std::optional<std::pair<std::vector<RingTriangle>, double>> leastBoundTriangulation(
    const std::vector<std::uint32_t>& ring, const FaceMesh& mesh,
    const std::vector<char>& forbidden, double facing, const TriangleBound& bound, double limit) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    const std::size_t size = ring.size(), m = size - 1;
    auto uv = [&](std::size_t i) -> const Point2& { return mesh.vertices[ring[i]].uv; };
    double extent = 0;
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = 0; j < size; ++j)
            extent = std::max(extent, (uv(i) - uv(j)).squaredNorm());
    const double minimumArea = 1e-14 * extent;
    // sides are edges already; a diagonal must cross no side (the chord included)
    auto edgeUsable = [&](std::size_t i, std::size_t j) {
        if (j == i + 1 || (i == 0 && j == m)) return true;
        if (forbidden[i * size + j]) return false;
        for (std::size_t k = 0; k < size; ++k)
            if (segmentsCross(uv(i), uv(j), uv(k), uv((k + 1) % size))) return false;
        return true;
    };
    auto triangleCost = [&](std::size_t i, std::size_t k, std::size_t j) {
        if (!emptyRingTriangle(uv, size, i, k, j, minimumArea)) return kNever;
        const auto& a = mesh.vertices[ring[i]];
        const auto& b = mesh.vertices[ring[k]];
        const auto& c = mesh.vertices[ring[j]];
        const Vector3 n = (b.position - a.position).cross(c.position - a.position);
        if (!(facing * n.dot(a.normal + b.normal + c.normal) > 1e-6 * n.norm())) return kNever;
        const double value = bound({ring[i], ring[k], ring[j]});
        return value <= limit ? value : kNever;
    };
    std::vector<double> cost(size * size, 0.0);
    std::vector<std::size_t> split(size * size, 0);
    std::vector<char> usable(size * size, 0);
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i + 1; j < size; ++j) usable[i * size + j] = edgeUsable(i, j);
    for (std::size_t length = 2; length <= m; ++length)
        for (std::size_t i = 0; i + length <= m; ++i) {
            const std::size_t j = i + length;
            double best = kNever;
            if (usable[i * size + j])
                for (std::size_t k = i + 1; k < j; ++k) {
                    if (!usable[i * size + k] || !usable[k * size + j]) continue;
                    const double below = std::max(cost[i * size + k], cost[k * size + j]);
                    if (!(below < best)) continue;
                    const double c = std::max(below, triangleCost(i, k, j));
                    if (c < best) best = c, split[i * size + j] = k;
                }
            cost[i * size + j] = best;
        }
    if (cost[m] == kNever) return std::nullopt;
    return std::make_pair(trianglesOfSplits(ring, split), cost[m]);
}

}  // namespace nurbslod
