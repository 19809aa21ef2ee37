#include "geometry/HornerPowerBasis.hpp"

#include "geometry/BasisFunctions.hpp"
#include "geometry/BezierGridLookup.hpp"

namespace nurbslod {

namespace {

// Bezier control points pts[0], pts[stride], ... of a degree-n curve to its Taylor
// coefficients about the middle of the segment, c_k = f^(k)(1/2) / k! =
// C(n, k) sum_i B^(n-k)_i(1/2) Delta^k P_i: the power basis in (t - 1/2). About 0 instead, the
// alternating sums of the conversion lose about 3^n ulps (Farouki 1991), 1e-8 at degree 15;
// about the middle the loss is about C(n, k) ulps and |t - 1/2|^k <= 2^-k damps it.
void toPowerBasis(HomogeneousPoint3* pts, int degree, int stride) {
    HomogeneousPoint3 difference[kMaxDegree + 1], level[kMaxDegree + 1], c[kMaxDegree + 1];
    for (int i = 0; i <= degree; ++i) difference[i] = pts[i * stride];
    for (int k = 0; k <= degree; ++k) {
        // difference[0..n-k] holds Delta^k P; its Bezier polynomial of degree n-k at 1/2
        for (int i = 0; i <= degree - k; ++i) level[i] = difference[i];
        for (int r = 1; r <= degree - k; ++r)
            for (int i = 0; i <= degree - k - r; ++i) level[i] = 0.5 * (level[i] + level[i + 1]);
        c[k] = binomial(degree, k) * level[0];
        for (int i = 0; i < degree - k; ++i) difference[i] = difference[i + 1] - difference[i];
    }
    for (int k = 0; k <= degree; ++k) pts[k * stride] = c[k];
}

}  // namespace

HornerPowerBasis::HornerPowerBasis(const BSplineSurface& surface)
    : surface_(surface.validated()), patches_(surface) {
    const int pu = surface_.degreeU(), pv = surface_.degreeV();
    for (int a = 0; a < patches_.spansU(); ++a)
        for (int b = 0; b < patches_.spansV(); ++b) {
            const size_t first = coefficients_.size();
            const BezierPatch& patch = patches_.patch(a, b);
            for (int k = 0; k <= pu; ++k)
                for (int l = 0; l <= pv; ++l) coefficients_.push_back(patch.pole(k, l));
            HomogeneousPoint3* c = &coefficients_[first];
            for (int k = 0; k <= pu; ++k) toPowerBasis(c + k * (pv + 1), pv, 1);
            for (int l = 0; l <= pv; ++l) toPowerBasis(c + l, pu, pv + 1);
        }
}

void HornerPowerBasis::evaluate(std::span<const double> us, std::span<const double> vs,
                                Point3* points, Vector3* normals) const {
    const BezierGridLookup lu = BezierGridLookup::alongU(patches_, us);
    const BezierGridLookup lv = BezierGridLookup::alongV(patches_, vs);
    const int pu = surface_.degreeU(), pv = surface_.degreeV();
    const size_t perPatch = static_cast<size_t>(pu + 1) * (pv + 1);
    HomogeneousPoint3 R[kMaxDegree + 1], Rt[kMaxDegree + 1];
    for (size_t i = 0; i < us.size(); ++i) {
        const double s = lu.local[i] - 0.5;
        for (size_t j = 0; j < vs.size(); ++j) {
            const double t = lv.local[j] - 0.5;
            const HomogeneousPoint3* c =
                &coefficients_[(lu.patch[i] * patches_.spansV() + lv.patch[j]) * perPatch];
            // along v: R_k(t) = sum_l c_kl t^l and its derivative, by nested multiplication
            for (int k = 0; k <= pu; ++k) {
                const HomogeneousPoint3* ck = c + k * (pv + 1);
                HomogeneousPoint3 value = ck[pv], derivative = HomogeneousPoint3::Zero();
                for (int l = pv - 1; l >= 0; --l) {
                    if (normals) derivative = derivative * t + value;
                    value = value * t + ck[l];
                }
                R[k] = value;
                Rt[k] = derivative;
            }
            // along u
            HomogeneousPoint3 S = R[pu], Su = HomogeneousPoint3::Zero(), Sv = Rt[pu];
            for (int k = pu - 1; k >= 0; --k) {
                if (normals) {
                    Su = Su * s + S;
                    Sv = Sv * s + Rt[k];
                }
                S = S * s + R[k];
            }
            const size_t index = i * vs.size() + j;
            if (!normals) {
                points[index] = projectHomogeneous(S);
                continue;
            }
            finishVertex(S, lu.scale[i] * Su, lv.scale[j] * Sv, surface_, lu.parameter[i],
                         lv.parameter[j], points[index], &normals[index]);
        }
    }
}

}  // namespace nurbslod
