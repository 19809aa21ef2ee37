#include "lod/CollapsedPoleRows.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace nurbslod::gui {

namespace {

// Parameter distance, relative to the domain, under which a trimming curve lies on a
// boundary iso-line (an importer's pcurve ends within rounding of the knot, 3e-7 on trj7).
constexpr double onBoundary = 1e-5;

// The boundary row of the surface a degenerated edge runs along: 0 u = first, 1 u = last,
// 2 v = first, 3 v = last; -1 if none.
int boundaryRowOf(const BSplineSurface& surface, const TrimCurve& curve) {
    const std::array<double, 2> low = {surface.knotsU().first(), surface.knotsV().first()};
    const std::array<double, 2> high = {surface.knotsU().last(), surface.knotsV().last()};
    const double middle = 0.5 * (curve.first + curve.last);
    const std::array<Point2, 3> points = {curve.pcurve.point(curve.first),
                                          curve.pcurve.point(middle),
                                          curve.pcurve.point(curve.last)};
    for (int axis = 0; axis < 2; ++axis) {
        const double range = high[axis] - low[axis];
        for (int end = 0; end < 2; ++end) {
            const double at = end == 0 ? low[axis] : high[axis];
            const bool along = std::all_of(points.begin(), points.end(), [&](const Point2& p) {
                return std::abs(p[axis] - at) <= onBoundary * range;
            });
            if (along) return 2 * axis + end;
        }
    }
    return -1;
}

// Under this spread, relative to the control net's size, a row is a pole already: rounding
// (1e-11 of the net on trj7's true poles), far below where BSplineSurface::normal takes the
// limit normal (derivatives 1e-8 apart).
constexpr double alreadyCollapsed = 1e-9;

double controlNetSize(const BSplineSurface& surface) {
    const auto [low, high] = surface.controlNetBox();
    return (high - low).norm();
}

// Collapses the row onto the mean of its points when every point lies within `tolerance` of
// it; whether it changed the surface (a row that is a pole already is left as it is).
bool collapseRow(BSplineSurface& surface, int row, double tolerance) {
    const bool alongV = row < 2;  // u fixed: the row runs along v
    const int count = alongV ? surface.countV() : surface.countU();
    const int fixed = row % 2 == 0 ? 0 : (alongV ? surface.countU() : surface.countV()) - 1;
    auto pole = [&](int k) -> HomogeneousPoint3& {
        return alongV ? surface.pole(fixed, k) : surface.pole(k, fixed);
    };
    Point3 mean = Point3::Zero();
    for (int k = 0; k < count; ++k) mean += projectHomogeneous(pole(k));
    mean /= count;
    double spread = 0;
    for (int k = 0; k < count; ++k)
        spread = std::max(spread, (projectHomogeneous(pole(k)) - mean).norm());
    if (!(spread <= tolerance) || spread <= alreadyCollapsed * controlNetSize(surface))
        return false;
    for (int k = 0; k < count; ++k) {
        const double weight = pole(k)[3];
        pole(k) << weight * mean, weight;
    }
    return true;
}

}  // namespace

TrimmedSurface withPoleRowsCollapsed(const Model& model, const TrimmedSurface& face,
                                     int* collapsed) {
    TrimmedSurface result = face;
    int rows = 0;
    if (face.surface.problem()) {  // the tessellator names the problem
        if (collapsed) *collapsed = 0;
        return result;
    }
    for (const TrimLoop& loop : face.loops) {
        for (const TrimCurve& curve : loop.curves) {
            if (!curve.degenerated || curve.edge < 0 ||
                curve.edge >= static_cast<int>(model.edges.size()))
                continue;
            const ModelEdge& edge = model.edges[static_cast<std::size_t>(curve.edge)];
            // the point the edge stands for: its vertex's tolerance, or the edge's own
            double tolerance = edge.tolerance;
            for (int vertex : {edge.firstVertex, edge.lastVertex})
                if (vertex >= 0 && vertex < static_cast<int>(model.vertices.size()))
                    tolerance = std::max(
                        tolerance, model.vertices[static_cast<std::size_t>(vertex)].tolerance);
            const int row = boundaryRowOf(result.surface, curve);
            if (row >= 0 && collapseRow(result.surface, row, tolerance)) ++rows;
        }
    }
    if (collapsed) *collapsed = rows;
    return result;
}

}  // namespace nurbslod::gui
