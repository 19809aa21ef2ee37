#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
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
// mayJoin(point, kept), where given, may refuse to merge a point into the kept point (given as
// the first point that kept it); the search then goes on to the other kept points near it.
WeldedPoints weldPoints(const std::vector<Point3>& points, const std::vector<char>& used,
                        double quantum,
                        const std::function<bool(std::uint32_t, std::uint32_t)>& mayJoin = {});

// Takes back the welds that fold the mesh: between two points where the weld joined two B-rep
// vertices each (brepVertex: per point, the vertex it stands for or -1), a side used by more
// triangles after the weld than any side it came from was, or one where the weld joined two
// triangles lying on each other (two faces of a plate thinner than the weld, on each other or
// across its rim). The points that the weld moved onto such a side's ends are welded again (at
// `quantum`) among themselves only, apart from the points they were moved onto. Returns how
// many points it moved back.
std::size_t unweldFolds(const std::vector<std::array<std::uint32_t, 3>>& triangles,
                        const std::vector<Point3>& points,
                        const std::vector<std::int32_t>& brepVertex, double quantum,
                        WeldedPoints& welded);

}  // namespace nurbslod
