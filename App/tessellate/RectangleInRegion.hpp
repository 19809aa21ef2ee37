#pragma once

#include <polyclipping/clipper.hpp>

namespace nurbslod {

// Where an axis-aligned rectangle lies with respect to a region of integer polygons
// (ClipperLib paths, non-zero fill), found without clipping.
enum class RectangleInRegion {
    Inside,   // no boundary segment meets it, and it is inside the region
    Outside,  // no boundary segment meets it, and it is outside the region
    Near,     // a boundary segment meets the closed rectangle: only a clip can tell
};

// The kd-tree asks this of every cell. Most cells lie wholly inside or outside the trimmed
// region; for them the answer needs one pass over the boundary's segments and no clipping.
// Where no segment meets the closed rectangle, the rectangle is wholly inside or wholly
// outside, and the winding number of its centre (non-zero fill, as the clipping uses) tells
// which. Every test is exact in integers, so Inside and Outside agree with what clipping the
// region to the rectangle gives: the whole rectangle or nothing.
RectangleInRegion rectangleInRegion(const ClipperLib::Paths& region, ClipperLib::cInt x0,
                                    ClipperLib::cInt y0, ClipperLib::cInt x1, ClipperLib::cInt y1);

}  // namespace nurbslod
