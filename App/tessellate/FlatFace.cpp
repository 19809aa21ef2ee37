#include "tessellate/FlatFace.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "tessellate/PolygonTriangulator.hpp"

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
    if (rings.empty()) return std::nullopt;
    double extent = 0;
    for (const auto& ring : rings)
        for (const Point3& p : ring) {
            if (!p.allFinite()) return std::nullopt;
            const Vector3 d = p - plane.origin;
            extent = std::max({extent, std::abs(d.dot(plane.e1)), std::abs(d.dot(plane.e2))});
        }
    if (!(extent > 0) || !std::isfinite(extent)) return std::nullopt;
    // 2^50 steps across the rings: far below any tolerance, and every cross product of two
    // coordinate differences stays exact in the triangulator's 128-bit arithmetic
    const double scale = std::ldexp(1.0, 50) / extent;
    std::vector<std::vector<IntegerPoint2>> integerRings;
    std::vector<double> areas;
    for (const auto& ring : rings) {
        std::vector<IntegerPoint2> integerRing;
        for (const Point3& p : ring) {
            const Vector3 d = p - plane.origin;
            integerRing.push_back(
                {std::llround(d.dot(plane.e1) * scale), std::llround(d.dot(plane.e2) * scale)});
        }
        double twiceArea = 0;
        for (std::size_t i = 0; i < integerRing.size(); ++i) {
            const auto& a = integerRing[i];
            const auto& b = integerRing[(i + 1) % integerRing.size()];
            twiceArea += double(a.x) * double(b.y) - double(b.x) * double(a.y);
        }
        areas.push_back(std::abs(twiceArea));
        integerRings.push_back(std::move(integerRing));
    }
    // the outer ring first, the rings' points keeping their indices in the concatenation
    const std::size_t outer =
        static_cast<std::size_t>(std::max_element(areas.begin(), areas.end()) - areas.begin());
    std::vector<std::size_t> order(rings.size());
    std::iota(order.begin(), order.end(), 0);
    std::swap(order[0], order[outer]);
    std::vector<std::uint32_t> firstIndex(rings.size(), 0);
    for (std::size_t r = 1; r < rings.size(); ++r)
        firstIndex[r] = firstIndex[r - 1] + static_cast<std::uint32_t>(rings[r - 1].size());
    std::vector<std::vector<IntegerPoint2>> ordered;
    std::vector<std::uint32_t> index;  // concatenation of `ordered` -> concatenation of `rings`
    for (const std::size_t r : order) {
        ordered.push_back(std::move(integerRings[r]));
        for (std::uint32_t i = 0; i < rings[r].size(); ++i) index.push_back(firstIndex[r] + i);
    }
    const Triangulation triangulation = triangulatePolygon(ordered);
    if (!triangulation.complete || triangulation.triangles.empty()) return std::nullopt;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const auto& t : triangulation.triangles)
        triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    return triangles;
}

}  // namespace nurbslod
