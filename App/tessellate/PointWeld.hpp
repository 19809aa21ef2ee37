#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// Points merged where they are closer than `quantum`, in order: each used point goes to the
// first kept point found within quantum in its grid cell (cells of size quantum) or one of its
// 26 neighbours, searched in the order dx, dy, dz = -1, 0, 1; otherwise it is kept itself and
// becomes its cell's point if the cell has none yet. Unused points are dropped.
struct WeldedPoints {
    std::vector<Point3> kept;
    std::vector<std::uint32_t> remap;  // per input point its kept point (unused: unspecified)
};
WeldedPoints weldPoints(const std::vector<Point3>& points, const std::vector<char>& used,
                        double quantum);

}  // namespace nurbslod
