#include "geometry/PointSetEvaluator.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geometry/BasisFunctions.hpp"
#include "geometry/SurfaceNormal.hpp"

namespace nurbslod {

PointSetEvaluator::PointSetEvaluator(const BSplineSurface& surface) : surface_(surface) {
    if (auto problem = surface.problem()) throw std::invalid_argument(*problem);
}

void PointSetEvaluator::evaluate(std::span<const Point2> uv, Point3* points, Vector3* normals,
                                 int threads) const {
    const KnotVector& ku = surface_.knotsU();
    const KnotVector& kv = surface_.knotsV();
    const int pu = ku.degree(), pv = kv.degree();
    // clamped parameters, as BSplineSurface clamps them
    std::vector<Point2> clamped(uv.size());
    for (size_t k = 0; k < uv.size(); ++k) {
        if (!std::isfinite(uv[k].x()) || !std::isfinite(uv[k].y()))
            throw std::invalid_argument("parameter pair " + std::to_string(k) + " is not finite");
        clamped[k] = Point2(std::clamp(uv[k].x(), ku.first(), ku.last()),
                            std::clamp(uv[k].y(), kv.first(), kv.last()));
    }
    // pairs sorted by u: each run of equal u is one group sharing its row sums
    std::vector<size_t> order(uv.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return clamped[a].x() < clamped[b].x(); });
    std::vector<size_t> groupStart;
    for (size_t k = 0; k < order.size(); ++k)
        if (k == 0 || clamped[order[k]].x() != clamped[order[k - 1]].x()) groupStart.push_back(k);
    groupStart.push_back(order.size());

    auto runGroups = [&](size_t firstGroup, size_t lastGroup) {
        std::vector<HomogeneousPoint3> rowSums, rowDerivativeSums;
        std::vector<int> spans;
        for (size_t g = firstGroup; g < lastGroup; ++g) {
            const size_t begin = groupStart[g], end = groupStart[g + 1];
            const double u = clamped[order[begin]].x();
            const int su = ku.findSpan(u);
            double Nu[kMaxDegree + 1], dNu[kMaxDegree + 1];
            basisFunctionsWithDerivative(ku, su, u, Nu, dNu);
            // the control-point columns this group's v values reach
            spans.resize(end - begin);
            int lo = surface_.countV(), hi = 0;
            for (size_t k = begin; k < end; ++k) {
                spans[k - begin] = kv.findSpan(clamped[order[k]].y());
                lo = std::min(lo, spans[k - begin] - pv);
                hi = std::max(hi, spans[k - begin]);
            }
            const int width = hi - lo + 1;
            rowSums.assign(width, HomogeneousPoint3::Zero());
            rowDerivativeSums.assign(width, HomogeneousPoint3::Zero());
            for (int k = 0; k <= pu; ++k)
                for (int j = 0; j < width; ++j) {
                    const HomogeneousPoint3& P = surface_.pole(su - pu + k, lo + j);
                    rowSums[j] += Nu[k] * P;
                    if (normals) rowDerivativeSums[j] += dNu[k] * P;
                }
            for (size_t k = begin; k < end; ++k) {
                const size_t index = order[k];
                const double v = clamped[index].y();
                const int sv = spans[k - begin];
                double Nv[kMaxDegree + 1], dNv[kMaxDegree + 1];
                basisFunctionsWithDerivative(kv, sv, v, Nv, dNv);
                const HomogeneousPoint3* Q = &rowSums[sv - pv - lo];
                const HomogeneousPoint3* Qd = &rowDerivativeSums[sv - pv - lo];
                HomogeneousPoint3 S = HomogeneousPoint3::Zero(), Su = S, Sv = S;
                for (int l = 0; l <= pv; ++l) S += Nv[l] * Q[l];
                const double w = S[3];
                points[index] = S.head<3>() / w;
                if (!normals) continue;
                for (int l = 0; l <= pv; ++l) {
                    Su += Nv[l] * Qd[l];
                    Sv += dNv[l] * Q[l];
                }
                // quotient rule without the division (w^2 times the true derivatives)
                const Vector3 du = w * Su.head<3>() - Su[3] * S.head<3>();
                const Vector3 dv = w * Sv.head<3>() - Sv[3] * S.head<3>();
                normals[index] = unitNormal(du, dv, surface_, u, v);
            }
        }
    };
    const size_t groups = groupStart.size() - 1;
    if (threads <= 1 || uv.size() < 4096) {
        runGroups(0, groups);
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, groups),
            [&](const tbb::blocked_range<size_t>& r) { runGroups(r.begin(), r.end()); });
    });
}

}  // namespace nurbslod
