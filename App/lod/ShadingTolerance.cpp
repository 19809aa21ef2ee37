#include "lod/ShadingTolerance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/SurfaceCurvature.hpp"

namespace nurbslod::gui {

namespace {

// Samples per Bezier span and direction, and the most per direction: curvature is a rational
// function of low degree within a span, so a few samples per span follow it; a face of many
// spans is sampled uniformly instead, which bounds the cost (at most 48 x 48 evaluations).
constexpr int samplesPerSpan = 4;
constexpr int mostSamples = 48;

// The parameters to sample in [low, high]: every span of `knots` inside split in
// samplesPerSpan, or uniform when that would be too many.
std::vector<double> sampleParameters(const KnotVector& knots, double low, double high) {
    std::vector<double> breaks{low};
    for (double knot : knots.breakpoints())
        if (knot > low && knot < high) breaks.push_back(knot);
    breaks.push_back(high);
    std::vector<double> samples;
    const std::size_t spans = breaks.size() - 1;
    if (spans * samplesPerSpan + 1 > static_cast<std::size_t>(mostSamples)) {
        for (int k = 0; k < mostSamples; ++k)
            samples.push_back(low + (high - low) * k / (mostSamples - 1));
        return samples;
    }
    for (std::size_t s = 0; s < spans; ++s)
        for (int k = 0; k < samplesPerSpan; ++k)
            samples.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * k / samplesPerSpan);
    samples.push_back(high);
    return samples;
}

}  // namespace

double maximumCurvature(const TrimmedSurface& face) {
    const BSplineSurface& surface = face.surface;
    double u0 = surface.knotsU().first(), u1 = surface.knotsU().last();
    double v0 = surface.knotsV().first(), v1 = surface.knotsV().last();
    // The loops' box in (u, v): a pcurve lies in the convex hull of its poles (weights > 0),
    // so the poles' box holds the trimmed domain. Sampling the surface outside the face only
    // overestimates the curvature: a finer level, never a larger normal error.
    double lowU = std::numeric_limits<double>::infinity(), highU = -lowU;
    double lowV = lowU, highV = -lowU;
    for (const TrimLoop& loop : face.loops) {
        for (const TrimCurve& curve : loop.curves) {
            for (const HomogeneousPoint2& pole : curve.pcurve.poles()) {
                if (!(pole.z() > 0)) continue;
                const double u = pole.x() / pole.z(), v = pole.y() / pole.z();
                if (!(std::isfinite(u) && std::isfinite(v))) continue;
                lowU = std::min(lowU, u), highU = std::max(highU, u);
                lowV = std::min(lowV, v), highV = std::max(highV, v);
            }
        }
    }
    if (lowU <= highU && lowV <= highV) {
        u0 = std::clamp(lowU, u0, u1), u1 = std::clamp(highU, u0, u1);
        v0 = std::clamp(lowV, v0, v1), v1 = std::clamp(highV, v0, v1);
    }
    double maximum = 0;
    bool anyFinite = false;
    for (double u : sampleParameters(surface.knotsU(), u0, u1)) {
        for (double v : sampleParameters(surface.knotsV(), v0, v1)) {
            const SurfaceCurvature curvature = displayCurvature(surface, u, v);
            const double largest =
                std::max(std::abs(curvature.minimum), std::abs(curvature.maximum));
            if (!std::isfinite(largest)) continue;
            anyFinite = true;
            maximum = std::max(maximum, largest);
        }
    }
    if (!anyFinite)
        throw std::invalid_argument("face " + std::to_string(face.faceIndex) +
                                    ": the surface's curvature is not finite anywhere");
    return maximum;
}

double shadingTolerance(double normalErrorRadians, double curvature) {
    if (!(normalErrorRadians >= 0 && normalErrorRadians < std::numbers::pi / 2))
        throw std::invalid_argument("the normal error bound must be in [0, 90) degrees");
    if (!(curvature >= 0 && std::isfinite(curvature)))
        throw std::invalid_argument("the curvature must be finite and >= 0");
    if (normalErrorRadians == 0 || curvature == 0) return std::numeric_limits<double>::infinity();
    // Section 4.1 takes the surface locally as bent with the maximum curvature kappa in the
    // direction where the normal deviates most: a normal section there is a circle of radius
    // 1 / kappa. A chord of that circle whose ends are both on it, seen from the centre under
    // 2 alpha, lies (1 - cos alpha) / kappa from the arc at its middle (the sagitta), and its
    // normal differs by alpha from the exact normals at its ends. A chord within
    //     (1 - cos theta) / kappa
    // of the surface therefore turns the normal by at most theta; in any other direction
    // the curvature is smaller and so is the angle. Where the paper adds the shading error
    // to the geometric one, eps^2 = eps_geometric^2 + eps_shading^2 with eps_shading ~
    // |n - n_bilin| / max(c_u, c_v), this bound is an angle the user chose, independent of
    // the view, so the face takes the smaller of the two tolerances instead.
    return (1 - std::cos(normalErrorRadians)) / curvature;
}

}  // namespace nurbslod::gui
