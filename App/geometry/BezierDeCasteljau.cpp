#include "geometry/BezierDeCasteljau.hpp"

#include "geometry/BasisFunctions.hpp"
#include "geometry/BezierGridLookup.hpp"
#include "geometry/DeCasteljauReduce.hpp"

namespace nurbslod {

BezierDeCasteljau::BezierDeCasteljau(const BSplineSurface& surface)
    : surface_(surface.validated()), patches_(surface) {}

void BezierDeCasteljau::evaluate(std::span<const double> us, std::span<const double> vs,
                                 Point3* points, Vector3* normals) const {
    const BezierGridLookup lu = BezierGridLookup::alongU(patches_, us);
    const BezierGridLookup lv = BezierGridLookup::alongV(patches_, vs);
    const int pu = surface_.degreeU(), pv = surface_.degreeV();
    HomogeneousPoint3 row[kMaxDegree + 1], C[kMaxDegree + 1], D[kMaxDegree + 1];
    for (size_t i = 0; i < us.size(); ++i) {
        const double s = lu.local[i], cs = lu.complement[i];
        for (size_t j = 0; j < vs.size(); ++j) {
            const double t = lv.local[j], ct = lv.complement[j];
            const BezierPatch& patch = patches_.patch(lu.patch[i], lv.patch[j]);
            for (int k = 0; k <= pu; ++k) {
                for (int l = 0; l <= pv; ++l) row[l] = patch.pole(k, l);
                if (normals) {
                    deCasteljauReduce(row, pv, pv - 1, t, ct);
                    C[k] = ct * row[0] + t * row[1];
                    D[k] = pv * lv.scale[j] * (row[1] - row[0]);
                } else {
                    deCasteljauReduce(row, pv, pv, t, ct);
                    C[k] = row[0];
                }
            }
            const size_t index = i * vs.size() + j;
            if (!normals) {
                deCasteljauReduce(C, pu, pu, s, cs);
                points[index] = projectHomogeneous(C[0]);
                continue;
            }
            deCasteljauReduce(C, pu, pu - 1, s, cs);
            deCasteljauReduce(D, pu, pu, s, cs);
            const HomogeneousPoint3 S = cs * C[0] + s * C[1];
            const HomogeneousPoint3 Su = pu * lu.scale[i] * (C[1] - C[0]);
            finishVertex(S, Su, D[0], surface_, lu.parameter[i], lv.parameter[j], points[index],
                         &normals[index]);
        }
    }
}

}  // namespace nurbslod
