#include "tessellate/SurfaceProjection.hpp"

#include <algorithm>
#include <cmath>

namespace nurbslod {

SurfaceFoot projectOntoSurface(const BSplineSurface& surface, const Point3& target, Point2 start) {
    const double u0 = surface.knotsU().first(), u1 = surface.knotsU().last();
    const double v0 = surface.knotsV().first(), v1 = surface.knotsV().last();
    Point2 uv(std::clamp(start.x(), u0, u1), std::clamp(start.y(), v0, v1));
    SurfaceFoot best{uv, surface.point(uv.x(), uv.y())};
    double bestDistance = (best.point - target).norm();
    for (int iteration = 0; iteration < 20; ++iteration) {
        const auto d = surface.derivatives(uv.x(), uv.y());
        const Vector3 r = target - d.point;
        const double a = d.du.dot(d.du), b = d.du.dot(d.dv), c = d.dv.dot(d.dv);
        const double determinant = a * c - b * b;
        if (!(determinant > 1e-300)) break;
        const double ru = d.du.dot(r), rv = d.dv.dot(r);
        const Point2 next(std::clamp(uv.x() + (c * ru - b * rv) / determinant, u0, u1),
                          std::clamp(uv.y() + (a * rv - b * ru) / determinant, v0, v1));
        if (!next.allFinite()) break;
        const Point3 p = surface.point(next.x(), next.y());
        const double distance = (p - target).norm();
        if (!(distance < bestDistance)) break;  // no longer getting closer
        const bool converged = (next - uv).norm() <= 1e-14 * (1 + uv.norm());
        uv = next;
        best = {uv, p};
        bestDistance = distance;
        if (converged) break;
    }
    return best;
}

}  // namespace nurbslod
