#include "tessellate/SurfaceMeeting.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

#include "tessellate/SurfaceProjection.hpp"

namespace nurbslod {

SurfaceMeeting findSurfaceMeeting(const std::vector<const BSplineSurface*>& surfaces,
                                  const Point3& start, const std::vector<Point2>& starts,
                                  int iterations) {
    const auto count = static_cast<Eigen::Index>(surfaces.size());
    SurfaceMeeting best{start, starts, std::vector<Point3>(surfaces.size()), 0, 0};
    best.offset = std::numeric_limits<double>::infinity();
    Point3 point = start;
    std::vector<Point2> uv = starts;
    for (int iteration = 0; iteration <= iterations; ++iteration) {
        // the feet of the current point and their tangent planes n . (x - foot) = 0
        Eigen::MatrixXd normals(count, 3);
        Eigen::VectorXd heights(count);
        std::vector<Point3> feet(surfaces.size());
        double offset = 0;
        for (Eigen::Index s = 0; s < count; ++s) {
            const SurfaceFoot foot = projectOntoSurface(*surfaces[s], point, uv[s]);
            uv[s] = foot.uv;
            feet[s] = foot.point;
            offset = std::max(offset, (foot.point - point).norm());
            // pole-safe: where a derivative has collapsed, the limit from inside the domain
            const Vector3 normal = surfaces[s]->normal(foot.uv.x(), foot.uv.y());
            normals.row(s) = normal.transpose();
            heights(s) = normal.dot(foot.point - point);
        }
        if (offset < best.offset) best = {point, uv, feet, offset, 0};
        best.iterations = iteration + 1;
        if (iteration == iterations || !(offset > 0)) break;
        // the shortest step onto every plane; normals less than about half a degree apart (the
        // pivoted QR's relative threshold 1e-2 ~ sin 0.57 deg) count as one direction, so that
        // nearly parallel planes give the midway step, not a leap along them
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> planes(normals.rows(), 3);
        planes.setThreshold(1e-2);
        planes.compute(normals);
        const Eigen::Vector3d step = planes.solve(heights);
        // A step within rounding of the point leaves it where it is: the surfaces have met, or
        // the point sits midway between side-by-side surfaces (where the step is the same
        // least-squares one every time). Further iterations would only repeat the feet: on
        // trj7_b1-ec-214.stp most meetings stood still from their fifth iteration on.
        if (!step.allFinite() || step.norm() <= 1e-12 * (1 + point.norm())) break;
        point += Vector3(step);
    }
    return best;
}

}  // namespace nurbslod
