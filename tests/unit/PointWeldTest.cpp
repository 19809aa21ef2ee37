#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "tessellate/PointWeld.hpp"

using nurbslod::Point3;

namespace {

// The weld as its header states it, with an ordered map and no hashing: the reference.
nurbslod::WeldedPoints referenceWeld(const std::vector<Point3>& points,
                                     const std::vector<char>& used, double quantum) {
    nurbslod::WeldedPoints out;
    out.remap.assign(points.size(), 0);
    std::map<std::array<std::int64_t, 3>, std::uint32_t> cells;
    auto cellOf = [&](const Point3& p, int dx, int dy, int dz) {
        // the same 21-bit codes per axis
        return std::array<std::int64_t, 3>{
            (static_cast<std::int64_t>(std::floor(p.x() / quantum)) + dx) & 0x1fffff,
            (static_cast<std::int64_t>(std::floor(p.y() / quantum)) + dy) & 0x1fffff,
            (static_cast<std::int64_t>(std::floor(p.z() / quantum)) + dz) & 0x1fffff};
    };
    for (size_t i = 0; i < points.size(); ++i) {
        if (!used[i]) continue;
        long found = -1;
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz) {
                    auto it = cells.find(cellOf(points[i], dx, dy, dz));
                    if (it != cells.end() && (out.kept[it->second] - points[i]).norm() <= quantum)
                        found = it->second;
                }
        if (found >= 0) {
            out.remap[i] = static_cast<std::uint32_t>(found);
            continue;
        }
        out.remap[i] = static_cast<std::uint32_t>(out.kept.size());
        cells.emplace(cellOf(points[i], 0, 0, 0), out.remap[i]);
        out.kept.push_back(points[i]);
    }
    return out;
}

}  // namespace

TEST(PointWeld, MergesAsTheReferenceDoesOnClustersNearAndFarFromTheOrigin) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const double offset : {0.0, -3.7e4, 1e9}) {
        const double quantum = 1e-3;
        std::vector<Point3> points;
        std::vector<char> used;
        // clusters of points within a few quanta, so that some merge and some do not, and
        // every tenth point unused
        for (int cluster = 0; cluster < 300; ++cluster) {
            const Point3 centre =
                Point3(offset, offset, -offset) + Point3(unit(random), unit(random), unit(random));
            for (int k = 0; k < 8; ++k) {
                points.push_back(centre +
                                 2.5 * quantum * Point3(unit(random), unit(random), unit(random)));
                used.push_back(points.size() % 10 != 0);
            }
        }
        const auto welded = nurbslod::weldPoints(points, used, quantum);
        const auto reference = referenceWeld(points, used, quantum);
        ASSERT_EQ(welded.kept.size(), reference.kept.size()) << offset;
        EXPECT_LT(welded.kept.size(), 0.9 * points.size()) << "nothing merged";
        EXPECT_GT(welded.kept.size(), 300u) << "clusters merged into one point each";
        for (size_t i = 0; i < points.size(); ++i) {
            if (!used[i]) continue;
            EXPECT_EQ(welded.remap[i], reference.remap[i]) << i;
            EXPECT_LE((welded.kept[welded.remap[i]] - points[i]).norm(), quantum);
        }
    }
}

TEST(PointWeld, KeepsPointsFartherApartThanTheQuantum) {
    const std::vector<Point3> points{{0, 0, 0}, {0.0015, 0, 0}, {0.0009, 0, 0}, {5, 5, 5}};
    const auto welded = nurbslod::weldPoints(points, {1, 1, 1, 0}, 1e-3);
    ASSERT_EQ(welded.kept.size(), 2u);
    EXPECT_EQ(welded.remap[0], 0u);
    EXPECT_EQ(welded.remap[1], 1u);
    EXPECT_EQ(welded.remap[2], 0u);  // within 1e-3 of the first point, found first
}

TEST(PointWeld, ACellKeepsItsFirstPoint) {
    // B is in A's cell but farther than the quantum from it: kept, not the cell's point. C is
    // within the quantum of B only, and so finds nothing to merge with.
    const std::vector<Point3> points{{0, 0, 0}, {0.0009, 0.0009, 0.0009}, {0.0017, 0.0009, 0.0009}};
    const auto welded = nurbslod::weldPoints(points, {1, 1, 1}, 1e-3);
    ASSERT_EQ(welded.kept.size(), 3u);
    EXPECT_EQ(welded.remap[2], 2u);
}

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// How many triangles use each side, the triangles' corners taken through remap; triangles the
// remap leaves without three points are dropped, as the weld drops them.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> sideUses(
    const std::vector<Triangle>& triangles, const std::vector<std::uint32_t>& remap) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : triangles) {
        const std::uint32_t a = remap[t[0]], b = remap[t[1]], c = remap[t[2]];
        if (a == b || b == c || a == c) continue;
        for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
            ++uses[{std::min(p, q), std::max(p, q)}];
    }
    return uses;
}

