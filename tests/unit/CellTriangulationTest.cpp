#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "tessellate/CellTriangulation.hpp"
#include "tessellate/PolygonTriangulator.hpp"

using nurbslod::IntegerPoint2;
using nurbslod::triangulateCellWithoutCaps;

namespace {

using Ring = std::vector<IntegerPoint2>;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

std::int64_t twiceArea(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The largest angle of the triangle in degrees, in the cell scaled to the unit square.
double largestAngle(const Ring& ring, const std::array<std::uint32_t, 3>& t, double width,
                    double height) {
    double largest = 0;
    for (int k = 0; k < 3; ++k) {
        const IntegerPoint2& o = ring[t[k]];
        const IntegerPoint2& p = ring[t[(k + 1) % 3]];
        const IntegerPoint2& q = ring[t[(k + 2) % 3]];
        const double ux = (p.x - o.x) / width, uy = (p.y - o.y) / height;
        const double vx = (q.x - o.x) / width, vy = (q.y - o.y) / height;
        const double c = (ux * vx + uy * vy) / std::hypot(ux, uy) / std::hypot(vx, vy);
        largest = std::max(largest, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI);
    }
    return largest;
}

// Every triangle counter-clockwise with area, n - 2 of them, covering the cell exactly.
void expectTriangulatesTheCell(const Ring& ring, const Triangles& triangles) {
    ASSERT_EQ(triangles.size(), ring.size() - 2);
    std::int64_t sum = 0;
    std::set<std::uint32_t> used;
    for (const auto& t : triangles) {
        const std::int64_t area = twiceArea(ring[t[0]], ring[t[1]], ring[t[2]]);
        EXPECT_GT(area, 0);
        sum += area;
        used.insert(t.begin(), t.end());
    }
    std::int64_t cell = 0;
    for (std::size_t i = 1; i + 1 < ring.size(); ++i)
        cell += twiceArea(ring[0], ring[i], ring[i + 1]);
    EXPECT_EQ(sum, cell);
    EXPECT_EQ(used.size(), ring.size());
}

// The cell of the fold that the zigzag made: points on the top side, and a neighbour's corner
// one step below the top right corner.
Ring cellWithAPointOneStepBelowItsCorner() {
    const std::int64_t x0 = 768000000, x1 = 835132530, y0 = 1000000000, y1 = 1020717537;
    return {{x0, y0}, {x1, y0}, {x1, y1 - 1}, {x1, y1}, {808620386, y1}, {795364314, y1}, {x0, y1}};
}

}  // namespace

TEST(CellTriangulation, APointOneStepFromACornerMakesNoCap) {
    const Ring ring = cellWithAPointOneStepBelowItsCorner();
    const double width = double(ring[1].x - ring[0].x), height = double(ring[3].y - ring[0].y);
    const Triangles triangles = triangulateCellWithoutCaps(ring);
    expectTriangulatesTheCell(ring, triangles);
    for (const auto& t : triangles) EXPECT_LT(largestAngle(ring, t, width, height), 150.0);
    // the general triangulator made a cap there (this test's reason to exist)
    double zigzagLargest = 0;
    for (const auto& t : nurbslod::triangulatePolygon({ring}).triangles)
        zigzagLargest = std::max(zigzagLargest, largestAngle(ring, t, width, height));
    EXPECT_GT(zigzagLargest, 179.0);
}

TEST(CellTriangulation, RandomHangingPointsNeverGiveACap) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 200; ++trial) {
        const std::int64_t width = 1 + random() % 100000, height = 1 + random() % 100000;
        auto sidePoints = [&](std::int64_t length) {
            std::set<std::int64_t> at;
            const int count = static_cast<int>(random() % 6);
            for (int k = 0; k < count && length > 1; ++k) {
                // near the ends as often as anywhere: one step from a corner is the hard case
                const std::int64_t offset = random() % 2 ? 1 + random() % 3 : 1 + random() % length;
                at.insert(std::clamp<std::int64_t>(random() % 2 ? offset : length - offset, 1,
                                                   length - 1));
            }
            return std::vector<std::int64_t>(at.begin(), at.end());
        };
        Ring ring{{0, 0}};
        for (auto x : sidePoints(width)) ring.push_back({x, 0});
        ring.push_back({width, 0});
        for (auto y : sidePoints(height)) ring.push_back({width, y});
        ring.push_back({width, height});
        auto top = sidePoints(width);
        for (auto x = top.rbegin(); x != top.rend(); ++x) ring.push_back({*x, height});
        ring.push_back({0, height});
        auto left = sidePoints(height);
        for (auto y = left.rbegin(); y != left.rend(); ++y) ring.push_back({0, *y});
        const Triangles triangles = triangulateCellWithoutCaps(ring);
        expectTriangulatesTheCell(ring, triangles);
        // a cap would need three points near one line; the unit square's points never force it
        for (const auto& t : triangles)
            EXPECT_LT(largestAngle(ring, t, double(width), double(height)), 170.0)
                << "trial " << trial;
    }
}

TEST(CellTriangulation, DegenerateRingsGiveNoTriangles) {
    EXPECT_TRUE(triangulateCellWithoutCaps({{0, 0}, {5, 0}}).empty());
    EXPECT_TRUE(triangulateCellWithoutCaps({{0, 0}, {5, 0}, {9, 0}, {12, 0}}).empty());
}
