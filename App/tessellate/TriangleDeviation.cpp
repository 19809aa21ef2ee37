#include "tessellate/TriangleDeviation.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "geometry/TriangularBezierPatch.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {

namespace {

// The part of the convex polygon `polygon` inside the box [low, high] (Sutherland-Hodgman, one
// side of the box at a time).
std::vector<Point2> clipToBox(std::vector<Point2> polygon, const Point2& low, const Point2& high) {
    for (int side = 0; side < 4 && !polygon.empty(); ++side) {
        const int axis = side % 2;
        const bool keepAbove = side < 2;
        const double border = keepAbove ? low[axis] : high[axis];
        auto inside = [&](const Point2& p) {
            return keepAbove ? p[axis] >= border : p[axis] <= border;
        };
        std::vector<Point2> kept;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Point2& a = polygon[i];
            const Point2& b = polygon[(i + 1) % polygon.size()];
            if (inside(a)) kept.push_back(a);
            if (inside(a) != inside(b)) {
                const double f = (border - a[axis]) / (b[axis] - a[axis]);
                Point2 crossing = a + f * (b - a);
                crossing[axis] = border;
                kept.push_back(crossing);
            }
        }
        polygon = std::move(kept);
    }
    return polygon;
}

// The bound over `part` against the flat triangle `image`, halved at its longest side (in
// space) while over the target, `halvings` times at most.
double boundOver(const TriangularBezierPatch& part, const std::array<Point3, 3>& image,
                 double target, int halvings) {
    const double hull = part.farthestFromAffine(image);
    if (hull <= target || halvings <= 0) return hull;
    int side = 0;
    for (int k = 1; k < 3; ++k)
        if ((image[(k + 1) % 3] - image[k]).squaredNorm() >
            (image[(side + 1) % 3] - image[side]).squaredNorm())
            side = k;
    const int next = (side + 1) % 3;
    // the affine map takes the side's middle to the middle of its image
    const Point3 middle = 0.5 * (image[side] + image[next]);
    std::array<Point3, 3> first = image, second = image;
    first[next] = middle;
    second[side] = middle;
    const auto halves = part.halves(side);
    double bound = boundOver(halves[0], first, target, halvings - 1);
    if (!(bound <= target)) return bound;
    bound = std::max(bound, boundOver(halves[1], second, target, halvings - 1));
    // each half's hull is a true bound, and so is the whole's: keep the smaller
    return std::min(bound, hull);
}

}  // namespace

double triangleDeviation(const BezierPatch& patch, const std::array<Point2, 3>& corner,
                         const std::array<Point3, 3>& image, double target, int halvings) {
    return boundOver(TriangularBezierPatch(patch, corner), image, target, halvings);
}

std::optional<double> triangleDeviation(const BezierPatchGrid& patches,
                                        const std::array<Point2, 3>& uv,
                                        const TriangleAffineMap& affineAt, double target,
                                        std::size_t mostPieces) {
    const BezierPatch& first = patches.patch(0, 0);
    if (first.degreeU() + first.degreeV() > TriangularBezierPatch::kMostDegree) return std::nullopt;
    const Point2 low = uv[0].cwiseMin(uv[1]).cwiseMin(uv[2]);
    const Point2 high = uv[0].cwiseMax(uv[1]).cwiseMax(uv[2]);
    const int u0 = patches.spanIndexU(low.x()), u1 = patches.spanIndexU(high.x());
    const int v0 = patches.spanIndexV(low.y()), v1 = patches.spanIndexV(high.y());
    if (static_cast<std::size_t>(u1 - u0 + 1) * static_cast<std::size_t>(v1 - v0 + 1) > mostPieces)
        return std::nullopt;
    const auto& breaksU = patches.breakpointsU();
    const auto& breaksV = patches.breakpointsV();
    // pieces thinner than this share of the triangle's area hold no surface worth a bound of
    // their own (their sides are bounded with their neighbours')
    const double leastArea = 1e-12 * affineAt.doubleArea();
    double bound = 0;
    for (int su = u0; su <= u1; ++su)
        for (int sv = v0; sv <= v1; ++sv) {
            const Point2 from(breaksU[su], breaksV[sv]), to(breaksU[su + 1], breaksV[sv + 1]);
            const std::vector<Point2> piece = (su == u0 && su == u1 && sv == v0 && sv == v1)
                                                  ? std::vector<Point2>{uv[0], uv[1], uv[2]}
                                                  : clipToBox({uv[0], uv[1], uv[2]}, from, to);
            if (piece.size() < 3) continue;
            const Point2 size = to - from;
            auto local = [&](const Point2& q) -> Point2 { return (q - from).cwiseQuotient(size); };
            // the hull over the piece's box first: a few times cheaper than the triangles', and
            // enough for most pieces
            {
                Point2 boxLow = piece[0], boxHigh = piece[0];
                for (const Point2& q : piece)
                    boxLow = boxLow.cwiseMin(q), boxHigh = boxHigh.cwiseMax(q);
                if (boxLow.x() < boxHigh.x() && boxLow.y() < boxHigh.y()) {
                    const BezierPatch box =
                        patches.piece(su, sv, boxLow.x(), boxHigh.x(), boxLow.y(), boxHigh.y());
                    const double hull =
                        affineDeviation(box, affineAt(boxLow), affineAt({boxHigh.x(), boxLow.y()}),
                                        affineAt({boxLow.x(), boxHigh.y()}),
                                        std::numeric_limits<double>::infinity(),
                                        {Point2(0, 0), Point2(1, 0), Point2(0, 1)});
                    if (hull <= target) {
                        bound = std::max(bound, hull);
                        continue;
                    }
                }
            }
            for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
                const Point2 ab = piece[k] - piece[0], ac = piece[k + 1] - piece[0];
                if (!(std::abs(ab.x() * ac.y() - ab.y() * ac.x()) > leastArea)) continue;
                bound = std::max(
                    bound,
                    triangleDeviation(
                        patches.patch(su, sv),
                        {local(piece[0]), local(piece[k]), local(piece[k + 1])},
                        {affineAt(piece[0]), affineAt(piece[k]), affineAt(piece[k + 1])}, target));
                if (!(bound <= target)) return bound;
            }
        }
    return bound;
}

}  // namespace nurbslod
