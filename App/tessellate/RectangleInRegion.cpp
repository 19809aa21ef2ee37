#include "tessellate/RectangleInRegion.hpp"

#include <algorithm>

namespace nurbslod {

namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
// Products of two coordinate differences (up to 2^32 each at twice the scale) need more than
// 64 bits; in 128 bits every sign below is exact.
using Wide = __int128;

// Twice the cross product (b - a) x (p - a) for p given at twice the scale: its sign says on
// which side of the line a -> b the point p lies.
Wide sideOf(const IntPoint& a, const IntPoint& b, cInt px2, cInt py2) {
    return Wide(b.X - a.X) * Wide(py2 - 2 * a.Y) - Wide(b.Y - a.Y) * Wide(px2 - 2 * a.X);
}

// Whether segment ab meets the closed rectangle: the bounding boxes overlap and the rectangle's
// corners are not all strictly on one side of the line (the separating axes of a segment and a
// box are x, y and the segment's normal).
bool meets(const IntPoint& a, const IntPoint& b, cInt x0, cInt y0, cInt x1, cInt y1) {
    if (std::max(a.X, b.X) < x0 || std::min(a.X, b.X) > x1 || std::max(a.Y, b.Y) < y0 ||
        std::min(a.Y, b.Y) > y1)
        return false;
    int positive = 0, negative = 0;
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) {
        const Wide side = sideOf(a, b, 2 * x, 2 * y);
        positive += side > 0;
        negative += side < 0;
    }
    return positive < 4 && negative < 4;
}

}  // namespace

RectangleInRegion rectangleInRegion(const ClipperLib::Paths& region, cInt x0, cInt y0, cInt x1,
                                    cInt y1) {
    // The centre at twice the scale, so that it stays an integer.
    const cInt cx2 = x0 + x1, cy2 = y0 + y1;
    int winding = 0;
    for (const ClipperLib::Path& path : region) {
        const std::size_t n = path.size();
        for (std::size_t i = 0; i < n; ++i) {
            const IntPoint& a = path[i];
            const IntPoint& b = path[i + 1 == n ? 0 : i + 1];
            if (meets(a, b, x0, y0, x1, y1)) return RectangleInRegion::Near;
            // A segment that crosses the centre's horizontal line (half-open in y, so that a
            // vertex on the line counts once) crosses the ray to the right where the centre
            // lies left of the segment taken upwards.
            const bool upward = 2 * a.Y <= cy2 && 2 * b.Y > cy2;
            const bool downward = 2 * b.Y <= cy2 && 2 * a.Y > cy2;
            if (upward && sideOf(a, b, cx2, cy2) > 0) ++winding;
            if (downward && sideOf(a, b, cx2, cy2) < 0) --winding;
        }
    }
    return winding != 0 ? RectangleInRegion::Inside : RectangleInRegion::Outside;
}

}  // namespace nurbslod