// A closed plate [0, 1] x [0, thickness] x [0, 1], its 12 triangles turned outwards.
std::vector<Point3> platePoints(double thickness) {
    std::vector<Point3> points;
    for (int k = 0; k < 8; ++k)
        points.emplace_back(k & 1, (k & 2) ? thickness : 0.0, (k & 4) ? 1.0 : 0.0);
    return points;
}
const std::vector<Triangle> kPlate{{0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},   // y = 0, y = t
                                   {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},   // x = 0, x = 1
                                   {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};  // z = 0, z = 1

}  // namespace

// A plate thinner than the weld: welded, its two sides lie on each other and its rims fold
// (sides of four triangles, or of two lying on each other); the folds are taken back and every
// side is used by two triangles again.
TEST(PointWeld, WeldsThatFoldAPlateAreTakenBack) {
    const std::vector<Point3> points = platePoints(0.01);
    const std::vector<char> used(points.size(), 1);
    nurbslod::WeldedPoints welded = nurbslod::weldPoints(points, used, 0.0103);
    ASSERT_EQ(welded.kept.size(), 4u);  // the weld alone folds it
    const auto foldedUses = sideUses(kPlate, welded.remap);
    EXPECT_TRUE(std::any_of(foldedUses.begin(), foldedUses.end(),
                            [](const auto& side) { return side.second > 2; }));
    // each corner a B-rep vertex of its own
    const std::vector<std::int32_t> vertices{0, 1, 2, 3, 4, 5, 6, 7};
    // not where the points joined are no B-rep vertices (a face's own point on a chord)
    nurbslod::WeldedPoints unchanged = welded;
    EXPECT_EQ(nurbslod::unweldFolds(kPlate, points, {}, 0.0103, unchanged), 0u);
    EXPECT_EQ(unchanged.kept.size(), 4u);
    EXPECT_EQ(nurbslod::unweldFolds(kPlate, points, vertices, 0.0103, welded), 4u);
    EXPECT_EQ(welded.kept.size(), 8u);
    const auto uses = sideUses(kPlate, welded.remap);
    EXPECT_EQ(uses.size(), 18u);
    for (const auto& [side, count] : uses) EXPECT_EQ(count, 2) << side.first << "-" << side.second;
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_EQ(welded.kept[welded.remap[i]], points[i]) << i;
}

// A weld that closes a crack, two faces at a right angle whose shared side's copies are 1e-4
// apart (B-rep vertices of their own), is kept.
TEST(PointWeld, WeldsThatCloseACrackAreKept) {
    // face A in z = 0, face B in x = 0, their common side along y; B's copy moved by 1e-4
    const std::vector<Point3> points{{0, 0, 0},    {0, 1, 0},    {1, 0, 0}, {1, 1, 0},
                                     {0, 0, 1e-4}, {0, 1, 1e-4}, {0, 0, 1}, {0, 1, 1}};
    const std::vector<Triangle> triangles{{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    const std::vector<char> used(points.size(), 1);
    nurbslod::WeldedPoints welded = nurbslod::weldPoints(points, used, 1e-3);
    ASSERT_EQ(welded.kept.size(), 6u);
    const std::vector<std::int32_t> vertices{0, 1, 2, 3, 4, 5, 6, 7};
    EXPECT_EQ(nurbslod::unweldFolds(triangles, points, vertices, 1e-3, welded), 0u);
    EXPECT_EQ(welded.kept.size(), 6u);
    EXPECT_EQ(welded.remap[4], welded.remap[0]);
    EXPECT_EQ(welded.remap[5], welded.remap[1]);
    EXPECT_EQ(sideUses(triangles, welded.remap).at({welded.remap[0], welded.remap[1]}), 2);
}

// A refused join (mayJoin) keeps the point apart from that kept point, and the search goes on to
// the others near it.
TEST(PointWeld, ARefusedJoinSearchesOn) {
    // the third point is within the quantum of the first (refused) and of the second (allowed)
    const std::vector<Point3> points{{0, 0, 0}, {0.0012, 0, 0}, {0.0009, 0, 0}};
    const std::vector<char> used{1, 1, 1};
    const auto refuseA = [](std::uint32_t point, std::uint32_t kept) {
        return !(point == 2 && kept == 0);
    };
    const auto welded = nurbslod::weldPoints(points, used, 1e-3, refuseA);
    ASSERT_EQ(welded.kept.size(), 2u);
    EXPECT_EQ(welded.remap[2], welded.remap[1]);
    EXPECT_NE(welded.remap[2], welded.remap[0]);
    // refusing every join keeps every point
    const auto none = nurbslod::weldPoints(points, used, 1e-3,
                                           [](std::uint32_t, std::uint32_t) { return false; });
    EXPECT_EQ(none.kept.size(), 3u);
}
