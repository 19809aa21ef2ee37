#pragma once

#include <vector>

#include "geometry/BezierPatchGrid.hpp"
#include "geometry/SurfaceEvaluationMethod.hpp"

namespace nurbslod {

// Horner's scheme on the power basis (Sederberg 1995; evaluation paper, section 2.2): each
// Bezier patch is converted once to coefficients c_kl of s^k t^l (homogeneous), and each vertex
// is evaluated by nested multiplication along v for every k (value and derivative), then along
// u. Unlike the paper, s and t are measured from the middle of the patch (local parameter
// minus 1/2): the conversion about 0 is numerically unstable at high degree (Farouki 1991) and
// misses 1e-9 at degree 15, about the middle it does not; the operation count is the same.
class HornerPowerBasis final : public SurfaceEvaluationMethod {
public:
    explicit HornerPowerBasis(const BSplineSurface& surface);
    std::string name() const override { return "Horner power basis"; }
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals) const override;

private:
    BSplineSurface surface_;
    BezierPatchGrid patches_;
    // per patch (row-major over the patch grid), (pu + 1) * (pv + 1) coefficients
    std::vector<HomogeneousPoint3> coefficients_;
};

}  // namespace nurbslod
