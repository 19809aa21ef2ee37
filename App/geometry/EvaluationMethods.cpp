#include "geometry/EvaluationMethods.hpp"

#include "geometry/BezierDeCasteljau.hpp"
#include "geometry/CoxDeBoorTwoStage.hpp"
#include "geometry/HornerPowerBasis.hpp"
#include "geometry/ModifiedDeCasteljau.hpp"

namespace nurbslod {

CoherentDirectEvaluation::CoherentDirectEvaluation(const BSplineSurface& surface, bool vectorised)
    : evaluator_(surface) {
    evaluator_.setInstructionSet(vectorised ? GridEvaluator::InstructionSet::Avx2
                                            : GridEvaluator::InstructionSet::Scalar);
}

std::string CoherentDirectEvaluation::name() const {
    return evaluator_.instructionSet() == GridEvaluator::InstructionSet::Avx2
               ? "grid evaluator AVX2"
               : "optimized direct (coherent)";
}

void CoherentDirectEvaluation::evaluate(std::span<const double> us, std::span<const double> vs,
                                        Point3* points, Vector3* normals) const {
    evaluator_.evaluate(us, vs, points, normals, 1);
}

std::vector<std::unique_ptr<SurfaceEvaluationMethod>> makeEvaluationMethods(
    const BSplineSurface& surface) {
    std::vector<std::unique_ptr<SurfaceEvaluationMethod>> methods;
    methods.push_back(std::make_unique<CoxDeBoorTwoStage>(surface));
    methods.push_back(std::make_unique<CoherentDirectEvaluation>(surface, false));
    methods.push_back(std::make_unique<BezierDeCasteljau>(surface));
    methods.push_back(std::make_unique<ModifiedDeCasteljau>(surface));
    methods.push_back(std::make_unique<HornerPowerBasis>(surface));
    methods.push_back(std::make_unique<CoherentDirectEvaluation>(surface, true));
    return methods;
}

}  // namespace nurbslod
