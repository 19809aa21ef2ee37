#include "tessellate/RingTriangulation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "tessellate/PolygonTriangulator.hpp"

namespace nurbslod {

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateRings(
    const std::vector<std::vector<Point2>>& rings) {
    if (rings.empty()) return std::nullopt;
    double extent = 0;
    for (const auto& ring : rings)
        for (const Point2& p : ring) {
            if (!p.allFinite()) return std::nullopt;
            extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
        }
    if (!(extent > 0) || !std::isfinite(extent)) return std::nullopt;
    // 2^50 steps across the rings: far below any tolerance, and every cross product of two
    // coordinate differences stays exact in the triangulator's 128-bit arithmetic
    const double scale = std::ldexp(1.0, 50) / extent;
    std::vector<std::vector<IntegerPoint2>> integerRings;
    std::vector<double> areas;
    for (const auto& ring : rings) {
        std::vector<IntegerPoint2> integerRing;
        for (const Point2& p : ring)
            integerRing.push_back({std::llround(p.x() * scale), std::llround(p.y() * scale)});
        double twiceArea = 0;
        for (std::size_t i = 0; i < integerRing.size(); ++i) {
            const auto& a = integerRing[i];
            const auto& b = integerRing[(i + 1) % integerRing.size()];
            twiceArea += double(a.x) * double(b.y) - double(b.x) * double(a.y);
        }
        areas.push_back(std::abs(twiceArea));
        integerRings.push_back(std::move(integerRing));
    }
    // the outer ring first, the rings' points keeping their indices in the concatenation
    const std::size_t outer =
        static_cast<std::size_t>(std::max_element(areas.begin(), areas.end()) - areas.begin());
    std::vector<std::size_t> order(rings.size());
    std::iota(order.begin(), order.end(), 0);
    std::swap(order[0], order[outer]);
    std::vector<std::uint32_t> firstIndex(rings.size(), 0);
    for (std::size_t r = 1; r < rings.size(); ++r)
        firstIndex[r] = firstIndex[r - 1] + static_cast<std::uint32_t>(rings[r - 1].size());
    std::vector<std::vector<IntegerPoint2>> ordered;
    std::vector<std::uint32_t> index;  // concatenation of `ordered` -> concatenation of `rings`
    for (const std::size_t r : order) {
        ordered.push_back(std::move(integerRings[r]));
        for (std::uint32_t i = 0; i < rings[r].size(); ++i) index.push_back(firstIndex[r] + i);
    }
    const Triangulation triangulation = triangulatePolygon(ordered);
    if (!triangulation.complete || triangulation.triangles.empty()) return std::nullopt;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const auto& t : triangulation.triangles)
        triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    return triangles;
}

}  // namespace nurbslod
