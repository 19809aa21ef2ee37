#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace nurbslod {

// A point of the integer (u, v) plane in which the tessellator clips kd-tree cells against the
// trimming region (Clipper's coordinates, ClipperLib::IntPoint holds the same two numbers).
struct IntegerPoint2 {
    std::int64_t x = 0;
    std::int64_t y = 0;

    friend bool operator==(const IntegerPoint2&, const IntegerPoint2&) = default;
};

// The largest coordinate magnitude the triangulator accepts: Clipper's hiRange. Below it every
// cross product of two coordinate differences fits exactly in a signed 128-bit integer, so no
// orientation decision ever depends on rounding.
inline constexpr std::int64_t kMaximumTriangulationCoordinate = 0x3FFFFFFFFFFFFFFF;

// Triangles over the points of a polygon with holes. Each triangle holds three indices into the
// concatenation of the input rings and is counter-clockwise with positive area.
struct Triangulation {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // False when the input was found not to be a valid polygon with holes (rings crossing
    // themselves or each other, a hole outside the outer ring, a coordinate beyond
    // kMaximumTriangulationCoordinate): the triangles are then a best effort that may overlap,
    // leave gaps or leave points out. For valid input every point is used, except points where
    // no area lies on either side (a hole touching its outer ring along a segment, a spike).
    bool complete = true;
};

// Triangulates one polygon with holes without adding points (paper section 7): every point is a
// mesh vertex that is evaluated on the surface and may be shared with a neighbouring cell or face.
//
// rings[0] is the outer boundary, rings[1..] are holes inside it (one outer PolyNode of a Clipper
// PolyTree and its hole children); any ring may run either way round. Indices count ring 0's
// points first, then ring 1's, and so on. Points with equal coordinates are one vertex: all
// their occurrences are reported as the lowest of their indices. Rings may touch the way Clipper
// leaves them: at points, or along segments where the region has zero width. Rings that enclose
// no area (fewer than three distinct points, all points on one line) give no triangles; a
// zero-area outer ring gives an empty, complete triangulation.
//
// Convex rings without holes take the paper's linear zigzag path and give exactly n - 2
// triangles for n distinct points, none of zero area. Everything else is ear clipped after the
// holes are joined to the outer ring by bridges, O(n^2); for valid input the triangles' areas
// sum exactly to the polygon's area (outer minus holes), no triangle has zero area, and a
// polygon of n points without holes gives n - 2 triangles.
Triangulation triangulatePolygon(const std::vector<std::vector<IntegerPoint2>>& rings);

}  // namespace nurbslod
