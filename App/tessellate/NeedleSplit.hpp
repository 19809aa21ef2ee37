#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

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

// The triangles' directed sides by the vertex they leave: for each vertex a list, newest first,
// of its sides as (triangle, corner), linked through one array. A side is checked against its
// triangle as it is now, so a triangle that changes is added again and its old sides are
// skipped. The model's mesh was indexed in a hash table of twice its sides at 16 bytes each: on
// bottle.brep at relative 1e-4 a fresh 4 MB array for 41 needles, whose first touch (page
// faults) took 5% of the tessellation's time; these lists take 12 bytes a side, written in
// order, and 4 a vertex.
class SidesFromVertex {
public:
    using Triangles = std::vector<std::array<std::uint32_t, 3>>;
    explicit SidesFromVertex(const Triangles& triangles) : triangles_(&triangles) {
        std::uint32_t vertices = 0;
        for (const auto& t : triangles)
            for (const std::uint32_t v : t) vertices = std::max(vertices, v + 1);
        first_.assign(vertices, kNone);
        // room for the triangles that splits change and add: growing the array past its
        // capacity would copy it whole
        sides_.reserve(3 * triangles.size() + 6 * kSplitsWithoutCopy);
        for (std::size_t i = 0; i < triangles.size(); ++i) add(i);
    }
    // Adds triangle i's sides as it is now.
    void add(std::size_t i) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = (*triangles_)[i][k];
            if (from >= first_.size()) first_.resize(from + 1, kNone);
            sides_.push_back({static_cast<std::uint32_t>(i), k, first_[from]});
            first_[from] = static_cast<std::uint32_t>(sides_.size() - 1);
        }
    }
    // The triangle that runs from -> to now, the one added last where several do; none: -1.
    std::ptrdiff_t at(std::uint32_t from, std::uint32_t to) const {
        if (from >= first_.size()) return -1;
        for (std::uint32_t s = first_[from]; s != kNone; s = sides_[s].next) {
            const auto& t = (*triangles_)[sides_[s].triangle];
            const int k = sides_[s].corner;
            if (t[k] == from && t[(k + 1) % 3] == to)
                return static_cast<std::ptrdiff_t>(sides_[s].triangle);
        }
        return -1;
    }

    // splits whose changes fit in the room reserved for them
    static constexpr std::size_t kSplitsWithoutCopy = 1024;

private:
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};
    struct Side {
        std::uint32_t triangle;
        int corner;
        std::uint32_t next;  // the vertex's side added before this one
    };
    const Triangles* triangles_;
    std::vector<std::uint32_t> first_;  // per vertex: its side added last
    std::vector<Side> sides_;
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
        origins->reserve(triangles.size() + SidesFromVertex::kSplitsWithoutCopy);
        origins->resize(triangles.size());
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            (*origins)[i].triangle = static_cast<std::uint32_t>(i);
            for (int k = 0; k < 3; ++k)
                (*origins)[i].corners[k] = {static_cast<std::uint32_t>(i), k};
        }
    }
    SidesFromVertex sides(triangles);
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
        const std::ptrdiff_t across = sides.at(b, a);
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
        sides.add(j);
        sides.add(triangles.size() - 1);
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
