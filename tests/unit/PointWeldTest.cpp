#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

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
