#pragma once

#include <span>
#include <string>

#include "geometry/BSplineSurface.hpp"
#include "geometry/Point.hpp"
#include "geometry/SurfaceNormal.hpp"

namespace nurbslod {

// One way of evaluating a surface on a parameter grid us x vs (the evaluation paper's methods,
// section 2.2): vertex (i, j) is written at index i * vs.size() + j, its exact unit normal too
// when `normals` is not null. Parameters outside the domain are clamped to it; non-finite ones
// throw std::invalid_argument.
class SurfaceEvaluationMethod {
public:
    virtual ~SurfaceEvaluationMethod() = default;
    virtual std::string name() const = 0;
    virtual void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                          Vector3* normals) const = 0;
};

// The vertex from the homogeneous point S and its homogeneous partial derivatives Su, Sv: the
// point S/w and the normal along (w Su - w_u S) x (w Sv - w_v S), w^4 times du x dv by the
// quotient rule (NURBS Book, equation 4.19); the pole-safe rule of SurfaceNormal.hpp applies.
inline void finishVertex(const HomogeneousPoint3& S, const HomogeneousPoint3& Su,
                         const HomogeneousPoint3& Sv, const BSplineSurface& surface, double u,
                         double v, Point3& point, Vector3* normal) {
    const double w = S[3];
    point = S.head<3>() * (1.0 / w);
    if (!normal) return;
    const Vector3 du = w * Su.head<3>() - Su[3] * S.head<3>();
    const Vector3 dv = w * Sv.head<3>() - Sv[3] * S.head<3>();
    *normal = unitNormal(du, dv, surface, u, v);
}

}  // namespace nurbslod
