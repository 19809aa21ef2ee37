#include "tessellate/PointWeld.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "geometry/BitMix.hpp"

namespace nurbslod {

namespace {

// Grid cell -> first kept point, by open addressing in one array. A node-based hash map did
// 27 lookups per point, each a division by a prime and a pointer chase: the weld took 5% of
// a whole tessellation.
class CellTable {
public:
    explicit CellTable(std::size_t capacity) {
        std::size_t size = 64;
        while (size < 2 * capacity) size *= 2;
        slots_.assign(size, Slot{kEmpty, 0});
    }
    // the point registered for `key`, or -1
    std::int64_t find(std::int64_t key) const {
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t at = mixBits(static_cast<std::uint64_t>(key)) & mask;;
             at = (at + 1) & mask) {
            if (slots_[at].key == key) return slots_[at].point;
            if (slots_[at].key == kEmpty) return -1;
        }
    }
    // registers `point` for `key` unless the key has one
    void insert(std::int64_t key, std::uint32_t point) {
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t at = mixBits(static_cast<std::uint64_t>(key)) & mask;;
             at = (at + 1) & mask) {
            if (slots_[at].key == key) return;
            if (slots_[at].key == kEmpty) {
                slots_[at] = {key, point};
                return;
            }
        }
    }

private:
    struct Slot {
        std::int64_t key;
        std::uint32_t point;
    };
    // keys are 63-bit cell codes, never negative
    static constexpr std::int64_t kEmpty = -1;
    std::vector<Slot> slots_;
};

}  // namespace

WeldedPoints weldPoints(const std::vector<Point3>& points, const std::vector<char>& used,
                        double quantum,
                        const std::function<bool(std::uint32_t, std::uint32_t)>& mayJoin) {
    WeldedPoints out;
    std::vector<std::uint32_t> keptFrom;  // per kept point, the point it was
    out.remap.assign(points.size(), 0);
    std::size_t usedCount = 0;
    for (std::size_t i = 0; i < points.size(); ++i) usedCount += used[i] != 0;
    CellTable cells(usedCount);
    // 21 bits per axis: cells far apart may share a code, and are then told apart by distance
    auto cellKey = [&](const Point3& p, int dx, int dy, int dz) {
        const auto x = (static_cast<std::int64_t>(std::floor(p.x() / quantum)) + dx) & 0x1fffff;
        const auto y = (static_cast<std::int64_t>(std::floor(p.y() / quantum)) + dy) & 0x1fffff;
        const auto z = (static_cast<std::int64_t>(std::floor(p.z() / quantum)) + dz) & 0x1fffff;
        return (x << 42) | (y << 21) | z;
    };
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!used[i]) continue;
        const Point3& p = points[i];
        std::int64_t found = -1;
        // the point's grid cell and its neighbours: two close points may straddle a cell border
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz)
                    if (const std::int64_t k = cells.find(cellKey(p, dx, dy, dz));
                        k >= 0 && (out.kept[static_cast<std::size_t>(k)] - p).norm() <= quantum &&
                        (!mayJoin || mayJoin(static_cast<std::uint32_t>(i),
                                             keptFrom[static_cast<std::size_t>(k)])))
                        found = k;
        if (found >= 0) {
            out.remap[i] = static_cast<std::uint32_t>(found);
            continue;
        }
        out.remap[i] = static_cast<std::uint32_t>(out.kept.size());
        cells.insert(cellKey(p, 0, 0, 0), out.remap[i]);
        out.kept.push_back(p);
        keptFrom.push_back(static_cast<std::uint32_t>(i));
    }
    return out;
}

