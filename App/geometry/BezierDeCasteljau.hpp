#pragma once

#include "geometry/BezierPatchGrid.hpp"
#include "geometry/SurfaceEvaluationMethod.hpp"

namespace nurbslod {

// de Casteljau on the Bezier patches of the surface (evaluation paper, section 2.2; de Casteljau
// 1986) with the weights of each parameter precomputed (Carriere 1995): per vertex, each row of
// the patch is reduced along v to a point and a v-derivative, then the column of points along u
// to the point and the u-derivative, and the column of v-derivatives to the v-derivative.
class BezierDeCasteljau final : public SurfaceEvaluationMethod {
public:
    explicit BezierDeCasteljau(const BSplineSurface& surface);
    std::string name() const override { return "de Casteljau"; }
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals) const override;

private:
    BSplineSurface surface_;
    BezierPatchGrid patches_;
};

}  // namespace nurbslod
