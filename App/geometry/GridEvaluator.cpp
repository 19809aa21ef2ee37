#include "geometry/GridEvaluator.hpp"

#include <immintrin.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/GridBasis.hpp"
#include "geometry/SurfaceNormal.hpp"

namespace nurbslod {

namespace {

constexpr int kLanes = 4;

// The v basis functions of four consecutive grid columns side by side: column block b covers
// control-point columns base[b] .. base[b] + width[b] - 1, and coefficient l of lane q sits at
// coefficients[offset[b] + l * 4 + q] (values) and offset[b] + width[b] * 4 + l * 4 + q
// (derivatives), zero outside the lane's own span. A block whose spans lie far apart (a coarse
// grid over many spans) gets width 0 and is evaluated vertex by vertex.
struct ColumnBlocks {
    std::vector<int> base, width;
    std::vector<size_t> offset;
    std::vector<double> coefficients;
};

ColumnBlocks makeColumnBlocks(const GridBasis& v) {
    ColumnBlocks blocks;
    const int n = static_cast<int>(v.span.size());
    const int p = v.degree;
    for (int j0 = 0; j0 < n; j0 += kLanes) {
        const int count = std::min(kLanes, n - j0);
        int lo = v.span[j0], hi = v.span[j0];
        for (int q = 1; q < count; ++q) {
            lo = std::min(lo, v.span[j0 + q]);
            hi = std::max(hi, v.span[j0 + q]);
        }
        int width = hi - lo + p + 1;
        if (width > 2 * (p + 1)) width = 0;
        blocks.base.push_back(lo - p);
        blocks.width.push_back(width);
        blocks.offset.push_back(blocks.coefficients.size());
        const size_t offset = blocks.coefficients.size();
        blocks.coefficients.resize(offset + 2 * kLanes * width, 0.0);
        if (width == 0) continue;
        for (int q = 0; q < count; ++q) {
            const int shift = v.span[j0 + q] - lo;
            for (int l = 0; l <= p; ++l) {
                blocks.coefficients[offset + (shift + l) * kLanes + q] =
                    v.values[(j0 + q) * (p + 1) + l];
                blocks.coefficients[offset + width * kLanes + (shift + l) * kLanes + q] =
                    v.derivatives[(j0 + q) * (p + 1) + l];
            }
        }
    }
    return blocks;
}

// Everything a row needs, shared by all rows.
struct GridPlan {
    const BSplineSurface* surface;
    const double* poles;  // structure of arrays, see GridEvaluator::poles_
    int countU, countV;
    GridBasis u, v;
    ColumnBlocks blocks;
    Point3* points;
    Vector3* normals;
};

// Row sums Q_j = sum_k N_k(u) P_(s-p+k, j) (and Q'_j with N'_k) for every column j, component
// by component: q[c * countV + j] (the AVX2 path's layout). Inlined into a target("avx2,fma")
// function, so that the compiler vectorises the column loops with AVX2.
template <bool kDerivatives>
[[gnu::always_inline]] inline void rowSumsBody(const GridPlan& plan, int row, double* q,
                                               double* qd) {
    const int p = plan.u.degree, n = plan.countV;
    const int first = plan.u.span[row] - p;
    const double* N = &plan.u.values[row * (p + 1)];
    const double* dN = &plan.u.derivatives[row * (p + 1)];
    for (int c = 0; c < 4; ++c) {
        double* __restrict out = q + c * n;
        double* __restrict outD = qd + c * n;
        const double* pole = plan.poles + (static_cast<size_t>(c) * plan.countU + first) * n;
        for (int j = 0; j < n; ++j) {
            out[j] = N[0] * pole[j];
            if constexpr (kDerivatives) outD[j] = dN[0] * pole[j];
        }
        for (int k = 1; k <= p; ++k) {
            const double* __restrict row_k = pole + static_cast<size_t>(k) * n;
            const double a = N[k], b = dN[k];
            for (int j = 0; j < n; ++j) {
                out[j] += a * row_k[j];
                if constexpr (kDerivatives) outD[j] += b * row_k[j];
            }
        }
    }
}

[[gnu::target("avx2,fma")]] void rowSumsAvx2(const GridPlan& plan, int row, double* q, double* qd) {
    if (plan.normals)
        rowSumsBody<true>(plan, row, q, qd);
    else
        rowSumsBody<false>(plan, row, q, qd);
}

// One vertex from the AVX2 path's row sums, for a block whose columns lie too far apart to be
// padded into one: S = sum_l N_l(v) Q_(s-p+l), S_u = sum N_l Q'_.., S_v = sum N'_l
// Q_..; the point is S/w and the normal the direction of (w S_u - w_u S) x (w S_v - w_v S),
// which is w^4 times du x dv by the quotient rule.
void scalarVertex(const GridPlan& plan, const double* q, const double* qd, int row, int column) {
    const int p = plan.v.degree, n = plan.countV;
    const int first = plan.v.span[column] - p;
    const double* N = &plan.v.values[column * (p + 1)];
    const double* dN = &plan.v.derivatives[column * (p + 1)];
    double S[4] = {0, 0, 0, 0}, Su[4] = {0, 0, 0, 0}, Sv[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c) {
        const double* qc = q + c * n + first;
        for (int l = 0; l <= p; ++l) S[c] += N[l] * qc[l];
    }
    const size_t index = static_cast<size_t>(row) * plan.v.span.size() + column;
    const double inverseW = 1.0 / S[3];
    plan.points[index] = Point3(S[0] * inverseW, S[1] * inverseW, S[2] * inverseW);
    if (!plan.normals) return;
    for (int c = 0; c < 4; ++c) {
        const double* qc = q + c * n + first;
        const double* qdc = qd + c * n + first;
        for (int l = 0; l <= p; ++l) {
            Su[c] += N[l] * qdc[l];
            Sv[c] += dN[l] * qc[l];
        }
    }
    const double w = S[3];
    const Vector3 du(w * Su[0] - Su[3] * S[0], w * Su[1] - Su[3] * S[1], w * Su[2] - Su[3] * S[2]);
    const Vector3 dv(w * Sv[0] - Sv[3] * S[0], w * Sv[1] - Sv[3] * S[1], w * Sv[2] - Sv[3] * S[2]);
    const Vector3 normal = du.cross(dv);
    plan.normals[index] =
        isReliableNormal(du, dv, normal)
            ? Vector3(normal * (1.0 / std::sqrt(normal.squaredNorm())))
            : plan.surface->normal(plan.u.parameter[row], plan.v.parameter[column]);
}

// The scalar path (the paper's optimized direct evaluation): row sums as homogeneous points,
// then per vertex (pv + 1) terms for each of S, S_u, S_v, four components at a time.
void scalarRow(const GridPlan& plan, int row, HomogeneousPoint3* Q, HomogeneousPoint3* Qd) {
    const BSplineSurface& surface = *plan.surface;
    const int pu = plan.u.degree, pv = plan.v.degree, n = plan.countV;
    const int first = plan.u.span[row] - pu;
    const double* Nu = plan.u.valuesAt(row);
    const double* dNu = plan.u.derivativesAt(row);
    for (int j = 0; j < n; ++j) {
        Q[j] = Nu[0] * surface.pole(first, j);
        if (plan.normals) Qd[j] = dNu[0] * surface.pole(first, j);
    }
    for (int k = 1; k <= pu; ++k)
        for (int j = 0; j < n; ++j) {
            Q[j] += Nu[k] * surface.pole(first + k, j);
            if (plan.normals) Qd[j] += dNu[k] * surface.pole(first + k, j);
        }
    const size_t columns = plan.v.span.size();
    const size_t rowStart = static_cast<size_t>(row) * columns;
    for (size_t j = 0; j < columns; ++j) {
        const int base = plan.v.span[j] - pv;
        const double* Nv = plan.v.valuesAt(j);
        HomogeneousPoint3 S = HomogeneousPoint3::Zero();
        for (int l = 0; l <= pv; ++l) S += Nv[l] * Q[base + l];
        const double w = S[3];
        plan.points[rowStart + j] = S.head<3>() * (1.0 / w);
        if (!plan.normals) continue;
        const double* dNv = plan.v.derivativesAt(j);
        HomogeneousPoint3 Su = HomogeneousPoint3::Zero(), Sv = Su;
        for (int l = 0; l <= pv; ++l) {
            Su += Nv[l] * Qd[base + l];
            Sv += dNv[l] * Q[base + l];
        }
        // quotient rule without the division: w^2 times the true derivatives
        const Vector3 du = w * Su.head<3>() - Su[3] * S.head<3>();
        const Vector3 dv = w * Sv.head<3>() - Sv[3] * S.head<3>();
        const Vector3 normal = du.cross(dv);
        plan.normals[rowStart + j] =
            isReliableNormal(du, dv, normal)
                ? Vector3(normal * (1.0 / std::sqrt(normal.squaredNorm())))
                : surface.normal(plan.u.parameter[row], plan.v.parameter[j]);
    }
}

// x = (x0..x3), y, z to x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3: four Point3 in a row.
[[gnu::target("avx2,fma")]] inline void storeInterleaved(double* out, __m256d x, __m256d y,
                                                         __m256d z) {
    const __m256d xy02 = _mm256_unpacklo_pd(x, y);   // x0 y0 x2 y2
    const __m256d xy13 = _mm256_unpackhi_pd(x, y);   // x1 y1 x3 y3
    const __m256d zx = _mm256_unpacklo_pd(z, xy13);  // z0 x1 z2 x3
    const __m256d yz = _mm256_unpackhi_pd(xy13, z);  // y1 z1 y3 z3
    _mm256_storeu_pd(out, _mm256_permute2f128_pd(xy02, zx, 0x20));
    _mm256_storeu_pd(out + 4, _mm256_blend_pd(yz, xy02, 0b1100));
    _mm256_storeu_pd(out + 8, _mm256_permute2f128_pd(zx, yz, 0x31));
}

// Four vertices of a row from the row sums (see scalarVertex). For a polynomial surface the
// weight channel is skipped: its poles are stored divided by their common weight, so w = 1 and
// the quotient rule reduces to the plain derivatives.
template <bool kRational>
[[gnu::target("avx2,fma")]] void avx2Row(const GridPlan& plan, int row, double* q, double* qd) {
    rowSumsAvx2(plan, row, q, qd);
    const int n = plan.countV;
    const int columns = static_cast<int>(plan.v.span.size());
    const size_t rowStart = static_cast<size_t>(row) * columns;
    const bool withNormals = plan.normals != nullptr;
    const __m256d one = _mm256_set1_pd(1.0);
    for (int block = 0, j0 = 0; j0 < columns; ++block, j0 += kLanes) {
        const int count = std::min(kLanes, columns - j0);
        const int width = plan.blocks.width[block];
        if (width == 0) {
            for (int lane = 0; lane < count; ++lane) scalarVertex(plan, q, qd, row, j0 + lane);
            continue;
        }
        const int base = plan.blocks.base[block];
        const double* N = &plan.blocks.coefficients[plan.blocks.offset[block]];
        const double* dN = N + width * kLanes;
        const double *qx = q + base, *qy = q + n + base, *qz = q + 2 * n + base,
                     *qw = q + 3 * n + base;
        __m256d sx = _mm256_setzero_pd(), sy = sx, sz = sx, sw = one;
        double* pointOut = plan.points[rowStart + j0].data();
        if (!withNormals) {
            if constexpr (kRational) sw = _mm256_setzero_pd();
            for (int l = 0; l < width; ++l) {
                const __m256d b = _mm256_loadu_pd(N + l * kLanes);
                sx = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qx + l), sx);
                sy = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qy + l), sy);
                sz = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qz + l), sz);
                if constexpr (kRational) sw = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qw + l), sw);
            }
            if constexpr (kRational) {
                const __m256d inverse = _mm256_div_pd(one, sw);
                sx = _mm256_mul_pd(sx, inverse);
                sy = _mm256_mul_pd(sy, inverse);
                sz = _mm256_mul_pd(sz, inverse);
            }
            if (count == kLanes) {
                storeInterleaved(pointOut, sx, sy, sz);
            } else {
                alignas(32) double tmp[12];
                storeInterleaved(tmp, sx, sy, sz);
                std::copy(tmp, tmp + 3 * count, pointOut);
            }
            continue;
        }
        const double *qdx = qd + base, *qdy = qd + n + base, *qdz = qd + 2 * n + base,
                     *qdw = qd + 3 * n + base;
        const __m256d zero = _mm256_setzero_pd();
        if constexpr (kRational) sw = zero;
        __m256d ux = zero, uy = zero, uz = zero, uw = zero, vx = zero, vy = zero, vz = zero,
                vw = zero;
        for (int l = 0; l < width; ++l) {
            const __m256d b = _mm256_loadu_pd(N + l * kLanes);
            const __m256d db = _mm256_loadu_pd(dN + l * kLanes);
            const __m256d px = _mm256_broadcast_sd(qx + l), py = _mm256_broadcast_sd(qy + l),
                          pz = _mm256_broadcast_sd(qz + l);
            sx = _mm256_fmadd_pd(b, px, sx);
            sy = _mm256_fmadd_pd(b, py, sy);
            sz = _mm256_fmadd_pd(b, pz, sz);
            vx = _mm256_fmadd_pd(db, px, vx);
            vy = _mm256_fmadd_pd(db, py, vy);
            vz = _mm256_fmadd_pd(db, pz, vz);
            ux = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qdx + l), ux);
            uy = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qdy + l), uy);
            uz = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qdz + l), uz);
            if constexpr (kRational) {
                const __m256d pw = _mm256_broadcast_sd(qw + l);
                sw = _mm256_fmadd_pd(b, pw, sw);
                vw = _mm256_fmadd_pd(db, pw, vw);
                uw = _mm256_fmadd_pd(b, _mm256_broadcast_sd(qdw + l), uw);
            }
        }
        __m256d dux = ux, duy = uy, duz = uz, dvx = vx, dvy = vy, dvz = vz;
        if constexpr (kRational) {
            // quotient rule without the division: w S_u - w_u S (w^2 times the true derivative)
            dux = _mm256_fmsub_pd(sw, ux, _mm256_mul_pd(uw, sx));
            duy = _mm256_fmsub_pd(sw, uy, _mm256_mul_pd(uw, sy));
            duz = _mm256_fmsub_pd(sw, uz, _mm256_mul_pd(uw, sz));
            dvx = _mm256_fmsub_pd(sw, vx, _mm256_mul_pd(vw, sx));
            dvy = _mm256_fmsub_pd(sw, vy, _mm256_mul_pd(vw, sy));
            dvz = _mm256_fmsub_pd(sw, vz, _mm256_mul_pd(vw, sz));
        }
        const __m256d nx = _mm256_fmsub_pd(duy, dvz, _mm256_mul_pd(duz, dvy));
        const __m256d ny = _mm256_fmsub_pd(duz, dvx, _mm256_mul_pd(dux, dvz));
        const __m256d nz = _mm256_fmsub_pd(dux, dvy, _mm256_mul_pd(duy, dvx));
        const __m256d a2 =
            _mm256_fmadd_pd(dux, dux, _mm256_fmadd_pd(duy, duy, _mm256_mul_pd(duz, duz)));
        const __m256d b2 =
            _mm256_fmadd_pd(dvx, dvx, _mm256_fmadd_pd(dvy, dvy, _mm256_mul_pd(dvz, dvz)));
        const __m256d n2 = _mm256_fmadd_pd(nx, nx, _mm256_fmadd_pd(ny, ny, _mm256_mul_pd(nz, nz)));
        // the reliability rule of SurfaceNormal.hpp, four lanes at once
        const __m256d tiny = _mm256_set1_pd(1e-16);
        const __m256d ok1 = _mm256_cmp_pd(a2, _mm256_mul_pd(tiny, b2), _CMP_GT_OQ);
        const __m256d ok2 = _mm256_cmp_pd(b2, _mm256_mul_pd(tiny, a2), _CMP_GT_OQ);
        const __m256d ok3 = _mm256_cmp_pd(
            n2, _mm256_mul_pd(_mm256_set1_pd(1e-20), _mm256_mul_pd(a2, b2)), _CMP_GT_OQ);
        const int reliable = _mm256_movemask_pd(_mm256_and_pd(ok1, _mm256_and_pd(ok2, ok3)));
        // one division and one square root per four vertices, the rest multiplications
        const __m256d inverseLength = _mm256_div_pd(one, _mm256_sqrt_pd(n2));
        if constexpr (kRational) {
            const __m256d inverse = _mm256_div_pd(one, sw);
            sx = _mm256_mul_pd(sx, inverse);
            sy = _mm256_mul_pd(sy, inverse);
            sz = _mm256_mul_pd(sz, inverse);
        }
        const __m256d mx = _mm256_mul_pd(nx, inverseLength), my = _mm256_mul_pd(ny, inverseLength),
                      mz = _mm256_mul_pd(nz, inverseLength);
        double* normalOut = plan.normals[rowStart + j0].data();
        if (count == kLanes) {
            storeInterleaved(pointOut, sx, sy, sz);
            storeInterleaved(normalOut, mx, my, mz);
        } else {
            alignas(32) double tmp[12];
            storeInterleaved(tmp, sx, sy, sz);
            std::copy(tmp, tmp + 3 * count, pointOut);
            storeInterleaved(tmp, mx, my, mz);
            std::copy(tmp, tmp + 3 * count, normalOut);
        }
        if ((reliable & ((1 << count) - 1)) != (1 << count) - 1) {
            for (int lane = 0; lane < count; ++lane)
                if (!(reliable & (1 << lane)))
                    plan.normals[rowStart + j0 + lane] =
                        plan.surface->normal(plan.u.parameter[row], plan.v.parameter[j0 + lane]);
        }
    }
}

}  // namespace

