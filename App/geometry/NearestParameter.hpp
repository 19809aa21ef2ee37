#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace nurbslod {

// The parameter of a curve nearest to a point, the curve sampled at increasing `parameters`
// whose squared distances to the point are `sampled`: from the nearest sample, a search over
// the spans on either side of it with `distance2(t)`, the squared distance at t (the sample
// itself where nothing between is nearer). Exact where the distance has one minimum over those
// two spans, as it has for a point near a curve sampled finely enough.
//
// Brent's minimisation: a parabola through the last three points where it falls inside the
// bracket and moves less than half the step before last, a golden section step otherwise. The
// squared distance is nearly a parabola about its minimum, so the parabolic steps take about a
// dozen evaluations where golden sections alone took 42 for the same 4e-9 of the two spans
// (a fifth of hammer.iges's import, pairing its free edges).
template <class Distance2>
double nearestParameter(const std::vector<double>& parameters, const std::vector<double>& sampled,
                        Distance2&& distance2) {
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < sampled.size(); ++k)
        if (sampled[k] < sampled[nearest]) nearest = k;
    double low = parameters[nearest == 0 ? 0 : nearest - 1];
    double high = parameters[std::min(nearest + 1, parameters.size() - 1)];
    const double goldenStep = 0.5 * (3 - std::sqrt(5.0));  // 0.382: the smaller golden part
    const double within = 1e-9 * (high - low);             // the bracket's width when done
    // best: the least value found; second, third: the two before it (the parabola's points)
    double best = low + goldenStep * (high - low);
    double second = best, third = best;
    double fBest = distance2(best), fSecond = fBest, fThird = fBest;
    double step = 0, stepBefore = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double middle = 0.5 * (low + high);
        if (std::abs(best - middle) <= within - 0.5 * (high - low)) break;
        bool parabolic = false;
        if (std::abs(stepBefore) > 0.5 * within) {
            // the vertex of the parabola through (best, second, third) is best + p / q
            const double r = (best - second) * (fBest - fThird);
            double q = (best - third) * (fBest - fSecond);
            double p = (best - third) * q - (best - second) * r;
            q = 2 * (q - r);
            if (q > 0) p = -p;
            q = std::abs(q);
            const double limit = stepBefore;
            stepBefore = step;
            if (std::abs(p) < std::abs(0.5 * q * limit) && p > q * (low - best) &&
                p < q * (high - best)) {
                step = p / q;
                parabolic = true;
                const double next = best + step;
                // not within `within` of the bracket's ends
                if (next - low < within || high - next < within)
                    step = middle > best ? 0.5 * within : -0.5 * within;
            }
        }
        if (!parabolic) {
            stepBefore = best >= middle ? low - best : high - best;
            step = goldenStep * stepBefore;
        }
        const double next = std::abs(step) >= 0.5 * within
                                ? best + step
                                : best + (step > 0 ? 0.5 * within : -0.5 * within);
        const double fNext = distance2(next);
        if (fNext <= fBest) {
            (next >= best ? low : high) = best;
            third = second, fThird = fSecond;
            second = best, fSecond = fBest;
            best = next, fBest = fNext;
        } else {
            (next < best ? low : high) = next;
            if (fNext <= fSecond || second == best) {
                third = second, fThird = fSecond;
                second = next, fSecond = fNext;
            } else if (fNext <= fThird || third == best || third == second) {
                third = next, fThird = fNext;
            }
        }
    }
    if (sampled[nearest] <= fBest) return parameters[nearest];
    return best;
}

}  // namespace nurbslod
