#include "tessellate/OpenBoundaryPoints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace nurbslod {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

double cross(const Point2& a, const Point2& b, const Point2& c) {
    const Point2 ab = b - a, ac = c - a;
    return ab.x() * ac.y() - ab.y() * ac.x();
}

// The vertices around v in counter-clockwise order n0 .. nm when v lies on the mesh's boundary
// and its triangles (v, n_i, n_i+1) form one fan; none otherwise (an inner vertex, a pinch).
std::optional<std::vector<std::uint32_t>> ringAround(std::uint32_t v,
                                                     const std::vector<Triangle>& triangles,
                                                     const std::vector<std::size_t>& fan) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;  // n_i -> n_i+1
    for (std::size_t t : fan) {
        const Triangle& tri = triangles[t];
        int at = 0;
        while (tri[at] != v) ++at;
        links.push_back({tri[(at + 1) % 3], tri[(at + 2) % 3]});
    }
    std::optional<std::uint32_t> start;
    for (const auto& [from, to] : links) {
        const bool isTarget = std::any_of(links.begin(), links.end(),
                                          [&](const auto& link) { return link.second == from; });
        if (isTarget) continue;
        if (start) return std::nullopt;  // two open ends: not one fan
        start = from;
    }
    if (!start) return std::nullopt;  // a closed ring: an inner vertex
    std::vector<std::uint32_t> ring{*start};
    while (ring.size() <= links.size()) {
        auto next = std::find_if(links.begin(), links.end(),
                                 [&](const auto& link) { return link.first == ring.back(); });
        if (next == links.end()) return std::nullopt;
        ring.push_back(next->second);
    }
    std::vector<std::uint32_t> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
    return ring;
}

// Proper crossing of segments ab and cd in the plane (touching at an end does not count).
bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
    const double c1 = cross(a, b, c), c2 = cross(a, b, d), c3 = cross(c, d, a), c4 = cross(c, d, b);
    return ((c1 > 0 && c2 < 0) || (c1 < 0 && c2 > 0)) && ((c3 > 0 && c4 < 0) || (c3 < 0 && c4 > 0));
}

// The triangulation of the ring n0 .. nm (closed by the chord nm -> n0 that v lies on) that
// least changes the surface, and that change. Both the old fan and the new triangles are graphs
// of heights along the fan's mean normal over one region of the plane normal to it, where every
// triangle faces that normal: a point of the new triangles is then within their height
// difference of the old fan. The difference is linear on the overlay of the two triangulations,
// so it is largest at the overlay's vertices: the ring's points (no difference), v (on the new
// chord) and where an old edge (v, n_i) crosses a new diagonal. Each diagonal's largest
// difference is its own, so the best triangulation is found by the polygon triangulation
// recurrence over the ring, minimising the largest difference. None where no triangulation is
// valid in (u, v) and in space. `allowed` tells whether a diagonal may be made (it must not
// already be an edge outside the fan).
constexpr std::size_t kLargestRing = 64;

