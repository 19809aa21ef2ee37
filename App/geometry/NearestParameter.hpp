#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace nurbslod {

// The parameter of a curve nearest to a point, the curve sampled at increasing `parameters`
// whose squared distances to the point are `sampled`: from the nearest sample, a golden
// section search over the spans on either side of it with `distance2(t)`, the squared distance
// at t (the sample itself where nothing between is nearer). Exact where the distance has one
// minimum over those two spans, as it has for a point near a curve sampled finely enough.
template <class Distance2>
double nearestParameter(const std::vector<double>& parameters, const std::vector<double>& sampled,
                        Distance2&& distance2) {
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < sampled.size(); ++k)
        if (sampled[k] < sampled[nearest]) nearest = k;
    double low = parameters[nearest == 0 ? 0 : nearest - 1];
    double high = parameters[std::min(nearest + 1, parameters.size() - 1)];
    const double ratio = 0.5 * (std::sqrt(5.0) - 1);
    double a = high - ratio * (high - low), b = low + ratio * (high - low);
    double fa = distance2(a), fb = distance2(b);
    for (int step = 0; step < 40; ++step) {  // 0.618^40: 4e-9 of the two spans
        if (fa < fb) {
            high = b, b = a, fb = fa;
            a = high - ratio * (high - low), fa = distance2(a);
        } else {
            low = a, a = b, fa = fb;
            b = low + ratio * (high - low), fb = distance2(b);
        }
    }
    if (sampled[nearest] <= std::min(fa, fb)) return parameters[nearest];
    return fa < fb ? a : b;
}

}  // namespace nurbslod
