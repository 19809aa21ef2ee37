#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <optional>

#include "geometry/Point.hpp"

namespace nurbslod {

// The affine map of a triangle of surface parameters onto the flat triangle of its corners'
// positions: position = X0 + G (q - q0). A mesh triangle is this map's image, so its distance
// from the surface at the parameter q is |S(q) - map(q)|.
class TriangleAffineMap {
public:
    // None for a triangle without area in (u, v) (against its own extent).
    static std::optional<TriangleAffineMap> through(const std::array<Point2, 3>& uv,
                                                    const std::array<Point3, 3>& position) {
        Eigen::Matrix2d across;
        across << uv[1].x() - uv[0].x(), uv[2].x() - uv[0].x(), uv[1].y() - uv[0].y(),
            uv[2].y() - uv[0].y();
        const double determinant = across.determinant();
        const double scale = across.cwiseAbs().maxCoeff();
        if (!(std::abs(determinant) > 1e-12 * scale * scale)) return std::nullopt;
        Eigen::Matrix<double, 3, 2> differences;
        differences << position[1] - position[0], position[2] - position[0];
        TriangleAffineMap map;
        map.start_ = uv[0];
        map.origin_ = position[0];
        map.gradient_ = differences * across.inverse();
        map.doubleArea_ = std::abs(determinant);
        return map;
    }

    Point3 operator()(const Point2& q) const { return origin_ + gradient_ * (q - start_); }
    // twice the triangle's area in (u, v)
    double doubleArea() const { return doubleArea_; }

private:
    Point2 start_;
    Point3 origin_;
    Eigen::Matrix<double, 3, 2> gradient_;
    double doubleArea_ = 0;
};

}  // namespace nurbslod