template <class Allowed>
std::optional<std::pair<std::vector<Triangle>, double>> leastChangingTriangulation(
    std::uint32_t v, const std::vector<std::uint32_t>& ring, const FaceMesh& mesh,
    const Allowed& allowed) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    auto position = [&](std::uint32_t i) -> const Point3& { return mesh.vertices[i].position; };
    auto uv = [&](std::size_t i) -> const Point2& { return mesh.vertices[ring[i]].uv; };
    auto areaNormal = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) -> Vector3 {
        return (position(b) - position(a)).cross(position(c) - position(a));
    };
    const std::size_t size = ring.size(), m = size - 1;
    // The search is cubic in the ring: the fans of wing.brep's free edges at relative 1e-4 (up
    // to hundreds of triangles about one point) took 88% of its tessellation time (1.38 s).
    // Larger fans keep their point: 64 gives 0.60 s and 145 open edges there (139 unbounded;
    // 32: 0.22 s, 179), and still 50 at relative 1e-3.
    // The large fans are made by the removals themselves: each one's new triangles join the fan
    // of the next point along the same chord. Of the 18 points wing keeps beyond its 127 free
    // chords at relative 1e-4, 13 have rings of 65 or 66 (5 are over the allowance); unbounded
    // gives 132 (3.5 s against 1.6 s with 64, measured back to back).
    if (size > kLargestRing) return std::nullopt;
    Vector3 normal = Vector3::Zero();
    for (std::size_t i = 0; i < m; ++i) normal += areaNormal(v, ring[i], ring[i + 1]);
    if (!(normal.norm() > 0)) return std::nullopt;
    normal.normalize();
    auto facesNormal = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const Vector3 n = areaNormal(a, b, c);
        return n.dot(normal) > 1e-6 * n.norm();
    };
    for (std::size_t i = 0; i < m; ++i)
        if (!facesNormal(v, ring[i], ring[i + 1])) return std::nullopt;
    const Vector3 across = normal.unitOrthogonal(), along = normal.cross(across);
    auto planar = [&](std::uint32_t i) {
        return Point2(across.dot(position(i)), along.dot(position(i)));
    };
    // the ring and v in that plane, once: the search below reads them O(size^3) times
    std::vector<Point2> plane(size);
    for (std::size_t i = 0; i < size; ++i) plane[i] = planar(ring[i]);
    const Point2 planeV = planar(v);
    std::vector<Point2> fromV(size);  // n_l - v in the plane
    for (std::size_t i = 0; i < size; ++i) fromV[i] = plane[i] - planeV;
    // the old fan turns once about v (half a turn, v being on the chord), not round it again
    double turn = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const Point2 a = fromV[i], b = fromV[i + 1];
        turn += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    if (!(turn < 1.5 * std::numbers::pi)) return std::nullopt;
    double extent = 0;
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = 0; j < size; ++j)
            extent = std::max(extent, (uv(i) - uv(j)).squaredNorm());
    const double minimumArea = 1e-14 * extent;

    // the largest height difference along the diagonal (i, j), infinite where it may not be made
    std::vector<std::vector<double>> diagonal(size, std::vector<double>(size, kNever));
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i + 2; j < size; ++j) {
            if (i == 0 && j == m) continue;  // the chord: the polygon's own side
            bool crosses = false;
            for (std::size_t k = 0; k < m && !crosses; ++k)
                crosses = segmentsCross(uv(i), uv(j), uv(k), uv(k + 1));
            if (crosses || !allowed(ring[i], ring[j])) continue;
            double largest = 0;
            const Point2 d2 = plane[j] - plane[i];
            const Point2& w = fromV[i];
            for (std::size_t l = 1; l < m; ++l) {
                if (l == i || l == j) continue;
                // v + s (n_l - v) = n_i + r (n_j - n_i) in the plane
                const Point2& d1 = fromV[l];
                const double determinant = d1.x() * d2.y() - d1.y() * d2.x();
                if (determinant == 0) continue;
                const double s = (w.x() * d2.y() - w.y() * d2.x()) / determinant;
                const double r = (w.x() * d1.y() - w.y() * d1.x()) / determinant;
                if (s < 0 || s > 1 || r < 0 || r > 1) continue;
                const double old = normal.dot(position(v) + s * (position(ring[l]) - position(v)));
                const double now =
                    normal.dot(position(ring[i]) + r * (position(ring[j]) - position(ring[i])));
                largest = std::max(largest, std::abs(old - now));
            }
            diagonal[i][j] = largest;
        }
    auto sideCost = [&](std::size_t i, std::size_t j) {
        return (j == i + 1 || (i == 0 && j == m)) ? 0.0 : diagonal[i][j];
    };
    auto triangleValid = [&](std::size_t i, std::size_t k, std::size_t j) {
        if (!(cross(uv(i), uv(k), uv(j)) > minimumArea)) return false;
        for (std::size_t w = 0; w < size; ++w) {
            if (w == i || w == k || w == j) continue;
            if (cross(uv(i), uv(k), uv(w)) >= -minimumArea &&
                cross(uv(k), uv(j), uv(w)) >= -minimumArea &&
                cross(uv(j), uv(i), uv(w)) >= -minimumArea)
                return false;
        }
        return facesNormal(ring[i], ring[k], ring[j]);
    };
    // cost[i][j]: the least largest difference over triangulations of the sub-polygon i .. j
    std::vector<std::vector<double>> cost(size, std::vector<double>(size, 0.0));
    std::vector<std::vector<std::size_t>> split(size, std::vector<std::size_t>(size, 0));
    for (std::size_t length = 2; length <= m; ++length)
        for (std::size_t i = 0; i + length <= m; ++i) {
            const std::size_t j = i + length;
            cost[i][j] = kNever;
            if (sideCost(i, j) == kNever) continue;
            for (std::size_t k = i + 1; k < j; ++k) {
                const double c = std::max(
                    {cost[i][k], cost[k][j], sideCost(i, k), sideCost(k, j), sideCost(i, j)});
                if (c < cost[i][j] && triangleValid(i, k, j)) cost[i][j] = c, split[i][j] = k;
            }
        }
    if (cost[0][m] == kNever) return std::nullopt;
    std::vector<Triangle> triangles;
    std::vector<std::pair<std::size_t, std::size_t>> pending{{0, m}};
    while (!pending.empty()) {
        const auto [i, j] = pending.back();
        pending.pop_back();
        if (j < i + 2) continue;
        const std::size_t k = split[i][j];
        triangles.push_back({ring[i], ring[k], ring[j]});
        pending.push_back({i, k});
        pending.push_back({k, j});
    }
    const Point3& first = position(ring.front());
    const Point3& last = position(ring.back());
    const Vector3 chord = first - last;
    const double t = std::clamp((position(v) - last).dot(chord) / chord.squaredNorm(), 0.0, 1.0);
    return std::make_pair(std::move(triangles),
                          std::max(cost[0][m], (last + t * chord - position(v)).norm()));
}

}  // namespace

