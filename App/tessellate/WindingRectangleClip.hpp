#pragma once

#include <optional>
#include <polyclipping/clipper.hpp>

namespace nurbslod {

// Cuts each path of a region down to an axis-aligned rectangle by clipping it against the
// rectangle's four half-planes in turn (Sutherland and Hodgman): a part of a path that leaves
// a half-plane is replaced by the piece of the half-plane's line between where it leaves and
// where it comes back. That loop lies outside the half-plane, so every point strictly inside
// the rectangle keeps its winding number; the paths may run back and forth along the
// rectangle's sides, which add nothing to any winding number.
//
// The kd-tree's walk over its leaves cuts the region node by node only to hand each leaf a
// small piece, which the leaf then clips to its cell with the full clipper (non-zero fill): for
// that the winding numbers inside the node are all that counts, and this costs one pass over
// the points instead of a sweep. Cut points are rounded to the nearest integer on the line.
ClipperLib::Paths clipKeepingWinding(const ClipperLib::Paths& region, ClipperLib::cInt x0,
                                     ClipperLib::cInt y0, ClipperLib::cInt x1, ClipperLib::cInt y1);

// The piece of one simple ring (a region of the clipper's: no edge crosses another) within an
// axis-aligned rectangle, as one simple ring oriented counter-clockwise, or no points where the
// ring leaves nothing with area inside. Clipped against each of the rectangle's half-planes in
// turn (Sutherland and Hodgman), which gives a simple ring where the ring crosses that
// half-plane's line no more than twice; none (std::nullopt) where it crosses more often, or
// touches the line from inside, so the caller asks the full clipper.
std::optional<ClipperLib::Path> clipSimpleRing(const ClipperLib::Path& ring, ClipperLib::cInt x0,
                                               ClipperLib::cInt y0, ClipperLib::cInt x1,
                                               ClipperLib::cInt y1);

}  // namespace nurbslod
