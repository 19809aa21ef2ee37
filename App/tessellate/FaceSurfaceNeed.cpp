#include "tessellate/FaceSurfaceNeed.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {

namespace {

// Calls `visit` with each of the face's Bezier patches restricted to the bounding box of the
// trimming curves' control points (which holds the curves: positive weights) until it returns
// false; false where there is no such box. `given`: the face's patches, if the caller has them.
bool forEachTrimmedPiece(const TrimmedSurface& face, const BezierPatchGrid* given,
                         const std::function<bool(const BezierPatch&)>& visit) {
    double u0 = std::numeric_limits<double>::max(), v0 = u0, u1 = -u0, v1 = -u0;
    for (const auto& loop : face.loops)
        for (const auto& curve : loop.curves)
            for (const auto& pole : curve.pcurve.poles()) {
                if (!(pole.z() > 0)) return false;  // not a convex hull: no bound
                const Point2 p = projectHomogeneous(pole);
                if (!p.allFinite()) return false;
                u0 = std::min(u0, p.x()), u1 = std::max(u1, p.x());
                v0 = std::min(v0, p.y()), v1 = std::max(v1, p.y());
            }
    if (!(u1 >= u0) || !(v1 >= v0)) return false;  // no trimming curve

    std::optional<BezierPatchGrid> own;
    const BezierPatchGrid& patches = given ? *given : own.emplace(face.surface);
    const auto& breaksU = patches.breakpointsU();
    const auto& breaksV = patches.breakpointsV();
    u0 = std::max(u0, breaksU.front()), u1 = std::min(u1, breaksU.back());
    v0 = std::max(v0, breaksV.front()), v1 = std::min(v1, breaksV.back());
    if (!(u1 > u0) || !(v1 > v0)) return false;
    for (int su = patches.spanIndexU(u0); su <= patches.spanIndexU(u1); ++su) {
        const double a0 = std::max(u0, breaksU[su]), a1 = std::min(u1, breaksU[su + 1]);
        if (!(a1 > a0)) continue;
        for (int sv = patches.spanIndexV(v0); sv <= patches.spanIndexV(v1); ++sv) {
            const double b0 = std::max(v0, breaksV[sv]), b1 = std::min(v1, breaksV[sv + 1]);
            if (!(b1 > b0)) continue;
            if (!visit(patches.piece(su, sv, a0, a1, b0, b1))) return true;
        }
    }
    return true;
}

}  // namespace

double faceSurfaceNeed(const TrimmedSurface& face, ErrorMode mode, double cap,
                       const BezierPatchGrid* patches) {
    constexpr double kUnknown = std::numeric_limits<double>::infinity();
    double need = 0;
    const bool known = forEachTrimmedPiece(face, patches, [&](const BezierPatch& piece) {
        // the kd-tree's measure of a cell that the trimming curves may cross (the larger one)
        const double error = cellErrorBound(piece, mode, cap, true).measure(mode, true);
        need = error <= cap ? std::max(need, error) : kUnknown;
        return error <= cap;
    });
    return known ? need : kUnknown;
}

double surfaceCellEstimate(const TrimmedSurface& face, ErrorMode mode, double share,
                           const BezierPatchGrid* patches) {
    double cells = 0;
    const bool known = forEachTrimmedPiece(face, patches, [&](const BezierPatch& piece) {
        const double error = cellErrorBound(piece, mode, share, true).measure(mode, true);
        cells += std::isfinite(error) ? std::max(1.0, error / share) : 1.0;
        return true;
    });
    return known ? cells : 0;
}

}  // namespace nurbslod
