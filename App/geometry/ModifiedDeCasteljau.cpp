#include "geometry/ModifiedDeCasteljau.hpp"

#include "geometry/BasisFunctions.hpp"
#include "geometry/BezierGridLookup.hpp"
#include "geometry/DeCasteljauReduce.hpp"

namespace nurbslod {

ModifiedDeCasteljau::ModifiedDeCasteljau(const BSplineSurface& surface)
    : surface_(surface.validated()), patches_(surface) {}

void ModifiedDeCasteljau::evaluate(std::span<const double> us, std::span<const double> vs,
                                   Point3* points, Vector3* normals) const {
    const BezierGridLookup lu = BezierGridLookup::alongU(patches_, us);
    const BezierGridLookup lv = BezierGridLookup::alongV(patches_, vs);
    const int pu = surface_.degreeU(), pv = surface_.degreeV();
    HomogeneousPoint3 row[kMaxDegree + 1], A[kMaxDegree + 1], B[kMaxDegree + 1];
    for (size_t i = 0; i < us.size(); ++i) {
        const double s = lu.local[i], cs = lu.complement[i];
        for (size_t j = 0; j < vs.size(); ++j) {
            const double t = lv.local[j], ct = lv.complement[j];
            const BezierPatch& patch = patches_.patch(lu.patch[i], lv.patch[j]);
            // each row down to its last two points: columns A (left) and B (right)
            for (int k = 0; k <= pu; ++k) {
                for (int l = 0; l <= pv; ++l) row[l] = patch.pole(k, l);
                deCasteljauReduce(row, pv, pv - 1, t, ct);
                A[k] = row[0];
                B[k] = row[1];
            }
            // both columns down to two points: the bilinear patch a0 b0 / a1 b1
            deCasteljauReduce(A, pu, pu - 1, s, cs);
            deCasteljauReduce(B, pu, pu - 1, s, cs);
            const HomogeneousPoint3 S = cs * (ct * A[0] + t * B[0]) + s * (ct * A[1] + t * B[1]);
            const size_t index = i * vs.size() + j;
            if (!normals) {
                points[index] = projectHomogeneous(S);
                continue;
            }
            const HomogeneousPoint3 Su =
                pu * lu.scale[i] * (ct * (A[1] - A[0]) + t * (B[1] - B[0]));
            const HomogeneousPoint3 Sv =
                pv * lv.scale[j] * (cs * (B[0] - A[0]) + s * (B[1] - A[1]));
            finishVertex(S, Su, Sv, surface_, lu.parameter[i], lv.parameter[j], points[index],
                         &normals[index]);
        }
    }
}

}  // namespace nurbslod
