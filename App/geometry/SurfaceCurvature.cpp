#include "geometry/SurfaceCurvature.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/BasisFunctions.hpp"

namespace nurbslod {

namespace {

// Up to two derivatives of the non-zero basis functions at t in `span`: derivatives[k][r] is
// the k-th derivative of N_{span-degree+r} (NURBS Book, algorithm A2.3 with n = 2). A knot
// difference of zero contributes nothing, as in basisFunctions, instead of dividing by zero.
void basisFunctionSecondDerivatives(const KnotVector& knots, int span, double t,
                                    double (*derivatives)[kMaxDegree + 1]) {
    const int p = knots.degree();
    const int order = std::min(2, p);
    double ndu[kMaxDegree + 1][kMaxDegree + 1];
    auto divide = [](double numerator, double denominator) {
        return denominator != 0.0 ? numerator / denominator : 0.0;
    };
    basisFunctionTable(knots, span, t, ndu);
    for (int k = 0; k <= 2; ++k)
        for (int r = 0; r <= p; ++r) derivatives[k][r] = k == 0 ? ndu[r][p] : 0.0;
    for (int r = 0; r <= p; ++r) {
        double a[2][3] = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        int s1 = 0, s2 = 1;
        for (int k = 1; k <= order; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                a[s2][0] = divide(a[s1][0], ndu[pk + 1][rk]);
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = r - 1 <= pk ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = divide(a[s1][j] - a[s1][j - 1], ndu[pk + 1][rk + j]);
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = divide(-a[s1][k - 1], ndu[pk + 1][r]);
                d += a[s2][k] * ndu[r][pk];
            }
            derivatives[k][r] = d;
            std::swap(s1, s2);
        }
    }
    double factor = p;  // p!/(p-k)!
    for (int k = 1; k <= order; ++k) {
        for (int r = 0; r <= p; ++r) derivatives[k][r] *= factor;
        factor *= p - k;
    }
}

// |du x dv| relative to |du| |dv| below which the normal is noise (as in BSplineSurface).
bool isRegular(const SurfaceSecondDerivatives& d) {
    const double a = d.du.norm(), b = d.dv.norm();
    return a > 1e-8 * b && b > 1e-8 * a && d.du.cross(d.dv).norm() > 1e-10 * a * b;
}

}  // namespace

SurfaceSecondDerivatives secondDerivatives(const BSplineSurface& surface, double u, double v) {
    const KnotVector& knotsU = surface.knotsU();
    const KnotVector& knotsV = surface.knotsV();
    u = std::clamp(u, knotsU.first(), knotsU.last());
    v = std::clamp(v, knotsV.first(), knotsV.last());
    const int pu = knotsU.degree(), pv = knotsV.degree();
    const int su = knotsU.findSpan(u), sv = knotsV.findSpan(v);
    double Nu[3][kMaxDegree + 1], Nv[3][kMaxDegree + 1];
    basisFunctionSecondDerivatives(knotsU, su, u, Nu);
    basisFunctionSecondDerivatives(knotsV, sv, v, Nv);

    // homogeneous derivatives A_kl = d^(k+l) S^w / du^k dv^l for k + l <= 2
    HomogeneousPoint3 A[3][3];
    for (auto& row : A)
        for (auto& a : row) a.setZero();
    for (int k = 0; k <= pu; ++k) {
        HomogeneousPoint3 inner[3] = {HomogeneousPoint3::Zero(), HomogeneousPoint3::Zero(),
                                      HomogeneousPoint3::Zero()};
        for (int l = 0; l <= pv; ++l) {
            const HomogeneousPoint3& pole = surface.pole(su - pu + k, sv - pv + l);
            for (int j = 0; j <= 2; ++j) inner[j] += Nv[j][l] * pole;
        }
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; i + j <= 2; ++j) A[i][j] += Nu[i][k] * inner[j];
    }

    // quotient rule, S = A / w (NURBS Book, equation 4.20)
    const double w = A[0][0][3], wu = A[1][0][3], wv = A[0][1][3];
    const double wuu = A[2][0][3], wuv = A[1][1][3], wvv = A[0][2][3];
    SurfaceSecondDerivatives d;
    d.point = A[0][0].head<3>() / w;
    d.du = (A[1][0].head<3>() - wu * d.point) / w;
    d.dv = (A[0][1].head<3>() - wv * d.point) / w;
    d.duu = (A[2][0].head<3>() - 2 * wu * d.du - wuu * d.point) / w;
    d.dvv = (A[0][2].head<3>() - 2 * wv * d.dv - wvv * d.point) / w;
    d.duv = (A[1][1].head<3>() - wu * d.dv - wv * d.du - wuv * d.point) / w;
    return d;
}

