#include "lod/InterpolatedNormalError.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>
#include <vector>

namespace nurbslod::gui {

namespace {

// The angle between two vectors, radians: atan2 of |cross| and dot is accurate for the small
// angles measured here, where acos is not.
double angleBetween(const Vector3& a, const Vector3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Whether the surface closes on itself across its u (direction 0) or v (1) domain: the
// tessellator gives a vertex on the seam one (u, v), on one side, so a triangle beside the
// seam may have corners a whole period apart in parameter space though close in space.
bool closesIn(const BSplineSurface& surface, int direction) {
    const KnotVector& along = direction == 0 ? surface.knotsU() : surface.knotsV();
    const KnotVector& across = direction == 0 ? surface.knotsV() : surface.knotsU();
    auto at = [&](double a, double b) {
        return direction == 0 ? surface.point(a, b) : surface.point(b, a);
    };
    double size = 0, gap = 0;
    for (double t : {0.1, 0.5, 0.9}) {
        const double b = across.first() + t * (across.last() - across.first());
        const Point3 first = at(along.first(), b);
        gap = std::max(gap, (at(along.last(), b) - first).norm());
        size = std::max(size, (at(0.5 * (along.first() + along.last()), b) - first).norm());
    }
    return size > 0 && gap <= 1e-7 * size;
}

}  // namespace

InterpolatedNormalSampler::InterpolatedNormalSampler(const Mesh& mesh, const TrimmedSurface& face)
    : mesh_(mesh), face_(face) {
    const BSplineSurface& surface = face.surface;
    outwards_ = face.reversed ? -1.0 : 1.0;
    low_ = {surface.knotsU().first(), surface.knotsV().first()};
    period_ = {surface.knotsU().last() - low_[0], surface.knotsV().last() - low_[1]};
    closed_ = {closesIn(surface, 0), closesIn(surface, 1)};
    collapsed_.assign(mesh.normals.size(), -1);
}

// Whether the corner's vertex sits on a pole: 0 none, 1 the surface collapses along u there
// (its u says nothing about where a triangle leaves the pole), 2 along v.
int InterpolatedNormalSampler::collapsedAt(std::uint32_t normal) const {
    auto classify = [&] {
        const Point2& uv = mesh_.parameters[normal];
        const auto d = face_.surface.derivatives(uv.x(), uv.y());
        const double a = d.du.norm(), b = d.dv.norm();
        return a <= 1e-8 * b ? 1 : b <= 1e-8 * a ? 2 : 0;
    };
    // normals added after the sampler was made may be replaced: not remembered
    if (normal >= collapsed_.size()) return classify();
    signed char& known = collapsed_[normal];
    if (known < 0) known = static_cast<signed char>(classify());
    return known;
}

double InterpolatedNormalSampler::angle(std::size_t t, const std::array<double, 3>& weights,
                                        Point2* sampleParameter) const {
    const auto& corners = mesh_.triangleNormals[t];
    std::array<Point2, 3> uv;
    for (int k = 0; k < 3; ++k) uv[k] = mesh_.parameters[corners[k]];
    // Across a seam: the corners on the low side moved a period up, next to the others (a pole
    // corner's parameter is set below from the others).
    for (int axis = 0; axis < 2; ++axis) {
        if (!closed_[axis]) continue;
        double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
        for (int k = 0; k < 3; ++k) {
            if (collapsedAt(corners[k]) != 0) continue;
            lowest = std::min(lowest, uv[k][axis]);
            highest = std::max(highest, uv[k][axis]);
        }
        if (!(highest - lowest > 0.5 * period_[axis])) continue;
        for (Point2& corner : uv)
            if (corner[axis] < low_[axis] + 0.5 * period_[axis]) corner[axis] += period_[axis];
    }
    // A pole corner is a segment of parameter space: the triangle leaves it at the other
    // corners' collapsed parameter, so a sample takes their weighted mean there.
    for (int k = 0; k < 3; ++k) {
        const int axis = collapsedAt(corners[k]) - 1;
        if (axis < 0) continue;
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        const double rest = weights[a] + weights[b];
        if (rest > 0 && collapsedAt(corners[a]) == 0 && collapsedAt(corners[b]) == 0)
            uv[k][axis] = (weights[a] * uv[a][axis] + weights[b] * uv[b][axis]) / rest;
    }
    Point2 sample = weights[0] * uv[0] + weights[1] * uv[1] + weights[2] * uv[2];
    for (int axis = 0; axis < 2; ++axis)
        if (closed_[axis] && sample[axis] > low_[axis] + period_[axis])
            sample[axis] -= period_[axis];
    if (sampleParameter) *sampleParameter = sample;
    const Vector3 interpolated = weights[0] * mesh_.normals[corners[0]] +
                                 weights[1] * mesh_.normals[corners[1]] +
                                 weights[2] * mesh_.normals[corners[2]];
    return angleBetween(interpolated, outwards_ * face_.surface.normal(sample.x(), sample.y()));
}

double InterpolatedNormalSampler::triangleMaxDeg(std::size_t t, int steps) const {
    steps = std::max(steps, 2);
    double largest = angle(t, {1.0 / 3, 1.0 / 3, 1.0 / 3}, nullptr);
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            if (i == steps || j == steps || i + j == 0) continue;  // a corner
            const double a = double(i) / steps, b = double(j) / steps;
            largest = std::max(largest, angle(t, {a, b, 1 - a - b}, nullptr));
        }
    return largest * 180.0 / std::numbers::pi;
}

InterpolatedNormalError measureInterpolatedNormalError(const Mesh& mesh, const TrimmedSurface& face,
                                                       int steps) {
    InterpolatedNormalError error;
    if (mesh.parameters.size() != mesh.normals.size()) return error;
    steps = std::max(steps, 2);
    const InterpolatedNormalSampler sampler(mesh, face);
    double largest = 0;
    auto sampleAngle = [&](std::size_t t, const std::array<double, 3>& weights) {
        Point2 sample;
        const double angle = sampler.angle(t, weights, &sample);
        if (angle > largest) {
            largest = angle;
            error.worstTriangle = t;
            error.worstParameter = sample;
        }
    };
    // The points of an edge are shared by its two triangles: measured once, by its corners'
    // normal indices (which carry the (u, v)).
    std::unordered_set<std::uint64_t> measuredEdges;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& corners = mesh.triangles[t];
        const Vector3 ab = mesh.positions[corners[1]] - mesh.positions[corners[0]];
        const Vector3 ac = mesh.positions[corners[2]] - mesh.positions[corners[0]];
        const double longest =
            std::max({ab.squaredNorm(), ac.squaredNorm(), (ac - ab).squaredNorm()});
        // no area, relative to the triangle's size: it covers no pixel
        if (!(ab.cross(ac).norm() > 1e-12 * longest)) continue;
        ++error.triangles;
        sampleAngle(t, {1.0 / 3, 1.0 / 3, 1.0 / 3});
        const auto& normals = mesh.triangleNormals[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = normals[k], b = normals[(k + 1) % 3];
            if (!measuredEdges.insert((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b))
                     .second)
                continue;
            for (int step = 1; step < steps; ++step) {
                std::array<double, 3> weights = {0, 0, 0};
                weights[k] = 1 - double(step) / steps;
                weights[(k + 1) % 3] = double(step) / steps;
                sampleAngle(t, weights);
            }
        }
        for (int i = 1; i < steps; ++i)
            for (int j = 1; i + j < steps; ++j) {
                const double a = double(i) / steps, b = double(j) / steps;
                sampleAngle(t, {a, b, 1 - a - b});
            }
    }
    error.maxDeg = largest * 180.0 / std::numbers::pi;
    return error;
}

}  // namespace nurbslod::gui
