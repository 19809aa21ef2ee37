#include "geometry/PointSetEvaluator.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "geometry/GridBasis.hpp"
#include "geometry/SurfaceNormal.hpp"

namespace nurbslod {

namespace {

// A cheap hash of a parameter value (Fibonacci hashing of its bits; -0 and +0 alike): the
// library's byte hash costs more than the evaluation it groups.
struct ParameterHash {
    size_t operator()(double t) const {
        return static_cast<size_t>(
            (std::bit_cast<std::uint64_t>(t + 0.0) * 0x9E3779B97F4A7C15ull) >> 16);
    }
};

}  // namespace

PointSetEvaluator::PointSetEvaluator(const BSplineSurface& surface)
    : surface_(surface.validated()) {}

void PointSetEvaluator::evaluate(std::span<const Point2> uv, Point3* points, Vector3* normals,
                                 int threads) const {
    const KnotVector& ku = surface_.knotsU();
    const KnotVector& kv = surface_.knotsV();
    const int pu = ku.degree(), pv = kv.degree();
    // Distinct u and v values (a tessellation repeats them a lot): basis functions once per
    // distinct value, and pairs grouped by their u. Hashing instead of sorting: the groups
    // need no order, and a sort of the pairs would cost more than their evaluation.
    std::unordered_map<double, int, ParameterHash> uIndex, vIndex;
    uIndex.reserve(1024);
    vIndex.reserve(1024);
    std::vector<double> distinctU, distinctV;
    std::vector<int> pairU(uv.size()), pairV(uv.size());
    for (size_t k = 0; k < uv.size(); ++k) {
        if (!std::isfinite(uv[k].x()) || !std::isfinite(uv[k].y()))
            throw std::invalid_argument("parameter pair " + std::to_string(k) + " is not finite");
        auto [u, newU] = uIndex.try_emplace(uv[k].x(), static_cast<int>(distinctU.size()));
        if (newU) distinctU.push_back(uv[k].x());
        pairU[k] = u->second;
        auto [v, newV] = vIndex.try_emplace(uv[k].y(), static_cast<int>(distinctV.size()));
        if (newV) distinctV.push_back(uv[k].y());
        pairV[k] = v->second;
    }
    // clamped to the domain as BSplineSurface clamps
    const GridBasis basisU = makeGridBasis(ku, distinctU, 'u');
    const GridBasis basisV = makeGridBasis(kv, distinctV, 'v');
    // pairs by u group (a counting sort)
    std::vector<size_t> groupStart(distinctU.size() + 1, 0), order(uv.size());
    for (int g : pairU) ++groupStart[g + 1];
    for (size_t g = 0; g < distinctU.size(); ++g) groupStart[g + 1] += groupStart[g];
    {
        std::vector<size_t> next(groupStart.begin(), groupStart.end() - 1);
        for (size_t k = 0; k < uv.size(); ++k) order[next[pairU[k]]++] = k;
    }

    auto runGroups = [&](size_t firstGroup, size_t lastGroup) {
        std::vector<HomogeneousPoint3> rowSums, rowDerivativeSums;
        for (size_t g = firstGroup; g < lastGroup; ++g) {
            const size_t begin = groupStart[g], end = groupStart[g + 1];
            const int su = basisU.span[g];
            const double* Nu = basisU.valuesAt(g);
            const double* dNu = basisU.derivativesAt(g);
            // the control-point columns this group's v values reach
            int lo = surface_.countV(), hi = 0;
            for (size_t k = begin; k < end; ++k) {
                const int sv = basisV.span[pairV[order[k]]];
                lo = std::min(lo, sv - pv);
                hi = std::max(hi, sv);
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
                const int vi = pairV[index];
                const int sv = basisV.span[vi];
                const double* Nv = basisV.valuesAt(vi);
                const HomogeneousPoint3* Q = &rowSums[sv - pv - lo];
                HomogeneousPoint3 S = HomogeneousPoint3::Zero();
                for (int l = 0; l <= pv; ++l) S += Nv[l] * Q[l];
                const double w = S[3];
                points[index] = S.head<3>() * (1.0 / w);
                if (!normals) continue;
                const double* dNv = basisV.derivativesAt(vi);
                const HomogeneousPoint3* Qd = &rowDerivativeSums[sv - pv - lo];
                HomogeneousPoint3 Su = HomogeneousPoint3::Zero(), Sv = Su;
                for (int l = 0; l <= pv; ++l) {
                    Su += Nv[l] * Qd[l];
                    Sv += dNv[l] * Q[l];
                }
                // quotient rule without the division (w^2 times the true derivatives)
                const Vector3 du = w * Su.head<3>() - Su[3] * S.head<3>();
                const Vector3 dv = w * Sv.head<3>() - Sv[3] * S.head<3>();
                normals[index] =
                    unitNormal(du, dv, surface_, basisU.parameter[g], basisV.parameter[vi]);
            }
        }
    };
    const size_t groups = distinctU.size();
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