std::optional<SurfaceCurvature> curvatureAt(const BSplineSurface& surface, double u, double v) {
    const SurfaceSecondDerivatives d = secondDerivatives(surface, u, v);
    if (!isRegular(d) || !d.point.allFinite()) return std::nullopt;
    SurfaceCurvature c;
    c.normal = d.du.cross(d.dv).normalized();
    // first (E, F, G) and second (L, M, N) fundamental forms
    const double E = d.du.dot(d.du), F = d.du.dot(d.dv), G = d.dv.dot(d.dv);
    const double L = d.duu.dot(c.normal), M = d.duv.dot(c.normal), N = d.dvv.dot(c.normal);
    const double area = E * G - F * F;
    if (!(area > 0)) return std::nullopt;
    // The shape operator in an orthonormal tangent frame (e1 along du, e2 = n x e1) is the
    // symmetric matrix [[a, b], [b, c]]. Its eigenvalues (a + c)/2 -+ sqrt(((a - c)/2)^2 + b^2)
    // have a discriminant that is a sum of squares: unlike H^2 - K it does not cancel at an
    // umbilic, where that would cost half the digits.
    const Vector3 e1 = d.du.normalized();
    const Vector3 e2 = c.normal.cross(e1);
    // (u, v) components of e1 and e2: I x = (du . e, dv . e)
    const Eigen::Matrix2d first{{E, F}, {F, G}};
    const Eigen::Matrix2d second{{L, M}, {M, N}};
    Eigen::Matrix2d frame;
    frame.col(0) = first.inverse() * Eigen::Vector2d(d.du.dot(e1), d.dv.dot(e1));
    frame.col(1) = first.inverse() * Eigen::Vector2d(d.du.dot(e2), d.dv.dot(e2));
    const Eigen::Matrix2d shape = frame.transpose() * second * frame;
    const double a = shape(0, 0), b = 0.5 * (shape(0, 1) + shape(1, 0)), cc = shape(1, 1);
    const double half = 0.5 * (a + cc);
    const double root = std::hypot(0.5 * (a - cc), b);
    c.minimum = half - root;
    c.maximum = half + root;
    c.mean = half;
    c.gaussian = c.minimum * c.maximum;
    // the maximum direction at angle theta from e1, tan(2 theta) = 2b / (a - c); at an umbilic
    // every direction is principal and atan2(0, 0) = 0 picks e1
    const double theta = 0.5 * std::atan2(2 * b, a - cc);
    c.maximumDirection = std::cos(theta) * e1 + std::sin(theta) * e2;
    c.minimumDirection = c.normal.cross(c.maximumDirection);
    return c;
}

SurfaceCurvature displayCurvature(const BSplineSurface& surface, double u, double v) {
    if (auto c = curvatureAt(surface, u, v)) return *c;
    const KnotVector& knotsU = surface.knotsU();
    const KnotVector& knotsV = surface.knotsV();
    const double um = 0.5 * (knotsU.first() + knotsU.last());
    const double vm = 0.5 * (knotsV.first() + knotsV.last());
    for (double step = 1e-6; step <= 0.5; step *= 4)
        if (auto c = curvatureAt(surface, u + step * (um - u), v + step * (vm - v))) return *c;
    SurfaceCurvature flat;
    flat.normal = Vector3(0, 0, 1);
    flat.minimumDirection = Vector3(1, 0, 0);
    flat.maximumDirection = Vector3(0, 1, 0);
    return flat;
}

}  // namespace nurbslod
