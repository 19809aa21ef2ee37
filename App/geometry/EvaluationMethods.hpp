#pragma once

#include <memory>
#include <vector>

#include "geometry/GridEvaluator.hpp"
#include "geometry/SurfaceEvaluationMethod.hpp"

namespace nurbslod {

// The optimized direct evaluation with coherence between vertices (NURBS Book; evaluation
// paper, section 2.2) is GridEvaluator's scalar path on one thread; with `vectorised` it is
// GridEvaluator with AVX2+FMA where the CPU has it (beyond the paper).
class CoherentDirectEvaluation final : public SurfaceEvaluationMethod {
public:
    CoherentDirectEvaluation(const BSplineSurface& surface, bool vectorised);
    std::string name() const override;
    void evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                  Vector3* normals) const override;

private:
    GridEvaluator evaluator_;
};

// The evaluation paper's five methods on one surface, in the paper's order (two-stage
// Cox-de Boor, optimized direct with coherence, de Casteljau, modified de Casteljau, Horner),
// followed by the vectorised grid evaluator. Throws std::invalid_argument for a surface that
// cannot be evaluated.
std::vector<std::unique_ptr<SurfaceEvaluationMethod>> makeEvaluationMethods(
    const BSplineSurface& surface);

}  // namespace nurbslod