std::size_t removeOpenBoundaryPoints(FaceMesh& mesh, const std::vector<double>& sharedOffsets,
                                     double allowance) {
    const std::size_t vertexCount = mesh.vertices.size();
    std::vector<std::vector<std::size_t>> trianglesOf(vertexCount);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t i : mesh.triangles[t]) trianglesOf[i].push_back(t);
    std::vector<char> removed(mesh.triangles.size(), 0);
    std::size_t count = 0;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        if (mesh.vertices[v].shared) continue;  // another face has it: it must stay
        std::vector<std::size_t>& fan = trianglesOf[v];
        fan.erase(std::remove_if(fan.begin(), fan.end(), [&](std::size_t t) { return removed[t]; }),
                  fan.end());
        if (fan.size() < 2) continue;
        const auto ring = ringAround(v, mesh.triangles, fan);
        if (!ring) continue;
        // v must lie on the chord between its two boundary neighbours, in space
        const Point3& first = mesh.vertices[ring->front()].position;
        const Point3& last = mesh.vertices[ring->back()].position;
        const Vector3 chord = first - last;
        const double length2 = chord.squaredNorm();
        if (!(length2 > 0)) continue;
        const Vector3 fromLast = mesh.vertices[v].position - last;
        const double t = fromLast.dot(chord) / length2;
        if (!(t > 0 && t < 1) || (fromLast - t * chord).squaredNorm() > 1e-18 * length2) continue;
        // a new diagonal that is already an edge outside the fan would make a non-manifold edge
        auto allowed = [&](std::uint32_t a, std::uint32_t b) {
            for (std::size_t t2 : trianglesOf[a]) {
                if (removed[t2] || std::find(fan.begin(), fan.end(), t2) != fan.end()) continue;
                const Triangle& other = mesh.triangles[t2];
                if (std::find(other.begin(), other.end(), b) != other.end()) return false;
            }
            return true;
        };
        const auto best = leastChangingTriangulation(v, *ring, mesh, allowed);
        if (!best) continue;
        double ringOffset = 0;
        for (std::uint32_t i : *ring)
            if (mesh.vertices[i].shared)
                ringOffset = std::max(ringOffset, sharedOffsets[mesh.vertices[i].sharedId]);
        if (best->second + ringOffset > allowance) continue;
        const std::vector<Triangle>& replacement = best->first;
        for (std::size_t t : fan) removed[t] = 1;
        fan.clear();
        for (const Triangle& triangle : replacement) {
            const std::size_t index = mesh.triangles.size();
            mesh.triangles.push_back(triangle);
            removed.push_back(0);
            for (std::uint32_t i : triangle) trianglesOf[i].push_back(index);
        }
        ++count;
    }
    std::size_t out = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (!removed[t]) mesh.triangles[out++] = mesh.triangles[t];
    mesh.triangles.resize(out);
    return count;
}

}  // namespace nurbslod
