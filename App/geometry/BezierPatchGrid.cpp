#include "geometry/BezierPatchGrid.hpp"

#include <algorithm>

namespace nurbslod {

std::vector<HomogeneousPoint3> decomposeIntoBezierSegments(const KnotVector& knots,
                                                           const HomogeneousPoint3* pts,
                                                           int stride) {
    const int p = knots.degree();
    const auto& U = knots.knots();
    const int m = static_cast<int>(U.size()) - 1;
    const int segments = static_cast<int>(knots.breakpoints().size()) - 1;
    std::vector<HomogeneousPoint3> Q(static_cast<size_t>(std::max(segments, 1) * (p + 1)),
                                     HomogeneousPoint3::Zero());
    auto q = [&](int segment, int i) -> HomogeneousPoint3& { return Q[segment * (p + 1) + i]; };
    std::vector<double> alphas(p + 1);
    int a = p, b = p + 1, nb = 0;
    for (int i = 0; i <= p; ++i) q(0, i) = pts[i * stride];
    while (b < m && nb < segments) {
        const int i = b;
        while (b < m && U[b + 1] == U[b]) ++b;
        const int mult = b - i + 1;
        if (mult < p) {
            const double numer = U[b] - U[a];
            for (int j = p; j > mult; --j) alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
            const int r = p - mult;
            for (int j = 1; j <= r; ++j) {
                const int save = r - j, s = mult + j;
                for (int k = p; k >= s; --k) {
                    const double alpha = alphas[k - s];
                    q(nb, k) = alpha * q(nb, k) + (1.0 - alpha) * q(nb, k - 1);
                }
                if (b < m && nb + 1 < segments) q(nb + 1, save) = q(nb, p);
            }
        }
        ++nb;
        if (b < m && nb < segments) {
            for (int k = p - mult; k <= p; ++k) q(nb, k) = pts[(b - p + k) * stride];
            a = b;
            ++b;
        }
    }
    return Q;
}

BezierPatchGrid::BezierPatchGrid(const BSplineSurface& surface)
    : breaksU_(surface.knotsU().breakpoints()), breaksV_(surface.knotsV().breakpoints()) {
    const int pu = surface.degreeU(), pv = surface.degreeV();
    const int nu = spansU(), nv = spansV();
    const int cv = surface.countV();
    // along u for every column j: strips[segU][i][j] with i in 0..pu
    std::vector<HomogeneousPoint3> strips(static_cast<size_t>(nu * (pu + 1) * cv));
    for (int j = 0; j < cv; ++j) {
        auto segs = decomposeIntoBezierSegments(surface.knotsU(), &surface.poles()[j], cv);
        for (int s = 0; s < nu; ++s)
            for (int i = 0; i <= pu; ++i)
                strips[(s * (pu + 1) + i) * cv + j] = segs[s * (pu + 1) + i];
    }
    patches_.assign(static_cast<size_t>(nu * nv), BezierPatch(pu, pv));
    for (int s = 0; s < nu; ++s)
        for (int i = 0; i <= pu; ++i) {
            auto segs =
                decomposeIntoBezierSegments(surface.knotsV(), &strips[(s * (pu + 1) + i) * cv], 1);
            for (int t = 0; t < nv; ++t)
                for (int j = 0; j <= pv; ++j)
                    patches_[s * nv + t].pole(i, j) = segs[t * (pv + 1) + j];
        }
}

namespace {
int spanIndex(const std::vector<double>& breaks, double t) {
    auto it = std::upper_bound(breaks.begin(), breaks.end(), t);
    int k = static_cast<int>(it - breaks.begin()) - 1;
    return std::clamp(k, 0, static_cast<int>(breaks.size()) - 2);
}
}  // namespace

BezierPatch BezierPatchGrid::piece(int spanU, int spanV, double u0, double u1, double v0,
                                   double v1) const {
    auto local = [](double t, double a, double b) {
        return std::clamp((t - a) / (b - a), 0.0, 1.0);
    };
    const double a0 = breaksU_[spanU], a1 = breaksU_[spanU + 1];
    const double b0 = breaksV_[spanV], b1 = breaksV_[spanV + 1];
    return patch(spanU, spanV)
        .restricted(local(u0, a0, a1), local(u1, a0, a1), local(v0, b0, b1), local(v1, b0, b1));
}

Point3 BezierPatchGrid::point(double u, double v) const {
    const int su = spanIndexU(u), sv = spanIndexV(v);
    return patch(su, sv).point((u - breaksU_[su]) / (breaksU_[su + 1] - breaksU_[su]),
                               (v - breaksV_[sv]) / (breaksV_[sv + 1] - breaksV_[sv]));
}

int BezierPatchGrid::spanIndexU(double u) const {
    return spanIndex(breaksU_, u);
}
int BezierPatchGrid::spanIndexV(double v) const {
    return spanIndex(breaksV_, v);
}

}  // namespace nurbslod