GridEvaluator::GridEvaluator(const BSplineSurface& surface) : surface_(surface.validated()) {
    const int nu = surface.countU(), nv = surface.countV();
    poles_.resize(4 * static_cast<size_t>(nu) * nv);
    // a polynomial surface (all weights equal) is stored with weight 1, so that the AVX2 path
    // can skip the weight channel and the quotient rule
    rational_ = surface.isRational();
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            HomogeneousPoint3 p = surface.pole(i, j);
            if (!rational_) p /= p[3];
            for (int c = 0; c < 4; ++c) poles_[(static_cast<size_t>(c) * nu + i) * nv + j] = p[c];
        }
    if (avx2Available()) instructionSet_ = InstructionSet::Avx2;
}

bool GridEvaluator::avx2Available() {
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

void GridEvaluator::setInstructionSet(InstructionSet set) {
    instructionSet_ = set == InstructionSet::Avx2 && avx2Available() ? InstructionSet::Avx2
                                                                     : InstructionSet::Scalar;
}

void GridEvaluator::evaluate(std::span<const double> us, std::span<const double> vs, Point3* points,
                             Vector3* normals, int threads) const {
    if (us.empty() || vs.empty()) return;
    GridPlan plan{&surface_,
                  poles_.data(),
                  surface_.countU(),
                  surface_.countV(),
                  makeGridBasis(surface_.knotsU(), us, 'u'),
                  makeGridBasis(surface_.knotsV(), vs, 'v'),
                  {},
                  points,
                  normals};
    const bool avx2 = instructionSet_ == InstructionSet::Avx2;
    if (avx2) plan.blocks = makeColumnBlocks(plan.v);
    const int rows = static_cast<int>(us.size());
    const size_t scratch = 8 * static_cast<size_t>(plan.countV);
    auto runRows = [&](int begin, int end) {
        std::vector<double> buffer(avx2 ? scratch : 0);
        std::vector<HomogeneousPoint3> rowSums(avx2 ? 0 : 2 * plan.countV);
        double* q = buffer.data();
        double* qd = q + (avx2 ? 4 * plan.countV : 0);
        for (int i = begin; i < end; ++i) {
            if (avx2 && rational_)
                avx2Row<true>(plan, i, q, qd);
            else if (avx2)
                avx2Row<false>(plan, i, q, qd);
            else
                scalarRow(plan, i, rowSums.data(), rowSums.data() + plan.countV);
        }
    };
    // a small grid is done before threads would have started
    if (threads <= 1 || us.size() * vs.size() < 16384) {
        runRows(0, rows);
        return;
    }
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, rows),
                          [&](const tbb::blocked_range<int>& r) { runRows(r.begin(), r.end()); });
    });
}

void GridEvaluator::evaluate(std::span<const double> us, std::span<const double> vs,
                             std::vector<Point3>& points, std::vector<Vector3>* normals,
                             int threads) const {
    points.resize(us.size() * vs.size());
    if (normals) normals->resize(us.size() * vs.size());
    evaluate(us, vs, points.data(), normals ? normals->data() : nullptr, threads);
}

}  // namespace nurbslod
