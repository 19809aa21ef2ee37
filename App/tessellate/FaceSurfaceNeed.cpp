#include "tessellate/FaceSurfaceNeed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/BezierPatchGrid.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {

double faceSurfaceNeed(const TrimmedSurface& face, ErrorMode mode, double cap) {
    constexpr double kUnknown = std::numeric_limits<double>::infinity();
    double u0 = std::numeric_limits<double>::max(), v0 = u0, u1 = -u0, v1 = -u0;
    for (const auto& loop : face.loops)
        for (const auto& curve : loop.curves)
            for (const auto& pole : curve.pcurve.poles()) {
                if (!(pole.z() > 0)) return kUnknown;  // not a convex hull: no bound
                const Point2 p = projectHomogeneous(pole);
                if (!p.allFinite()) return kUnknown;
                u0 = std::min(u0, p.x()), u1 = std::max(u1, p.x());
                v0 = std::min(v0, p.y()), v1 = std::max(v1, p.y());
            }
    if (!(u1 >= u0) || !(v1 >= v0)) return kUnknown;  // no trimming curve

    const BezierPatchGrid patches(face.surface);
    const auto& breaksU = patches.breakpointsU();
    const auto& breaksV = patches.breakpointsV();
    u0 = std::max(u0, breaksU.front()), u1 = std::min(u1, breaksU.back());
    v0 = std::max(v0, breaksV.front()), v1 = std::min(v1, breaksV.back());
    if (!(u1 > u0) || !(v1 > v0)) return kUnknown;
    double need = 0;
    for (int su = patches.spanIndexU(u0); su <= patches.spanIndexU(u1); ++su) {
        const double a0 = std::max(u0, breaksU[su]), a1 = std::min(u1, breaksU[su + 1]);
        if (!(a1 > a0)) continue;
        for (int sv = patches.spanIndexV(v0); sv <= patches.spanIndexV(v1); ++sv) {
            const double b0 = std::max(v0, breaksV[sv]), b1 = std::min(v1, breaksV[sv + 1]);
            if (!(b1 > b0)) continue;
            const BezierPatch piece = patches.piece(su, sv, a0, a1, b0, b1);
            // the kd-tree's measure of a cell that the trimming curves may cross (the larger one)
            const double error = cellErrorBound(piece, mode, cap, true).measure(mode, true);
            if (!(error <= cap)) return kUnknown;
            need = std::max(need, error);
        }
    }
    return need;
}

}  // namespace nurbslod