std::size_t unweldFolds(const std::vector<std::array<std::uint32_t, 3>>& triangles,
                        const std::vector<Point3>& points,
                        const std::vector<std::int32_t>& brepVertex, double quantum,
                        WeldedPoints& welded) {
    std::vector<std::uint32_t>& remap = welded.remap;
    // per kept point, the B-rep vertices the weld joined there: none (-1), one (its number) or
    // several (-2); only sides between two of the last kind are looked at
    std::vector<std::int64_t> joined(welded.kept.size(), -1);
    for (const auto& t : triangles)
        for (const std::uint32_t i : t) {
            const std::int64_t vertex = i < brepVertex.size() ? brepVertex[i] : -1;
            std::int64_t& at = joined[remap[i]];
            if (vertex >= 0 && at != vertex) at = at == -1 ? vertex : -2;
        }
    auto joinsVertices = [&](std::uint32_t kept) { return joined[kept] == -2; };
    // each such side, welded, with the side it came from and its triangle
    struct Side {
        std::uint32_t low, high;          // welded
        std::uint32_t fromLow, fromHigh;  // before the weld
        std::size_t triangle;
    };
    std::vector<Side> sides;
    for (std::size_t n = 0; n < triangles.size(); ++n) {
        const auto& t = triangles[n];
        const std::uint32_t a = remap[t[0]], b = remap[t[1]], c = remap[t[2]];
        if (a == b || b == c || a == c) continue;  // the weld drops it
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t p = t[k], q = t[(k + 1) % 3];
            const std::uint32_t wp = remap[p], wq = remap[q];
            if (!joinsVertices(wp) || !joinsVertices(wq)) continue;
            sides.push_back(
                {std::min(wp, wq), std::max(wp, wq), std::min(p, q), std::max(p, q), n});
        }
    }
    if (sides.empty()) return 0;
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
        return std::tie(x.low, x.high, x.fromLow, x.fromHigh, x.triangle) <
               std::tie(y.low, y.high, y.fromLow, y.fromHigh, y.triangle);
    });
    auto weldedNormal = [&](std::size_t n) {
        const auto& t = triangles[n];
        const Point3 &a = welded.kept[remap[t[0]]], &b = welded.kept[remap[t[1]]],
                     &c = welded.kept[remap[t[2]]];
        return Vector3((b - a).cross(c - a).normalized());
    };
    // A side is folded where more triangles meet at it than at any side it came from (two
    // sides of a plate and its rim), or where the weld joined two triangles that lie on each
    // other, their normals opposite (the plate's two sides across its rim, the rim's strip
    // face narrower than the weld and gone with it); only between points where the weld joined
    // two B-rep vertices each. Elsewhere such folds are a face's own point moved onto a chord
    // (needles, FoldedPairs), which the steps after the weld resolve: taken back there too,
    // bottle.brep at relative 1e-4 took 12 more triangles and 2 sides of three.
    constexpr double kOnEachOther = -0.99;
    std::vector<char> folded(welded.kept.size(), 0);
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        std::size_t mostFromOne = 0;
        while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high) {
            std::size_t k = j;
            while (k < sides.size() && sides[k].low == sides[j].low &&
                   sides[k].high == sides[j].high && sides[k].fromLow == sides[j].fromLow &&
                   sides[k].fromHigh == sides[j].fromHigh)
                ++k;
            mostFromOne = std::max(mostFromOne, k - j);
            j = k;
        }
        const bool moreThanBefore = j - i > 2 && mostFromOne <= 2;
        const bool joinedOnEachOther =
            j - i == 2 && mostFromOne == 1 &&
            weldedNormal(sides[i].triangle).dot(weldedNormal(sides[i + 1].triangle)) < kOnEachOther;
        if (moreThanBefore || joinedOnEachOther) folded[sides[i].low] = folded[sides[i].high] = 1;
        i = j;
    }
    // the moved points of those welded points, welded again among themselves only: a side's
    // own copies of one point stay one point
    std::vector<char> moved(points.size(), 0);
    std::size_t given = 0;
    for (const auto& t : triangles)
        for (const std::uint32_t i : t)
            if (!moved[i] && folded[remap[i]] && points[i] != welded.kept[remap[i]]) {
                moved[i] = 1;
                ++given;
            }
    if (given == 0) return 0;
    const WeldedPoints again = weldPoints(points, moved, quantum);
    const auto base = static_cast<std::uint32_t>(welded.kept.size());
    welded.kept.insert(welded.kept.end(), again.kept.begin(), again.kept.end());
    for (std::size_t i = 0; i < points.size(); ++i)
        if (moved[i]) remap[i] = base + again.remap[i];
    return given;
}

}  // namespace nurbslod
