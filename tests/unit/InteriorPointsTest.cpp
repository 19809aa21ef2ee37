#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/InteriorPoints.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// z = curvature (u^2 + v^2): the paraboloid's distance from a triangle's plane through its
// corners, largest inside the triangle.
constexpr double kCurvature = 0.05;
Point3 onParaboloid(const Point2& q) {
    return Point3(q.x(), q.y(), kCurvature * q.squaredNorm());
}

// A square of n x n cells, each cut into two triangles, on the paraboloid: its (n - 1)^2 inner
// points are the face's own, the border's points its boundary.
FaceMesh paraboloidGrid(int n) {
    FaceMesh mesh;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            FaceMesh::Vertex vertex;
            vertex.uv = Point2(i, j);
            vertex.position = onParaboloid(vertex.uv);
            vertex.normal = Vector3(-2 * kCurvature * i, -2 * kCurvature * j, 1).normalized();
            vertex.positionFromSurface = true;
            mesh.vertices.push_back(vertex);
        }
    auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

// The paraboloid's largest distance from the triangle at equal (u, v), at 231 points of it:
// close to the true one, which is what the tests compare against.
double sampledDeviation(const FaceMesh& mesh, const RingTriangle& t) {
    double largest = 0;
    constexpr int kSteps = 20;
    for (int a = 0; a <= kSteps; ++a)
        for (int b = 0; a + b <= kSteps; ++b) {
            const double wa = double(a) / kSteps, wb = double(b) / kSteps, wc = 1 - wa - wb;
            const Point2 q = wa * mesh.vertices[t[0]].uv + wb * mesh.vertices[t[1]].uv +
                             wc * mesh.vertices[t[2]].uv;
            const Point3 flat = wa * mesh.vertices[t[0]].position +
                                wb * mesh.vertices[t[1]].position +
                                wc * mesh.vertices[t[2]].position;
            largest = std::max(largest, (onParaboloid(q) - flat).norm());
        }
    return largest;
}

double uvArea(const FaceMesh& mesh) {
    double area = 0;
    for (const auto& t : mesh.triangles) {
        const Point2 a = mesh.vertices[t[0]].uv, b = mesh.vertices[t[1]].uv,
                     c = mesh.vertices[t[2]].uv;
        const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        EXPECT_GT(twice, 0) << "a triangle turned clockwise or lost its area";
        area += 0.5 * twice;
    }
    return area;
}

// The directed edges used once (the region's boundary) and whether any edge is used twice the
// same way (a fold, or a non-manifold edge).
std::pair<std::set<std::pair<std::uint32_t, std::uint32_t>>, bool> boundaryOf(
    const FaceMesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++uses[{t[k], t[(k + 1) % 3]}];
    std::set<std::pair<std::uint32_t, std::uint32_t>> boundary;
    bool twice = false;
    for (const auto& [edge, count] : uses) {
        twice = twice || count > 1;
        if (!uses.count({edge.second, edge.first})) boundary.insert(edge);
    }
    return {boundary, twice};
}

// Within a limit twice the grid's own deviation, points go; the square stays the same region
// in (u, v) with the same boundary, every triangle within the limit.
TEST(InteriorPoints, PointsGoWhereTheNewTrianglesAreWithinTheLimit) {
    FaceMesh mesh = paraboloidGrid(8);
    const std::size_t before = mesh.triangles.size();
    const double gridDeviation = sampledDeviation(mesh, mesh.triangles.front());
    const auto [boundaryBefore, foldedBefore] = boundaryOf(mesh);
    ASSERT_FALSE(foldedBefore);
    auto deviation = [&](const RingTriangle& t) { return sampledDeviation(mesh, t); };
    const double limit = 2.5 * gridDeviation;
    const std::size_t removed = removeInteriorPoints(mesh, deviation, deviation, limit);
    EXPECT_GT(removed, 0u);
    EXPECT_EQ(mesh.triangles.size(), before - 2 * removed);
    EXPECT_NEAR(uvArea(mesh), 64.0, 1e-9);
    const auto [boundaryAfter, foldedAfter] = boundaryOf(mesh);
    EXPECT_FALSE(foldedAfter);
    EXPECT_EQ(boundaryAfter, boundaryBefore);
    for (const auto& t : mesh.triangles) EXPECT_LE(sampledDeviation(mesh, t), limit);
}

// Below what any triangle over two cells would deviate, nothing goes, and the bound is never
// asked about a point whose own distance already rules it out; a point an edge shares stays.
TEST(InteriorPoints, NothingGoesBelowTheLimitNorAPointAnEdgeShares) {
    FaceMesh mesh = paraboloidGrid(6);
    const auto triangles = mesh.triangles;
    const double gridDeviation = sampledDeviation(mesh, mesh.triangles.front());
    std::size_t asked = 0;
    auto deviation = [&](const RingTriangle& t) {
        ++asked;
        return sampledDeviation(mesh, t);
    };
    EXPECT_EQ(removeInteriorPoints(mesh, deviation, deviation, 1.01 * gridDeviation), 0u);
    EXPECT_EQ(mesh.triangles, triangles);
    EXPECT_EQ(asked, 0u);
    for (auto& vertex : mesh.vertices) vertex.shared = true;
    EXPECT_EQ(removeInteriorPoints(mesh, deviation, deviation, 100.0), 0u);
    EXPECT_EQ(removeInteriorPoints(mesh, deviation, deviation, -1.0), 0u);
}

// Where the lower bound lets a triangulation through that the bound does not, the bound
// decides: a lower bound of zero with a bound over the limit removes nothing.
TEST(InteriorPoints, TheBoundDecidesNotTheLowerBound) {
    FaceMesh mesh = paraboloidGrid(6);
    const auto triangles = mesh.triangles;
    auto none = [](const RingTriangle&) { return 0.0; };
    auto over = [](const RingTriangle&) { return 1.0; };
    EXPECT_EQ(removeInteriorPoints(mesh, none, over, 0.5), 0u);
    EXPECT_EQ(mesh.triangles, triangles);
}

// FreeCAD's loft through a circle, an ellipse and a tilted circle (tests/data/freecad_loft.brep,
// the benchmark's generated loft) at relative 5e-4: compact takes at most 0.85x the triangles
// (2,680 of 3,424) and still passes the verifier, closed. A sphere was the example until its
// columns were tested on the rows its kd-tree cuts (EvenColumns.RowsAreCutOnTheOtherAxisLines):
// its plain mesh now has almost no point to spare (the same sphere at the same relative
// tolerance: 5,634 triangles, compact 5,606; before, 6,696 and 5,304).
TEST(InteriorPoints, CompactLoftHasFewerTrianglesWithinTheTolerance) {
    const TopoDS_Shape loft = occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_loft.brep");
    const Model model = occ::importModel(loft);
    TessellationOptions options;
    options.tolerance = 5e-4 * model.boundingBoxDiagonal;
    const auto plain = tessellateModel(model, options);
    options.compact = true;
    const auto compact = tessellateModel(model, options);
    ASSERT_TRUE(compact.failures.empty());
    EXPECT_LE(compact.mesh.triangles.size(), 0.85 * plain.mesh.triangles.size())
        << compact.mesh.triangles.size() << " of " << plain.mesh.triangles.size();
    const auto report = occ::verifyMesh(loft, compact.mesh, options.tolerance);
    EXPECT_TRUE(report.pass) << "dev " << report.maxDev << " cover " << report.maxCover;
    EXPECT_EQ(report.openEdges, 0u);
}

}  // namespace
}  // namespace nurbslod
