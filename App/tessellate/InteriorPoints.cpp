#include "tessellate/InteriorPoints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace nurbslod {

namespace {

// The largest fan tried: a disk of more triangles is left as it is (the bounds of its
// triangulations grow as the cube of its size).
constexpr std::size_t kLargestFan = 8;

// The points around v in counter-clockwise order where its live triangles `fan` close around it
// (one disk); none where they do not (a boundary point, a pinch).
std::optional<std::vector<std::uint32_t>> closedRing(std::uint32_t v, const FaceMesh& mesh,
                                                     const std::vector<std::size_t>& fan) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;  // n_i -> n_i+1
    for (std::size_t t : fan) {
        const RingTriangle& triangle = mesh.triangles[t];
        int at = 0;
        while (triangle[at] != v) ++at;
        links.push_back({triangle[(at + 1) % 3], triangle[(at + 2) % 3]});
    }
    std::vector<std::uint32_t> ring{links.front().first};
    while (ring.size() <= links.size()) {
        const auto next = std::find_if(links.begin(), links.end(),
                                       [&](const auto& link) { return link.first == ring.back(); });
        if (next == links.end()) return std::nullopt;
        if (next->second == ring.front())
            return ring.size() == links.size() ? std::optional(ring) : std::nullopt;
        ring.push_back(next->second);
    }
    return std::nullopt;
}

// The least distance of v's point from the interpolation of the ring's points, over the
// triangles of those points that hold v in (u, v): every triangulation of the ring has one, so
// none of them is within less of the surface at v.
double leastDistanceAtPoint(std::uint32_t v, const std::vector<std::uint32_t>& ring,
                            const FaceMesh& mesh) {
    const Point2& q = mesh.vertices[v].uv;
    double least = std::numeric_limits<double>::infinity();
    const std::size_t size = ring.size();
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t k = i + 1; k < size; ++k)
            for (std::size_t j = k + 1; j < size; ++j) {
                const auto& a = mesh.vertices[ring[i]];
                const auto& b = mesh.vertices[ring[k]];
                const auto& c = mesh.vertices[ring[j]];
                const double area = ring::cross(a.uv, b.uv, c.uv);
                if (area == 0) continue;
                const double wa = ring::cross(q, b.uv, c.uv) / area;
                const double wb = ring::cross(a.uv, q, c.uv) / area;
                const double wc = ring::cross(a.uv, b.uv, q) / area;
                if (wa < 0 || wb < 0 || wc < 0) continue;
                const Point3 at = wa * a.position + wb * b.position + wc * c.position;
                least = std::min(least, (at - mesh.vertices[v].position).norm());
            }
    return least;
}

}  // namespace

std::size_t removeInteriorPoints(FaceMesh& mesh, const TriangleBound& lowerBound,
                                 const TriangleBound& bound, double limit) {
    if (!(limit > 0)) return 0;
    const std::size_t vertexCount = mesh.vertices.size();
    std::vector<std::vector<std::size_t>> trianglesOf(vertexCount);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t i : mesh.triangles[t]) trianglesOf[i].push_back(t);
    std::vector<char> removed(mesh.triangles.size(), 0);
    auto liveFan = [&](std::uint32_t v) -> const std::vector<std::size_t>& {
        std::vector<std::size_t>& fan = trianglesOf[v];
        fan.erase(std::remove_if(fan.begin(), fan.end(), [&](std::size_t t) { return removed[t]; }),
                  fan.end());
        return fan;
    };
    struct SeenTriangle {
        RingTriangle triangle;
        double lower, bound;
    };
    constexpr double kNotYet = std::numeric_limits<double>::quiet_NaN();
    std::vector<SeenTriangle> seen;
    std::size_t count = 0;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        const FaceMesh::Vertex& vertex = mesh.vertices[v];
        if (vertex.shared || !vertex.positionFromSurface) continue;
        const std::vector<std::size_t> fan = liveFan(v);
        if (fan.size() < 3 || fan.size() > kLargestFan) continue;
        const auto ring = closedRing(v, mesh, fan);
        if (!ring) continue;
        const std::size_t size = ring->size();
        auto inFan = [&](std::size_t t) {
            return std::find(fan.begin(), fan.end(), t) != fan.end();
        };
        // no side of the ring on the face's boundary (a triangle beyond each), and no new
        // diagonal that is already an edge outside the fan (it would be a non-manifold edge)
        std::vector<char> forbidden(size * size, 0);
        std::vector<char> sideInside(size, 0);
        for (std::size_t a = 0; a < size; ++a)
            for (std::size_t t : liveFan((*ring)[a])) {
                if (inFan(t)) continue;
                for (std::uint32_t b : mesh.triangles[t]) {
                    const auto at = std::find(ring->begin(), ring->end(), b);
                    if (at == ring->end()) continue;
                    const std::size_t j = static_cast<std::size_t>(at - ring->begin());
                    forbidden[a * size + j] = forbidden[j * size + a] = 1;
                    if (j == (a + 1) % size) sideInside[a] = 1;
                    if (a == (j + 1) % size) sideInside[j] = 1;
                }
            }
        if (std::find(sideInside.begin(), sideInside.end(), 0) != sideInside.end()) continue;
        if (!(leastDistanceAtPoint(v, *ring, mesh) <= limit)) continue;
        std::vector<RingTriangle> old;
        for (std::size_t t : fan) old.push_back(mesh.triangles[t]);
        const double side = ring::facingOf(mesh, old);
        // each triangle's bounds asked once: both searches and the check between them meet
        // the same triangles of the ring's points (always as ring[i], ring[k], ring[j], i < k < j)
        seen.clear();
        auto boundsOf = [&](const RingTriangle& t) -> SeenTriangle& {
            for (SeenTriangle& known : seen)
                if (known.triangle == t) return known;
            seen.push_back({t, lowerBound(t), kNotYet});
            return seen.back();
        };
        auto lowerOf = [&](const RingTriangle& t) { return boundsOf(t).lower; };
        auto boundOf = [&](const RingTriangle& t) {
            SeenTriangle& known = boundsOf(t);
            if (!(known.lower <= limit)) return known.lower;
            if (std::isnan(known.bound)) known.bound = bound(t);
            return known.bound;
        };
        const auto likely = leastBoundTriangulation(*ring, mesh, forbidden, side, lowerOf, limit);
        if (!likely) continue;  // no triangulation is within the limit at the points sampled
        std::optional<std::vector<RingTriangle>> chosen;
        if (std::all_of(likely->first.begin(), likely->first.end(),
                        [&](const RingTriangle& t) { return boundOf(t) <= limit; }))
            chosen = likely->first;
        else if (auto bounded =
                     leastBoundTriangulation(*ring, mesh, forbidden, side, boundOf, limit))
            chosen = std::move(bounded->first);
        if (!chosen) continue;
        for (std::size_t t : fan) removed[t] = 1;
        trianglesOf[v].clear();
        for (const RingTriangle& triangle : *chosen) {
            const std::size_t index = mesh.triangles.size();
            mesh.triangles.push_back(triangle);
            removed.push_back(0);
            for (std::uint32_t i : triangle) trianglesOf[i].push_back(index);
        }
        ++count;
    }
    ring::dropRemoved(mesh.triangles, removed);
    return count;
}

}  // namespace nurbslod
