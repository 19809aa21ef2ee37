#pragma once

#include <vector>

#include "geometry/BSplineSurface.hpp"

namespace nurbslod {

// The 28 bicubic Bezier patches of the Utah teapot (rim, body, handle, spout, lid; the
// evaluation paper's "Utah teapot", section 4), each as a B-spline surface on [0,1]^2.
std::vector<BSplineSurface> utahTeapot();

}  // namespace nurbslod
