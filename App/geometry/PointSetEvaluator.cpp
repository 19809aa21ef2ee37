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
#include <utility>

#include "geometry/BasisFunctions.hpp"
#include "geometry/GridBasis.hpp"
#include "geometry/SurfaceNormal.hpp"

namespace nurbslod {

namespace {

// The distinct values of one coordinate of the pairs, in order of first appearance, and for
// each pair the index of its value: an open-addressing table sized for the call (a face's few
// dozen values cost a few instructions each; the library's hash table costs more to set up
// than the evaluations it saves, and a sort of the values more than twice that).
void distinctValues(std::span<const Point2> uv, int axis, std::vector<double>& distinct,
                    std::vector<int>& valueOfPair) {
    const size_t capacity = std::bit_ceil(std::max<size_t>(16, 2 * uv.size()));
    const int shift = 64 - std::countr_zero(capacity);
    std::vector<int> slot(capacity, -1);
    distinct.clear();
    valueOfPair.resize(uv.size());
    for (size_t k = 0; k < uv.size(); ++k) {
        const double t = uv[k][axis] + 0.0;  // -0 and +0 alike
        // Fibonacci hashing of the value's bits
        size_t h = (std::bit_cast<std::uint64_t>(t) * 0x9E3779B97F4A7C15ull) >> shift;
        while (slot[h] >= 0 && distinct[slot[h]] != t) h = (h + 1) & (capacity - 1);
        if (slot[h] < 0) {
            slot[h] = static_cast<int>(distinct.size());
            distinct.push_back(t);
        }
        valueOfPair[k] = slot[h];
    }
}

// Basis functions and first derivatives of a fixed degree P: the triangular scheme of NURBS
// Book A2.2 up to degree P-1, then the last degree and the derivatives from the same
// quotients, N'_{r,P} = P (N_{r-1,P-1}/(u_{r+P}-u_r) - N_{r,P-1}/(u_{r+P+1}-u_{r+1}))
// (eq. 2.9, as A2.3 computes them). Fixed bounds let the compiler unroll every loop; a zero
// knot difference gives 0 as in basisFunctions.
template <int P>
void fixedDegreeBasis(const double* U, int span, double t, double* N, double* dN) {
    double left[P + 1], right[P + 1], lower[P + 1];
    for (int j = 1; j <= P; ++j) {
        left[j] = t - U[span + 1 - j];
        right[j] = U[span + j] - t;
    }
    lower[0] = 1.0;
    for (int j = 1; j < P; ++j) {
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double denominator = right[r + 1] + left[j - r];
            const double temp = denominator != 0.0 ? lower[r] / denominator : 0.0;
            lower[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        lower[j] = saved;
    }
    double saved = 0.0, previous = 0.0;
    for (int r = 0; r < P; ++r) {
        const double denominator = right[r + 1] + left[P - r];
        const double temp = denominator != 0.0 ? lower[r] / denominator : 0.0;
        N[r] = saved + right[r + 1] * temp;
        dN[r] = P * (previous - temp);
        saved = left[P - r] * temp;
        previous = temp;
    }
    N[P] = saved;
    dN[P] = P * previous;
}

using FixedDegreeBasis = void (*)(const double*, int, double, double*, double*);

template <int... P>
FixedDegreeBasis fixedDegreeBasisAmong(int p, std::integer_sequence<int, P...>) {
    FixedDegreeBasis found = nullptr;
    ((p == P + 1 ? (found = &fixedDegreeBasis<P + 1>, 0) : 0), ...);
    return found;
}

// The unrolled basis for degrees 1 to 15 (the evaluation paper's range), else null.
FixedDegreeBasis fixedDegreeBasisFor(int p) {
    return fixedDegreeBasisAmong(p, std::make_integer_sequence<int, 15>{});
}

// Spans, basis functions and derivatives once per distinct parameter, clamped to the domain as
// BSplineSurface clamps.
GridBasis basisOf(const KnotVector& knots, const std::vector<double>& parameters) {
    GridBasis table;
    const int p = knots.degree();
    table.degree = p;
    table.parameter.resize(parameters.size());
    table.span.resize(parameters.size());
    table.values.resize(parameters.size() * (p + 1));
    table.derivatives.resize(parameters.size() * (p + 1));
    const double* U = knots.knots().data();
    const FixedDegreeBasis fixed = fixedDegreeBasisFor(p);
    for (size_t k = 0; k < parameters.size(); ++k) {
        const double t = std::clamp(parameters[k], knots.first(), knots.last());
        const int span = knots.findSpan(t);
        table.parameter[k] = t;
        table.span[k] = span;
        double* N = &table.values[k * (p + 1)];
        double* dN = &table.derivatives[k * (p + 1)];
        if (fixed)
            fixed(U, span, t, N, dN);
        else
            basisFunctionsWithDerivative(knots, span, t, N, dN);
    }
    return table;
}

// S = sum N_i(u) N_j(v) P_ij and its u and v derivatives over one span (the sums of
// BSplineSurface::derivatives), for degrees fixed at compile time (0: the surface's own).
template <int PU, int PV, bool kNormals>
void directSums(const BSplineSurface& surface, int su, int sv, const double* Nu, const double* dNu,
                const double* Nv, const double* dNv, HomogeneousPoint3& S, HomogeneousPoint3& Su,
                HomogeneousPoint3& Sv) {
    const int pu = PU ? PU : surface.degreeU(), pv = PV ? PV : surface.degreeV();
    S = HomogeneousPoint3::Zero();
    Su = S;
    Sv = S;
    for (int i = 0; i <= pu; ++i) {
        const HomogeneousPoint3* row = &surface.pole(su - pu + i, sv - pv);
        HomogeneousPoint3 inner = HomogeneousPoint3::Zero(), innerDv = inner;
        for (int l = 0; l <= pv; ++l) {
            inner += Nv[l] * row[l];
            if constexpr (kNormals) innerDv += dNv[l] * row[l];
        }
        S += Nu[i] * inner;
        if constexpr (kNormals) {
            Su += dNu[i] * inner;
            Sv += Nu[i] * innerDv;
        }
    }
}

using DirectSums = void (*)(const BSplineSurface&, int, int, const double*, const double*,
                            const double*, const double*, HomogeneousPoint3&, HomogeneousPoint3&,
                            HomogeneousPoint3&);

// The degrees of nearly every CAD surface (planes 1, conics 2, free forms 3) get their own
// unrolled kernel; a high degree in u over a low one in v (swept and lofted faces) keeps the
// inner loop unrolled; other degrees take the general loops.
template <bool kNormals>
DirectSums directSumsFor(int pu, int pv) {
    static constexpr DirectSums fixed[3][3] = {
        {&directSums<1, 1, kNormals>, &directSums<1, 2, kNormals>, &directSums<1, 3, kNormals>},
        {&directSums<2, 1, kNormals>, &directSums<2, 2, kNormals>, &directSums<2, 3, kNormals>},
        {&directSums<3, 1, kNormals>, &directSums<3, 2, kNormals>, &directSums<3, 3, kNormals>}};
    static constexpr DirectSums fixedV[3] = {
        &directSums<0, 1, kNormals>, &directSums<0, 2, kNormals>, &directSums<0, 3, kNormals>};
    if (pv >= 1 && pv <= 3) return pu >= 1 && pu <= 3 ? fixed[pu - 1][pv - 1] : fixedV[pv - 1];
    return &directSums<0, 0, kNormals>;
}

// Everything a group of pairs with one u value needs, shared by all groups.
struct PairSet {
    const BSplineSurface& surface;
    const GridBasis& basisU;
    const GridBasis& basisV;
    const std::vector<size_t>& order;  // pairs by u group
    const std::vector<size_t>& groupStart;
    const std::vector<int>& pairV;
    Point3* points;
    Vector3* normals;
};

// Point and unit normal from the homogeneous sums S, S_u, S_v.
template <bool kNormals>
inline void storeResult(const PairSet& set, size_t pair, const HomogeneousPoint3& S,
                        const HomogeneousPoint3& Su, const HomogeneousPoint3& Sv, double u,
                        double v) {
    const double w = S[3];
    set.points[pair] = S.head<3>() * (1.0 / w);
    if constexpr (kNormals) {
        // quotient rule without the division (w^2 times the true derivatives, NURBS Book
        // eq. 4.19)
        const Vector3 du = w * Su.head<3>() - Su[3] * S.head<3>();
        const Vector3 dv = w * Sv.head<3>() - Sv[3] * S.head<3>();
        set.normals[pair] = unitNormal(du, dv, set.surface, u, v);
    }
}

template <bool kNormals>
void evaluateGroups(const PairSet& set, size_t firstGroup, size_t lastGroup) {
    const BSplineSurface& surface = set.surface;
    const int pu = surface.degreeU(), pv = surface.degreeV();
    // the same kernel for points alone, so that both give the same bits
    const DirectSums sums = directSumsFor<true>(pu, pv);
    std::vector<HomogeneousPoint3> rowSums, rowDerivativeSums;
    for (size_t g = firstGroup; g < lastGroup; ++g) {
        const size_t begin = set.groupStart[g], end = set.groupStart[g + 1];
        const int su = set.basisU.span[g];
        const double* Nu = set.basisU.valuesAt(g);
        const double* dNu = set.basisU.derivativesAt(g);
        const double u = set.basisU.parameter[g];
        // the control-point columns this group's v values reach
        int lo = surface.countV(), hi = 0;
        for (size_t k = begin; k < end; ++k) {
            const int sv = set.basisV.span[set.pairV[set.order[k]]];
            lo = std::min(lo, sv - pv);
            hi = std::max(hi, sv);
        }
        const int width = hi - lo + 1;
        // Homogeneous multiply-adds of the two ways (counted with normals, so that points
        // alone take the same way and give the same bits): row sums over the band, then
        // (pv+1) terms per sum and pair; or per pair the (pu+1)(pv+1) terms of the inner sums
        // and (pu+1) of the outer ones. The row sums run in loops of run-time length, the direct
        // sums unrolled for the common degrees, so a row term counts double (measured on the
        // corpus: a lone pair of a face with pu > pv then goes the direct way).
        const long pairs = static_cast<long>(end - begin);
        const long rowWork = 2 * (2L * (pu + 1) * width + pairs * 3L * (pv + 1));
        const long directWork = pairs * ((pu + 1) * (2L * (pv + 1) + 3));
        if (rowWork >= directWork) {
            for (size_t k = begin; k < end; ++k) {
                const size_t pair = set.order[k];
                const int vi = set.pairV[pair];
                HomogeneousPoint3 S, Su, Sv;
                sums(surface, su, set.basisV.span[vi], Nu, dNu, set.basisV.valuesAt(vi),
                     set.basisV.derivativesAt(vi), S, Su, Sv);
                storeResult<kNormals>(set, pair, S, Su, Sv, u, set.basisV.parameter[vi]);
            }
            continue;
        }
        rowSums.assign(width, HomogeneousPoint3::Zero());
        if constexpr (kNormals) rowDerivativeSums.assign(width, HomogeneousPoint3::Zero());
        for (int k = 0; k <= pu; ++k) {
            const HomogeneousPoint3* row = &surface.pole(su - pu + k, lo);
            for (int j = 0; j < width; ++j) {
                rowSums[j] += Nu[k] * row[j];
                if constexpr (kNormals) rowDerivativeSums[j] += dNu[k] * row[j];
            }
        }
        for (size_t k = begin; k < end; ++k) {
            const size_t pair = set.order[k];
            const int vi = set.pairV[pair];
            const int sv = set.basisV.span[vi];
            const double* Nv = set.basisV.valuesAt(vi);
            const HomogeneousPoint3* Q = &rowSums[sv - pv - lo];
            HomogeneousPoint3 S = HomogeneousPoint3::Zero(), Su = S, Sv = S;
            for (int l = 0; l <= pv; ++l) S += Nv[l] * Q[l];
            if constexpr (kNormals) {
                const double* dNv = set.basisV.derivativesAt(vi);
                const HomogeneousPoint3* Qd = &rowDerivativeSums[sv - pv - lo];
                for (int l = 0; l <= pv; ++l) {
                    Su += Nv[l] * Qd[l];
                    Sv += dNv[l] * Q[l];
                }
            }
            storeResult<kNormals>(set, pair, S, Su, Sv, u, set.basisV.parameter[vi]);
        }
    }
}

}  // namespace

PointSetEvaluator::PointSetEvaluator(const BSplineSurface& surface)
    : surface_(&surface.validated()) {}

void PointSetEvaluator::evaluate(std::span<const Point2> uv, Point3* points, Vector3* normals,
                                 int threads) const {
    for (size_t k = 0; k < uv.size(); ++k)
        if (!std::isfinite(uv[k].x()) || !std::isfinite(uv[k].y()))
            throw std::invalid_argument("parameter pair " + std::to_string(k) + " is not finite");
    // distinct u and v values (a tessellation repeats them a lot): basis functions once per
    // distinct value
    std::vector<double> distinctU, distinctV;
    std::vector<int> pairU, pairV;
    distinctValues(uv, 0, distinctU, pairU);
    distinctValues(uv, 1, distinctV, pairV);
    const GridBasis basisU = basisOf(surface_->knotsU(), distinctU);
    const GridBasis basisV = basisOf(surface_->knotsV(), distinctV);
    // pairs by u group (a counting sort)
    std::vector<size_t> groupStart(distinctU.size() + 1, 0), order(uv.size());
    for (int g : pairU) ++groupStart[g + 1];
    for (size_t g = 0; g < distinctU.size(); ++g) groupStart[g + 1] += groupStart[g];
    {
        std::vector<size_t> next(groupStart.begin(), groupStart.end() - 1);
        for (size_t k = 0; k < uv.size(); ++k) order[next[pairU[k]]++] = k;
    }

    const PairSet set{*surface_, basisU, basisV, order, groupStart, pairV, points, normals};
    auto run = [&](size_t firstGroup, size_t lastGroup) {
        if (normals)
            evaluateGroups<true>(set, firstGroup, lastGroup);
        else
            evaluateGroups<false>(set, firstGroup, lastGroup);
    };
    const size_t groups = distinctU.size();
    if (threads <= 1 || uv.size() < 4096) {
        run(0, groups);
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, groups),
                          [&](const tbb::blocked_range<size_t>& r) { run(r.begin(), r.end()); });
    });
}

}  // namespace nurbslod
