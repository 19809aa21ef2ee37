#pragma once

#include "geometry/SurfaceEvaluationMethod.hpp"

namespace nurbslod {

// Two-stage Cox-de Boor evaluation (Luken and Cheng; evaluation paper, section 2.2): the first
// stage computes the basis functions and derivatives of every distinct u and v and stores them,
// the second evaluates the full tensor product sum_k sum_l N_k(u) N_l(v) P_kl at each
// parametric pair, without sharing partial sums between vertices.
class CoxDeBoorTwoStage final : public SurfaceEvaluationMethod {
public:
    explicit CoxDeBoorTwoStage(const BSplineSurface& surface);
    std::string name() const override { return "two-stage Cox-de Boor"; }
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals) const override;

private:
    BSplineSurface surface_;
};

}  // namespace nurbslod
