#include "tessellate/FlatFace.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "tessellate/RingTriangulation.hpp"

namespace nurbslod {

std::optional<FacePlane> facePlane(const BSplineSurface& surface, double flatness) {
    const auto& poles = surface.poles();
    if (poles.size() < 3 || !(flatness >= 0)) return std::nullopt;
    std::vector<Point3> points;
    points.reserve(poles.size());
    for (const HomogeneousPoint3& pole : poles) {
        if (!(pole.w() > 0) || !pole.allFinite()) return std::nullopt;
        points.push_back(pole.head<3>() / pole.w());
    }
    Point3 centre = Point3::Zero();
    for (const Point3& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Point3& p : points) scatter += (p - centre) * (p - centre).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    if (solver.info() != Eigen::Success) return std::nullopt;
    Vector3 normal = solver.eigenvectors().col(0);  // the least spread
    for (const Point3& p : points)
        if (!(std::abs((p - centre).dot(normal)) <= flatness)) return std::nullopt;
    // oriented along du x dv, taken where it is longest of a few points of the domain
    const auto& knotsU = surface.knotsU();
    const auto& knotsV = surface.knotsV();
    const double u0 = knotsU.first(), u1 = knotsU.last(), v0 = knotsV.first(), v1 = knotsV.last();
    Vector3 along = Vector3::Zero();
    for (const double s : {0.5, 0.25, 0.75})
        for (const double t : {0.5, 0.25, 0.75}) {
            const auto d = surface.derivatives(u0 + s * (u1 - u0), v0 + t * (v1 - v0));
            const Vector3 cross = d.du.cross(d.dv);
            if (cross.norm() > along.norm()) along = cross;
        }
    const double side = along.dot(normal);
    if (!(std::abs(side) > 1e-9 * along.norm()) || !(along.norm() > 0)) return std::nullopt;
    if (side < 0) normal = -normal;
    FacePlane plane;
    plane.origin = centre;
    plane.e1 = solver.eigenvectors().col(2).normalized();
    plane.e2 = normal.cross(plane.e1).normalized();
    return plane;
}

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateInPlane(
    const FacePlane& plane, const std::vector<std::vector<Point3>>& rings) {
    std::vector<std::vector<Point2>> inPlane;
    for (const auto& ring : rings) {
        inPlane.emplace_back();
        for (const Point3& p : ring) {
            const Vector3 d = p - plane.origin;
            inPlane.back().push_back({d.dot(plane.e1), d.dot(plane.e2)});
        }
    }
    return triangulateRings(inPlane);
}

}  // namespace nurbslod
