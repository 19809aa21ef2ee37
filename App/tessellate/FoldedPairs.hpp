#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/Point.hpp"

namespace nurbslod {

// Pairs of triangles on the same three points, one each way round, whose points lie on one
// line: a fold with no area, each side of it used once each way. They come where two faces'
// cell sides cut a shared chord a hair from its ends and each face makes a triangle of the
// three points on the chord (trj7_b1-ec-214.stp at relative 1e-4: faces 184 and 185, cuts
// 0.0006 and 0.002 mm from the ends of a 0.63 mm chord). Such a pair covers nothing, and
// every side it uses is used by the pair in both directions, so without it the other
// triangles keep their sides' uses as they were: no edge opens. Two triangles that do have
// area, one on each side of a thin sheet, are a shape, not a fold, and stay.
//
// Returns whether each triangle is kept.
std::vector<char> trianglesOutsideFolds(const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                        const std::vector<Point3>& positions);

}  // namespace nurbslod
