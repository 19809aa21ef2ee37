#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/BitMix.hpp"
#include "geometry/Point.hpp"

namespace nurbslod {

// Where a triangle's corner came from: the triangle (its index before splitNeedles) and the
// corner in it.
struct CornerOrigin {
    std::uint32_t triangle = 0;
    int corner = 0;
};

// What splitNeedles left: for each triangle now, where its corners came from, and the triangle
// whose place it takes (its own, or for the two halves of a split one, the split one).
struct TriangleOrigin {
    std::array<CornerOrigin, 3> corners;
    std::uint32_t triangle = 0;
};

// The triangle that runs each directed side, by the side's two vertices: open addressing, as
// the model's whole mesh fills it (an unordered_map there took 1.5% of trj7_b1-ec-214.stp's
// tessellation at relative 1e-4).
class TriangleOfSide {
public:
    explicit TriangleOfSide(std::size_t sides) {
        std::size_t size = 16;
        while (size < 2 * sides) size *= 2;
        slots_.assign(size, {kEmpty, 0});
    }
    void set(std::uint32_t from, std::uint32_t to, std::size_t triangle) {
        if (2 * (used_ + 1) > slots_.size()) grow();
        Slot& slot = find(key(from, to));
        if (slot.key == kEmpty) ++used_;
        slot = {key(from, to), triangle};
    }
    // The triangle with side from -> to, or none (-1).
    std::ptrdiff_t at(std::uint32_t from, std::uint32_t to) const {
        const Slot& slot = const_cast<TriangleOfSide*>(this)->find(key(from, to));
        return slot.key == kEmpty ? -1 : static_cast<std::ptrdiff_t>(slot.triangle);
    }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Slot {
        std::uint64_t key;
        std::size_t triangle;
    };
    static std::uint64_t key(std::uint32_t from, std::uint32_t to) {
        return (std::uint64_t{from} << 32) | to;
    }
    Slot& find(std::uint64_t key) {
        const std::size_t mask = slots_.size() - 1;
        std::size_t at = mixBits(key) & mask;
        while (slots_[at].key != kEmpty && slots_[at].key != key) at = (at + 1) & mask;
        return slots_[at];
    }
    void grow() {
        std::vector<Slot> old(2 * slots_.size(), Slot{kEmpty, 0});
        old.swap(slots_);
        for (const Slot& slot : old)
            if (slot.key != kEmpty) find(slot.key) = slot;
    }
    std::vector<Slot> slots_;
    std::size_t used_ = 0;
};

// A needle is a triangle of no area whose third corner lies on its longest side: a point cut
// into an edge's chord, placed on the 3D chord so that both faces of the edge share it, which in
// (u, v) the clipper's rounding moved off the chord by a fraction of a step; or a point the
// weld moved onto a chord. Valid in (u, v), of no area in space. Each needle whose longest side
// another triangle runs the other way is removed, and that triangle is split at the needle's
// third corner, which keeps every side shared: the mesh covers the same points as before.
// `position(i)` gives vertex i's position. Returns whether any triangle changed; where one did
// and `origins` is given, it receives the triangles' origins in their new order, so that a
// caller keeps per-corner and per-triangle attributes with them. Most meshes have no needle:
// one pass over the triangles finds that out, and nothing else is done.
template <class Position>
bool splitNeedles(std::vector<std::array<std::uint32_t, 3>>& triangles, const Position& position,
                  std::vector<TriangleOrigin>* origins = nullptr) {
    auto isNeedle = [&](const std::array<std::uint32_t, 3>& t, int& longest) {
        double longestLength = -1;
        for (int k = 0; k < 3; ++k) {
            const double l = (position(t[(k + 1) % 3]) - position(t[k])).squaredNorm();
            if (l > longestLength) longestLength = l, longest = k;
        }
        const Vector3 n = (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
        return n.norm() <= 1e-9 * longestLength;
    };
    std::size_t first = 0;
    for (int longest = 0; first < triangles.size() && !isNeedle(triangles[first], longest);)
        ++first;
    if (first == triangles.size()) return false;
    if (origins) {
        origins->resize(triangles.size());
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            (*origins)[i].triangle = static_cast<std::uint32_t>(i);
            for (int k = 0; k < 3; ++k)
                (*origins)[i].corners[k] = {static_cast<std::uint32_t>(i), k};
        }
    }
    TriangleOfSide triangleOfSide(3 * triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            triangleOfSide.set(triangles[i][k], triangles[i][(k + 1) % 3], i);
    std::vector<char> removed(triangles.size(), 0);
    // each split removes one needle; a split can make a new needle of a neighbour, so the
    // passes are bounded by the number of triangles that were there at the start
    const std::size_t maxSplits = triangles.size();
    std::size_t splits = 0;
    for (std::size_t i = first; i < triangles.size() && splits < maxSplits; ++i) {
        int longest = 0;
        if (removed[i] || !isNeedle(triangles[i], longest)) continue;
        const auto needle = triangles[i];
        const std::uint32_t a = needle[longest], b = needle[(longest + 1) % 3];
        const std::uint32_t c = needle[(longest + 2) % 3];
        // the neighbour runs the long edge the other way: b -> a
        const std::ptrdiff_t across = triangleOfSide.at(b, a);
        if (across < 0 || removed[across]) continue;
        const auto j = static_cast<std::size_t>(across);
        const auto other = triangles[j];
        int at = 0;
        while (!(other[at] == b && other[(at + 1) % 3] == a)) ++at;
        const std::uint32_t d = other[(at + 2) % 3];
        if (d == c) continue;
        // (b, a, d) becomes (b, c, d) and (c, a, d); the needle goes
        ++splits;
        removed[i] = 1;
        triangles[j] = {b, c, d};
        triangles.push_back({c, a, d});
        removed.push_back(0);
        if (origins) {
            auto& from = *origins;
            const CornerOrigin fromB = from[j].corners[at], fromA = from[j].corners[(at + 1) % 3];
            const CornerOrigin fromD = from[j].corners[(at + 2) % 3];
            const CornerOrigin fromC = from[i].corners[(longest + 2) % 3];
            from[j].corners = {fromB, fromC, fromD};
            from.push_back({{fromC, fromA, fromD}, from[j].triangle});
        }
        for (const std::size_t index : {j, triangles.size() - 1})
            for (int k = 0; k < 3; ++k)
                triangleOfSide.set(triangles[index][k], triangles[index][(k + 1) % 3], index);
    }
    std::size_t out = 0;
    for (std::size_t i = 0; i < triangles.size(); ++i)
        if (!removed[i]) {
            triangles[out] = triangles[i];
            if (origins) (*origins)[out] = (*origins)[i];
            ++out;
        }
    triangles.resize(out);
    if (origins) origins->resize(out);
    return splits > 0;
}

}  // namespace nurbslod
