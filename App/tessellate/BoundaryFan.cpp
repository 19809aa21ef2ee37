#include "tessellate/BoundaryFan.hpp"

#include <unordered_map>

namespace nurbslod {

namespace {

FaceMesh fan(const TrimmedSurface& face, const std::vector<BoundaryLoop>& loops,
             const std::vector<Point3>& sharedPositions, bool withMidpoints) {
    FaceMesh mesh;
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
            const Vector3 normal = face.surface.normal(p.uv.x(), p.uv.y());
            v.normal = face.reversed ? Vector3(-normal) : normal;
            mesh.vertices.push_back(v);
        }
        return it->second;
    };
    // the middle of a segment, in (u, v) on the surface: the face's own vertex
    auto ownVertexAt = [&](const Point2& uv) {
        FaceMesh::Vertex v;
        v.position = face.surface.point(uv.x(), uv.y());
        v.uv = uv;
        const Vector3 normal = face.surface.normal(uv.x(), uv.y());
        v.normal = face.reversed ? Vector3(-normal) : normal;
        mesh.vertices.push_back(v);
        return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    };
    for (const BoundaryLoop& loop : loops) {
        std::vector<BoundaryPoint> points;
        std::vector<std::uint32_t> ids;
        for (size_t i = 0; i < loop.points.size(); ++i) {
            points.push_back(loop.points[i]);
            ids.push_back(vertexOf(loop.points[i]));
            if (!withMidpoints) continue;
            const Point2 middle =
                0.5 * (loop.points[i].uv + loop.points[(i + 1) % loop.points.size()].uv);
            points.push_back({middle, 0});
            ids.push_back(ownVertexAt(middle));
        }
        if (points.size() < 3) continue;
        // counter-clockwise in (u, v) like the kd-tree's triangles: the loop's signed area
        double area = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const Point2& a = points[i].uv;
            const Point2& b = points[(i + 1) % points.size()].uv;
            area += a.x() * b.y() - a.y() * b.x();
        }
        for (size_t i = 1; i + 1 < points.size(); ++i) {
            std::array<std::uint32_t, 3> t{ids[0], ids[i], ids[i + 1]};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            if (area < 0) std::swap(t[1], t[2]);
            if (face.reversed) std::swap(t[1], t[2]);
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
