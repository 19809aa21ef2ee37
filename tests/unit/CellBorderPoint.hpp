#pragma once

#include <array>
#include <random>

namespace nurbslod::testing {

// A point (s, t) on the border of the unit cell, one of its four sides at random: a corner of a
// triangle the tessellator makes from a neighbour's points on the cell's sides.
inline std::array<double, 2> cellBorderPoint(std::mt19937& random) {
    const double x = std::uniform_real_distribution<double>(0, 1)(random);
    switch (std::uniform_int_distribution<int>(0, 3)(random)) {
        case 0:
            return {x, 0};
        case 1:
            return {1, x};
        case 2:
            return {x, 1};
        default:
            return {0, x};
    }
}

}  // namespace nurbslod::testing
