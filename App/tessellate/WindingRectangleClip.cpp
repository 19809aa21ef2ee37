#include "tessellate/WindingRectangleClip.hpp"

#include <algorithm>
#include <utility>

namespace nurbslod {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

// The half-plane coordinate(p) >= bound (keepAbove) or <= bound, coordinate 0: x, 1: y.
struct HalfPlane {
    int coordinate;
    cInt bound;
    bool keepAbove;
    cInt along(const IntPoint& p) const { return coordinate == 0 ? p.X : p.Y; }
    cInt across(const IntPoint& p) const { return coordinate == 0 ? p.Y : p.X; }
    bool inside(const IntPoint& p) const {
        return keepAbove ? along(p) >= bound : along(p) <= bound;
    }
    // The point of segment a-b on the line, a and b on opposite sides: the other coordinate
    // interpolated exactly in 128 bits and rounded to the nearest integer.
    IntPoint cut(const IntPoint& a, const IntPoint& b) const {
        const __int128 da = along(b) - along(a);
        const __int128 numerator =
            static_cast<__int128>(bound - along(a)) * (across(b) - across(a));
        // round(numerator / da) with da != 0 (a and b are on opposite sides)
        __int128 q = numerator / da, r = numerator % da;
        if (2 * (r < 0 ? -r : r) >= (da < 0 ? -da : da)) q += ((r < 0) != (da < 0)) ? -1 : 1;
        const cInt value = across(a) + static_cast<cInt>(q);
        return coordinate == 0 ? IntPoint{bound, value} : IntPoint{value, bound};
    }
};

void clipAgainst(const Path& in, const HalfPlane& plane, Path& out) {
    out.clear();
    if (in.empty()) return;
    out.reserve(in.size() + 2);
    auto push = [&](const IntPoint& p) {
        if (out.empty() || !(out.back() == p)) out.push_back(p);
    };
    IntPoint previous = in.back();
    bool previousInside = plane.inside(previous);
    for (const IntPoint& current : in) {
        const bool currentInside = plane.inside(current);
        if (currentInside != previousInside) {
            const IntPoint& inner = currentInside ? current : previous;
            const IntPoint& outer = currentInside ? previous : current;
            // an inside point already on the line is itself the crossing
            if (plane.along(inner) != plane.bound) push(plane.cut(inner, outer));
        }
        if (currentInside) push(current);
        previous = current;
        previousInside = currentInside;
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
}

}  // namespace

Paths clipKeepingWinding(const Paths& region, cInt x0, cInt y0, cInt x1, cInt y1) {
    const HalfPlane planes[4] = {{0, x0, true}, {0, x1, false}, {1, y0, true}, {1, y1, false}};
    Paths out;
    Path a, b;
    for (const Path& path : region) {
        // a path wholly inside is kept as it is, one wholly outside one side is dropped
        cInt lowX = path.empty() ? 0 : path[0].X, highX = lowX;
        cInt lowY = path.empty() ? 0 : path[0].Y, highY = lowY;
        for (const IntPoint& p : path) {
            lowX = std::min(lowX, p.X), highX = std::max(highX, p.X);
            lowY = std::min(lowY, p.Y), highY = std::max(highY, p.Y);
        }
        if (path.size() < 3 || highX <= x0 || lowX >= x1 || highY <= y0 || lowY >= y1) continue;
        if (lowX >= x0 && highX <= x1 && lowY >= y0 && highY <= y1) {
            out.push_back(path);
            continue;
        }
        a = path;
        for (const HalfPlane& plane : planes) {
            clipAgainst(a, plane, b);
            std::swap(a, b);
            if (a.size() < 3) break;
        }
        if (a.size() >= 3) out.push_back(a);
    }
    return out;
}

std::optional<Path> clipSimpleRing(const Path& ring, cInt x0, cInt y0, cInt x1, cInt y1) {
    if (ring.size() < 3) return Path{};
    cInt lowX = ring[0].X, highX = lowX, lowY = ring[0].Y, highY = lowY;
    for (const IntPoint& p : ring) {
        lowX = std::min(lowX, p.X), highX = std::max(highX, p.X);
        lowY = std::min(lowY, p.Y), highY = std::max(highY, p.Y);
    }
    if (highX < x0 || lowX > x1 || highY < y0 || lowY > y1) return Path{};
    // a half-plane that holds the ring's box holds every piece of it: no pass
    const bool holdsBox[4] = {lowX >= x0, highX <= x1, lowY >= y0, highY <= y1};
    const HalfPlane planes[4] = {{0, x0, true}, {0, x1, false}, {1, y0, true}, {1, y1, false}};
    Path a, b;
    const Path* current = &ring;
    for (int k = 0; k < 4; ++k) {
        if (holdsBox[k]) continue;
        const HalfPlane& plane = planes[k];
        const Path& in = *current;
        const std::size_t n = in.size();
        int crossings = 0;
        bool previousInside = plane.inside(in[n - 1]);
        for (std::size_t i = 0; i < n; ++i) {
            const bool inside = plane.inside(in[i]);
            crossings += inside != previousInside;
            previousInside = inside;
        }
        if (crossings == 0) {
            if (!plane.inside(in[0])) return Path{};
            continue;  // wholly inside: kept as it is
        }
        if (crossings > 2) return std::nullopt;
        // A point on the line between two inside points: the piece of the line that closes the
        // ring could run through it, and the ring would touch itself there.
        for (std::size_t i = 0; i < n; ++i)
            if (plane.along(in[i]) == plane.bound && plane.inside(in[i == 0 ? n - 1 : i - 1]) &&
                plane.inside(in[i + 1 == n ? 0 : i + 1]))
                return std::nullopt;
        clipAgainst(in, plane, b);
        std::swap(a, b);
        current = &a;
        if (a.size() < 3) return Path{};
    }
    const double area = ClipperLib::Area(*current);
    if (area == 0) return Path{};
    Path out = *current;
    if (area < 0) std::reverse(out.begin(), out.end());
    return out;
}

}  // namespace nurbslod
