#include "tessellate/PointWeld.hpp"

#include <cmath>

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
                        double quantum) {
    WeldedPoints out;
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
                        k >= 0 && (out.kept[static_cast<std::size_t>(k)] - p).norm() <= quantum)
                        found = k;
        if (found >= 0) {
            out.remap[i] = static_cast<std::uint32_t>(found);
            continue;
        }
        out.remap[i] = static_cast<std::uint32_t>(out.kept.size());
        cells.insert(cellKey(p, 0, 0, 0), out.remap[i]);
        out.kept.push_back(p);
    }
    return out;
}

}  // namespace nurbslod
