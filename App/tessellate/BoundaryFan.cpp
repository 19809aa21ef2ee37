#include "tessellate/BoundaryFan.hpp"

#include <limits>
#include <unordered_map>

namespace nurbslod {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// One corner of a loop to triangulate: its mesh vertex, (u, v) and position.
struct Corner {
    std::uint32_t id;
    Point2 uv;
    Point3 position;
};

double cross(const Point2& a, const Point2& b, const Point2& c) {
    const Point2 ab = b - a, ac = c - a;
    return ab.x() * ac.y() - ab.y() * ac.x();
}

// Ear clipping that always cuts the ear with the shortest diagonal in space. A thin face's loop
// runs out along one side and back along the other, so its shortest diagonals cross the face:
// the triangles zip the two sides together, each within a few chords of its corners. A fan from
// one corner instead spans the whole face: over a curved sliver its triangles cut across the
// bend, as far from the face as the bend's sagitta.
// Where the loop has area in (u, v) (`orientation`: the sign of its area) an ear must also be
// convex there and hold no other corner, so that the triangles stay inside the face; a loop
// without area (both sides on one curve in (u, v)) takes any ear. Where no ear is valid the
// shortest one is cut anyway: a thin face must never be missing.
std::vector<Triangle> shortestEarTriangulation(const std::vector<Corner>& corners,
                                               double orientation) {
    const std::size_t n = corners.size();
    std::vector<std::size_t> previous(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        previous[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    std::vector<char> gone(n, 0);
    auto diagonal = [&](std::size_t i) {
        return (corners[previous[i]].position - corners[next[i]].position).squaredNorm();
    };
    auto valid = [&](std::size_t i) {
        if (orientation == 0) return true;
        const Point2 &a = corners[previous[i]].uv, &b = corners[i].uv, &c = corners[next[i]].uv;
        if (!(orientation * cross(a, b, c) > 0)) return false;
        for (std::size_t k = next[next[i]]; k != previous[i]; k = next[k]) {
            const Point2& p = corners[k].uv;
            if (orientation * cross(a, b, p) >= 0 && orientation * cross(b, c, p) >= 0 &&
                orientation * cross(c, a, p) >= 0)
                return false;
        }
        return true;
    };
    std::vector<double> length(n);
    std::vector<char> isEar(n);
    for (std::size_t i = 0; i < n; ++i) {
        length[i] = diagonal(i);
        isEar[i] = valid(i);
    }
    std::vector<Triangle> triangles;
    for (std::size_t left = n; left >= 3; --left) {
        std::size_t best = n;
        for (int pass = 0; pass < 2 && best == n; ++pass)
            for (std::size_t i = 0; i < n; ++i)
                if (!gone[i] && (pass == 1 || isEar[i]) && (best == n || length[i] < length[best]))
                    best = i;
        triangles.push_back({corners[previous[best]].id, corners[best].id, corners[next[best]].id});
        gone[best] = 1;
        next[previous[best]] = next[best];
        previous[next[best]] = previous[best];
        for (const std::size_t i : {previous[best], next[best]}) {
            length[i] = diagonal(i);
            isEar[i] = valid(i);
        }
    }
    return triangles;
}

FaceMesh fan(const TrimmedSurface& face, const std::vector<BoundaryLoop>& loops,
             const std::vector<Point3>& sharedPositions, bool withMidpoints) {
    FaceMesh mesh;
    auto normalAt = [&](const Point2& uv) -> Vector3 {
        const Vector3 normal = face.surface.normal(uv.x(), uv.y());
        return face.reversed ? Vector3(-normal) : normal;
    };
    std::unordered_map<std::uint32_t, std::uint32_t> faceVertexOf;
    auto vertexOf = [&](const BoundaryPoint& p) {
        auto [it, inserted] =
            faceVertexOf.emplace(p.vertex, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (inserted) {
            FaceMesh::Vertex v;
            v.shared = true;
            v.sharedId = p.vertex;
            v.position = sharedPositions[p.vertex];
            v.uv = p.uv;
            v.normal = normalAt(p.uv);
            mesh.vertices.push_back(v);
        }
        return it->second;
    };
    // the middle of a segment, in (u, v) on the surface: the face's own vertex
    auto ownVertexAt = [&](const Point2& uv) {
        FaceMesh::Vertex v;
        v.position = face.surface.point(uv.x(), uv.y());
        v.uv = uv;
        v.normal = normalAt(uv);
        mesh.vertices.push_back(v);
        return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    };
    for (const BoundaryLoop& loop : loops) {
        std::vector<Corner> corners;
        for (size_t i = 0; i < loop.points.size(); ++i) {
            const std::uint32_t id = vertexOf(loop.points[i]);
            if (corners.empty() || corners.back().id != id)
                corners.push_back({id, loop.points[i].uv, mesh.vertices[id].position});
            if (!withMidpoints) continue;
            const Point2 middle =
                0.5 * (loop.points[i].uv + loop.points[(i + 1) % loop.points.size()].uv);
            const std::uint32_t own = ownVertexAt(middle);
            corners.push_back({own, middle, mesh.vertices[own].position});
        }
        while (corners.size() > 1 && corners.back().id == corners.front().id) corners.pop_back();
        if (corners.size() < 3) continue;
        double area = 0;
        for (size_t i = 0; i < corners.size(); ++i)
            area += cross(Point2::Zero(), corners[i].uv, corners[(i + 1) % corners.size()].uv);
        const double orientation = area > 0 ? 1.0 : area < 0 ? -1.0 : 0.0;
        for (Triangle t : shortestEarTriangulation(corners, orientation)) {
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            // facing the face's normal (counter-clockwise in (u, v) where the loop has area;
            // a loop without area has no such side, and its normal tells)
            const Point3 &a = mesh.vertices[t[0]].position, &b = mesh.vertices[t[1]].position,
                         &c = mesh.vertices[t[2]].position;
            const Point2 centre =
                (mesh.vertices[t[0]].uv + mesh.vertices[t[1]].uv + mesh.vertices[t[2]].uv) / 3;
            if ((b - a).cross(c - a).dot(normalAt(centre)) < 0) std::swap(t[1], t[2]);
            mesh.triangles.push_back(t);
        }
    }
    return mesh;
}

}  // namespace

FaceMesh fanOverBoundary(const TrimmedSurface& face, const std::vector<BoundaryLoop>& loops,
                         const std::vector<Point3>& sharedPositions) {
    FaceMesh mesh = fan(face, loops, sharedPositions, false);
    // A loop of two points (two curves between the same two vertices, straight within the
    // tolerance) has no triangle of its own: the middles of its segments make one.
    if (mesh.triangles.empty()) mesh = fan(face, loops, sharedPositions, true);
    return mesh;
}

}  // namespace nurbslod
