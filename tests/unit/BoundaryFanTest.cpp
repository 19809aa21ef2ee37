// The triangles of a face too thin for the kd-tree (fanOverBoundary): they must stay on the
// face, between its boundary's chords, however the face bends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tessellate/BoundaryFan.hpp"

namespace nurbslod {
namespace {

class CurvedSliver : public ::testing::Test {
protected:
    static constexpr double outer = 0.9;
    static constexpr int perSide = 32;
    // the plane z = 0 over [0, 1]^2, (u, v) -> (u, v, 0)
    TrimmedSurface face{
        0,
        BSplineSurface(KnotVector(1, {0, 0, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 2, 2,
                       {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 1, 0, 1),
                        HomogeneousPoint3(1, 0, 0, 1), HomogeneousPoint3(1, 1, 0, 1)}),
        {},
        false,
        {},
        {},
        {}};
    std::vector<Point3> positions;

    // A quarter annulus between radii `inner` and `outer` about the origin, out along the outer
    // arc and back along the inner one (counter-clockwise), perSide + 1 points a side; the
    // inner side's points lifted by `lift` in space (a sloppy edge off the plane).
    BoundaryLoop quarterAnnulus(double inner, double lift) {
        BoundaryLoop loop;
        auto add = [&](double radius, double angle, double z) {
            const Point2 uv(radius * std::cos(angle), radius * std::sin(angle));
            loop.points.push_back({uv, static_cast<std::uint32_t>(positions.size())});
            positions.push_back(Point3(uv.x(), uv.y(), z));
        };
        const double quarter = 0.5 * std::numbers::pi;
        for (int i = 0; i <= perSide; ++i) add(outer, quarter * i / perSide, 0);
        for (int i = perSide; i >= 0; --i) add(inner, quarter * i / perSide, lift);
        loop.origins.resize(loop.points.size());
        return loop;
    }

    // how far a point is from the quarter annulus, in space
    static double distanceToAnnulus(const Point3& p, double inner) {
        const double angle = std::atan2(p.y(), p.x());
        const double radius = std::hypot(p.x(), p.y());
        double planar = 0;
        if (angle < 0 || angle > 0.5 * std::numbers::pi)
            planar = 1;  // beyond the quarter: far in any case here
        else
            planar = std::max({0.0, inner - radius, radius - outer});
        return std::hypot(planar, p.z());
    }

    // the largest distance from the annulus of the triangles' corners, edge middles and
    // centroids; also checks that every triangle faces +z where `facing` (a loop with area)
    double largestDistance(const FaceMesh& mesh, double inner, bool facing) {
        double largest = 0;
        for (const auto& t : mesh.triangles) {
            const Point3 &a = mesh.vertices[t[0]].position, &b = mesh.vertices[t[1]].position,
                         &c = mesh.vertices[t[2]].position;
            if (facing) {
                EXPECT_GT((b - a).cross(c - a).z(), 0) << "a triangle faces away from the face";
            }
            for (const Point3& p : {Point3(0.5 * (a + b)), Point3(0.5 * (b + c)),
                                    Point3(0.5 * (c + a)), Point3((a + b + c) / 3)})
                largest = std::max(largest, distanceToAnnulus(p, inner));
        }
        return largest;
    }

    // the sag of one chord of the outer arc
    static double sag() { return outer * (1 - std::cos(0.25 * std::numbers::pi / perSide)); }
};

// A sliver 0.001 wide bent through a quarter turn, whose chords sag 0.00027: a fan from one
// corner spans the bend and folds over it (its triangles reached 0.26 from the face, facing
// away). Every triangle stays within a chord's sag and faces the face's side.
TEST_F(CurvedSliver, TrianglesStayBetweenTheChords) {
    const double inner = outer - 1e-3;
    const FaceMesh mesh = fanOverBoundary(face, {quarterAnnulus(inner, 0)}, positions);
    EXPECT_EQ(mesh.triangles.size(), std::size_t(2 * (perSide + 1) - 2));
    EXPECT_LE(largestDistance(mesh, inner, true), 1.01 * sag());
}

// Both sides on one arc in (u, v): the loop encloses no area (the case that makes a face thin
// for the kd-tree), and its two sides are apart in space only by a sloppy edge's lift. The
// triangles still zip the sides together along the arc.
TEST_F(CurvedSliver, LoopWithoutAreaIsZippedAlongItsCurve) {
    const double lift = 1e-4;
    const FaceMesh mesh = fanOverBoundary(face, {quarterAnnulus(outer, lift)}, positions);
    EXPECT_GE(mesh.triangles.size(), std::size_t(2 * perSide));
    EXPECT_LE(largestDistance(mesh, outer, false), sag() + lift);
}

// A loop of two points (two straight curves between the same two vertices) still gets
// triangles, through the middles of its segments on the surface.
TEST_F(CurvedSliver, LoopOfTwoPointsGetsTriangles) {
    BoundaryLoop loop;
    loop.points = {{Point2(0.2, 0.2), 0}, {Point2(0.6, 0.3), 1}};
    loop.origins.resize(2);
    positions = {Point3(0.2, 0.2, 0), Point3(0.6, 0.3, 0)};
    const FaceMesh mesh = fanOverBoundary(face, {loop}, positions);
    EXPECT_FALSE(mesh.triangles.empty());
}

}  // namespace
}  // namespace nurbslod
