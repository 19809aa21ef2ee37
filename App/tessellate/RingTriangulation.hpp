#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// Triangles over rings of points in a plane, by their coordinates there: the ring of largest
// area is the outer one, the others holes in it. Each triangle holds three indices into the
// concatenation of the rings (in the order given), counter-clockwise. None where the rings do
// not make a valid polygon with holes (crossing chords, two outer rings, a coordinate that is
// not finite). The points are rounded to 2^-50 of the rings' extent, so that the triangulator's
// orientation tests are exact.
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateRings(
    const std::vector<std::vector<Point2>>& rings);

}  // namespace nurbslod
