#pragma once

#include "geometry/BezierPatchGrid.hpp"
#include "geometry/SurfaceEvaluationMethod.hpp"

namespace nurbslod {

// The modified de Casteljau algorithm of Mann and DeRose (1995; evaluation paper, section 2.2):
// de Casteljau stops one level early in both directions, leaving a bilinear 2 x 2 patch whose
// value and edges give the point and both partial derivatives at once. It needs no equal
// degrees in u and v.
class ModifiedDeCasteljau final : public SurfaceEvaluationMethod {
public:
    explicit ModifiedDeCasteljau(const BSplineSurface& surface);
    std::string name() const override { return "modified de Casteljau"; }
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals) const override;

private:
    BSplineSurface surface_;
    BezierPatchGrid patches_;
};

}  // namespace nurbslod
