#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace nurbslod {

// Value types for points and vectors. Homogeneous points store (w*x, w*y, w*z, w), the form
// in which rational B-splines are linear in their control points (NURBS Book, section 4.2).
using Point2 = Eigen::Vector2d;
using Point3 = Eigen::Vector3d;
using Vector3 = Eigen::Vector3d;
using HomogeneousPoint2 = Eigen::Vector3d;
using HomogeneousPoint3 = Eigen::Vector4d;

inline Point3 projectHomogeneous(const HomogeneousPoint3& p) {
    return p.head<3>() / p[3];
}
inline Point2 projectHomogeneous(const HomogeneousPoint2& p) {
    return p.head<2>() / p[2];
}

}  // namespace nurbslod
