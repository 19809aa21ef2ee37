#include "geometry/BezierGridLookup.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nurbslod {

namespace {

BezierGridLookup lookup(const std::vector<double>& breaks, std::span<const double> ts, char name) {
    BezierGridLookup out;
    const int spans = static_cast<int>(breaks.size()) - 1;
    for (size_t k = 0; k < ts.size(); ++k) {
        if (!std::isfinite(ts[k]))
            throw std::invalid_argument(std::string("grid parameter ") + name + "[" +
                                        std::to_string(k) + "] is not finite");
        const double t = std::clamp(ts[k], breaks.front(), breaks.back());
        const int a = std::clamp(
            static_cast<int>(std::upper_bound(breaks.begin(), breaks.end(), t) - breaks.begin()) -
                1,
            0, spans - 1);
        const double length = breaks[a + 1] - breaks[a];
        const double s = (t - breaks[a]) / length;
        out.patch.push_back(a);
        out.local.push_back(s);
        out.complement.push_back(1.0 - s);
        out.scale.push_back(1.0 / length);
        out.parameter.push_back(t);
    }
    return out;
}

}  // namespace

BezierGridLookup BezierGridLookup::alongU(const BezierPatchGrid& grid, std::span<const double> us) {
    return lookup(grid.breakpointsU(), us, 'u');
}

BezierGridLookup BezierGridLookup::alongV(const BezierPatchGrid& grid, std::span<const double> vs) {
    return lookup(grid.breakpointsV(), vs, 'v');
}

}  // namespace nurbslod
