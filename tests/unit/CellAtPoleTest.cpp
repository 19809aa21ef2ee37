// Cells at a pole of the surface (a degenerated edge): no triangle may join the pole to two
// points of one meridian, which lies flat in space, across the surface.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeSphere.hxx>
#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "occ/ModelImporter.hpp"
#include "tessellate/CellTriangulation.hpp"
#include "tessellate/ModelTessellator.hpp"
#include "tessellate/PolygonTriangulator.hpp"

namespace nurbslod {
namespace {

using Ring = std::vector<IntegerPoint2>;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

std::int64_t twiceArea(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A cell [0, width] x [0, height] whose bottom side (y = 0) is the pole, counter-clockwise from
// (0, 0), with points at `bottom`, `right`, `top` and `left` strictly inside those sides.
struct PoleCell {
    Ring ring;
    std::vector<char> atPole;
};

PoleCell poleCell(std::int64_t width, std::int64_t height, const std::vector<std::int64_t>& bottom,
                  const std::vector<std::int64_t>& right, const std::vector<std::int64_t>& top,
                  const std::vector<std::int64_t>& left) {
    PoleCell cell;
    auto add = [&](std::int64_t x, std::int64_t y, bool pole) {
        cell.ring.push_back({x, y});
        cell.atPole.push_back(pole ? 1 : 0);
    };
    add(0, 0, true);
    for (auto x : bottom) add(x, 0, true);
    add(width, 0, true);
    for (auto y : right) add(width, y, false);
    add(width, height, false);
    for (auto x = top.rbegin(); x != top.rend(); ++x) add(*x, height, false);
    add(0, height, false);
    for (auto y = left.rbegin(); y != left.rend(); ++y) add(0, *y, false);
    return cell;
}

// The cell turned by a quarter turn counter-clockwise (the pole goes to the next side: right,
// top, left), shifted back into positive coordinates; the ring stays counter-clockwise.
PoleCell turned(const PoleCell& cell) {
    PoleCell out = cell;
    std::int64_t top = 0;
    for (const auto& p : cell.ring) top = std::max(top, p.y);
    for (auto& p : out.ring) p = {top - p.y, p.x};
    return out;
}

// A triangle with exactly one corner at the pole and the other two on one side of the cell
// through the pole: in space the pole and two points of one meridian, a triangle in the
// meridian's plane.
bool joinsThePoleToOneMeridian(const PoleCell& cell, const std::array<std::uint32_t, 3>& t) {
    const int poles = cell.atPole[t[0]] + cell.atPole[t[1]] + cell.atPole[t[2]];
    if (poles != 1) return false;
    // the pole side is the line all pole points share; the meridians are the two sides across
    const auto& ring = cell.ring;
    std::size_t p0 = 0;
    while (!cell.atPole[p0]) ++p0;
    std::size_t p1 = p0 + 1;
    while (!cell.atPole[p1]) ++p1;
    const bool poleAlongX = ring[p0].y == ring[p1].y;
    std::int64_t low = std::numeric_limits<std::int64_t>::max(), high = -low;
    for (const auto& p : ring) {
        low = std::min(low, poleAlongX ? p.x : p.y);
        high = std::max(high, poleAlongX ? p.x : p.y);
    }
    std::vector<std::int64_t> others;
    for (auto i : t)
        if (!cell.atPole[i]) others.push_back(poleAlongX ? ring[i].x : ring[i].y);
    return others[0] == others[1] && (others[0] == low || others[0] == high);
}

// n - 2 counter-clockwise triangles with area that cover the cell, none flat at the pole.
void expectPoleAwareTriangulation(const PoleCell& cell, const Triangles& triangles,
                                  const std::string& what) {
    const Ring& ring = cell.ring;
    ASSERT_EQ(triangles.size(), ring.size() - 2) << what;
    std::int64_t sum = 0;
    std::set<std::uint32_t> used;
    for (const auto& t : triangles) {
        const std::int64_t area = twiceArea(ring[t[0]], ring[t[1]], ring[t[2]]);
        EXPECT_GT(area, 0) << what;
        sum += area;
        used.insert(t.begin(), t.end());
        EXPECT_FALSE(joinsThePoleToOneMeridian(cell, t)) << what;
    }
    std::int64_t whole = 0;
    for (std::size_t i = 1; i + 1 < ring.size(); ++i)
        whole += twiceArea(ring[0], ring[i], ring[i + 1]);
    EXPECT_EQ(sum, whole) << what;
    EXPECT_EQ(used.size(), ring.size()) << what;
}

// A cell with a neighbour's corner low on the right side and two on the left, one of them a
// few steps from the pole: the plain triangulation joins the pole to two of them.
PoleCell cellWithHangingPointsNearThePole() {
    return poleCell(43586, 64056, {}, {9308}, {}, {3, 12571});
}

TEST(CellAtPole, NoTriangleJoinsThePoleToTwoPointsOfOneMeridian) {
    PoleCell cell = cellWithHangingPointsNearThePole();
    bool plainJoins = false;
    for (int side = 0; side < 4; ++side, cell = turned(cell)) {
        expectPoleAwareTriangulation(cell, triangulateCellAtPole(cell.ring, cell.atPole),
                                     "pole side " + std::to_string(side));
        // the triangulations used before join the pole to a meridian there (this test's
        // reason to exist)
        for (const auto& t : triangulatePolygon({cell.ring}).triangles)
            plainJoins |= joinsThePoleToOneMeridian(cell, t);
        for (const auto& t : triangulateCellWithoutCaps(cell.ring))
            plainJoins |= joinsThePoleToOneMeridian(cell, t);
    }
    EXPECT_TRUE(plainJoins);
}

TEST(CellAtPole, RandomHangingPointsNeverJoinThePoleToOneMeridian) {
    std::mt19937 random(11);
    int plainJoins = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const std::int64_t width = 2 + random() % 100000, height = 2 + random() % 100000;
        auto sidePoints = [&](std::int64_t length) {
            std::set<std::int64_t> at;
            const int count = static_cast<int>(random() % 5);
            for (int k = 0; k < count; ++k) {
                // one step from a corner as often as anywhere
                const std::int64_t offset = random() % 2 ? 1 + random() % 3 : 1 + random() % length;
                at.insert(std::clamp<std::int64_t>(random() % 2 ? offset : length - offset, 1,
                                                   length - 1));
            }
            return std::vector<std::int64_t>(at.begin(), at.end());
        };
        PoleCell cell = poleCell(width, height, sidePoints(width), sidePoints(height),
                                 sidePoints(width), sidePoints(height));
        for (int side = 0; side < 4; ++side, cell = turned(cell)) {
            expectPoleAwareTriangulation(
                cell, triangulateCellAtPole(cell.ring, cell.atPole),
                "trial " + std::to_string(trial) + " pole side " + std::to_string(side));
            bool joins = false;
            for (const auto& t : triangulatePolygon({cell.ring}).triangles)
                joins |= joinsThePoleToOneMeridian(cell, t);
            plainJoins += joins ? 1 : 0;
        }
    }
    // the plain triangulation of a trimmed cell joins the pole to a meridian in many of them
    EXPECT_GT(plainJoins, 0);
}

TEST(CellAtPole, OtherCellsAreLeftToTheCaller) {
    const PoleCell cell = cellWithHangingPointsNearThePole();
    // no pole
    EXPECT_TRUE(triangulateCellAtPole(cell.ring, std::vector<char>(cell.ring.size(), 0)).empty());
    // the pole marks only part of a side
    std::vector<char> part(cell.ring.size(), 0);
    part.front() = part.back() = 1;  // (0, 0) and (0, 3) of the left side
    EXPECT_TRUE(triangulateCellAtPole(cell.ring, part).empty());
    // pole marks on two sides
    std::vector<char> two = cell.atPole;
    for (std::size_t i = 0; i < cell.ring.size(); ++i) two[i] |= cell.ring[i].y == 64056;
    EXPECT_TRUE(triangulateCellAtPole(cell.ring, two).empty());
    // a point inside the cell: the ring need not be convex
    Ring inner = cell.ring;
    inner.insert(inner.begin() + 3, IntegerPoint2{40000, 30000});
    std::vector<char> innerPole = cell.atPole;
    innerPole.insert(innerPole.begin() + 3, 0);
    EXPECT_TRUE(triangulateCellAtPole(inner, innerPole).empty());
    // marks that do not match the ring
    EXPECT_TRUE(triangulateCellAtPole(cell.ring, {1, 1}).empty());
}

// A whole sphere, at tolerances where the fixed split (0.3, 0.03, 0.015) or the whole-face
// budget with a plain triangulation of the pole cells (0.01) made a triangle of a pole and two
// points of one meridian: every triangle at a pole has area, and its winding agrees with the
// sphere's outward normal and with its corners' normals.
TEST(CellAtPole, SphereHasNoFlatTriangleAtItsPoles) {
    const double radius = 10;
    const Model model = occ::importModel(BRepPrimAPI_MakeSphere(radius).Shape());
    for (const double tolerance : {0.3, 0.03, 0.015, 0.01}) {
        TessellationOptions options;
        options.tolerance = tolerance;
        const TessellationResult result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty()) << result.failures.front().reason;
        const Mesh& mesh = result.mesh;
        std::size_t atPole = 0;
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            const Point3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]],
                         &c = mesh.positions[tri[2]];
            const Vector3 cross = (b - a).cross(c - a);
            const Point3 centroid = (a + b + c) / 3;
            bool pole = false;
            for (const Point3* p : {&a, &b, &c})
                pole |= std::abs(std::abs(p->z()) - radius) < 1e-9 * radius;
            if (!pole) continue;
            ++atPole;
            ASSERT_GT(cross.norm(), 0) << "T " << tolerance << " triangle " << t;
            const Vector3 normal = cross.normalized();
            // a triangle at the pole spans it: its normal is near the pole's axis, far from a
            // flat one's (a meridian's plane holds the axis: cosine 0)
            EXPECT_GT(normal.dot(centroid.normalized()), 0.5)
                << "T " << tolerance << " triangle " << t;
            for (int k = 0; k < 3; ++k)
                EXPECT_GT(mesh.normals[mesh.triangleNormals[t][k]].dot(normal), 0)
                    << "T " << tolerance << " triangle " << t << " corner " << k;
        }
        EXPECT_GE(atPole, 6u) << "T " << tolerance;  // a fan at each of the two poles
    }
}

}  // namespace
}  // namespace nurbslod
