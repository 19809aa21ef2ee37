#include "geometry/CoxDeBoorTwoStage.hpp"

#include "geometry/GridBasis.hpp"

namespace nurbslod {

CoxDeBoorTwoStage::CoxDeBoorTwoStage(const BSplineSurface& surface)
    : surface_(surface.validated()) {}

void CoxDeBoorTwoStage::evaluate(std::span<const double> us, std::span<const double> vs,
                                 Point3* points, Vector3* normals) const {
    // stage 1: basis functions per distinct parameter
    const GridBasis bu = makeGridBasis(surface_.knotsU(), us, 'u');
    const GridBasis bv = makeGridBasis(surface_.knotsV(), vs, 'v');
    const int pu = surface_.degreeU(), pv = surface_.degreeV();
    // stage 2: the tensor product at each parametric pair
    for (size_t i = 0; i < us.size(); ++i) {
        const double* Nu = bu.valuesAt(i);
        const double* dNu = bu.derivativesAt(i);
        const int firstU = bu.span[i] - pu;
        for (size_t j = 0; j < vs.size(); ++j) {
            const double* Nv = bv.valuesAt(j);
            const double* dNv = bv.derivativesAt(j);
            const int firstV = bv.span[j] - pv;
            HomogeneousPoint3 S = HomogeneousPoint3::Zero(), Su = S, Sv = S;
            for (int k = 0; k <= pu; ++k)
                for (int l = 0; l <= pv; ++l) {
                    const HomogeneousPoint3& P = surface_.pole(firstU + k, firstV + l);
                    S += (Nu[k] * Nv[l]) * P;
                    if (normals) {
                        Su += (dNu[k] * Nv[l]) * P;
                        Sv += (Nu[k] * dNv[l]) * P;
                    }
                }
            const size_t index = i * vs.size() + j;
            finishVertex(S, Su, Sv, surface_, bu.parameter[i], bv.parameter[j], points[index],
                         normals ? &normals[index] : nullptr);
        }
    }
}

}  // namespace nurbslod
