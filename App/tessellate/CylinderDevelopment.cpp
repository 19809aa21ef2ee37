#include "tessellate/CylinderDevelopment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "tessellate/RingTriangulation.hpp"

namespace nurbslod {

namespace {

constexpr double kPi = std::numbers::pi;

// a step of the angle brought into (-pi, pi]
double wrapped(double step) {
    return step - 2 * kPi * std::round(step / (2 * kPi));
}

// A point's angle about the axis (in (-pi, pi]) and its height along it.
Point2 angleAndHeight(const CylinderFrame& frame, const Point3& p) {
    const Vector3 d = p - frame.origin;
    return {std::atan2(d.dot(frame.e2), d.dot(frame.e1)), d.dot(frame.axis)};
}

double cross(const Point2& a, const Point2& b, const Point2& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

using Triangle = std::array<std::uint32_t, 3>;

// How far a triangle's corners spread about the axis (their unwrapped angles).
double spanOf(const std::vector<double>& angles, std::uint32_t a, std::uint32_t b,
              std::uint32_t c) {
    return std::max({angles[a], angles[b], angles[c]}) -
           std::min({angles[a], angles[b], angles[c]});
}

// Whether d lies inside the circle through a, b, c (counter-clockwise).
bool insideCircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
    const Point2 p = a - d, q = b - d, r = c - d;
    const double det = p.squaredNorm() * (q.x() * r.y() - q.y() * r.x()) -
                       q.squaredNorm() * (p.x() * r.y() - p.y() * r.x()) +
                       r.squaredNorm() * (p.x() * q.y() - p.y() * q.x());
    const double scale = p.squaredNorm() * q.norm() * r.norm() +
                         q.squaredNorm() * p.norm() * r.norm() +
                         r.squaredNorm() * p.norm() * q.norm();
    return det > 1e-12 * scale;
}

// Lawson's flips over a triangulation of a polygon: an inner side whose two triangles make a
// convex quadrilateral is replaced by the other diagonal where `better(a, b, c, d)` says so, for
// the triangles (a, b, c) and (b, a, d) becoming (a, d, c) and (d, b, c). Each flip checks the
// four sides around it again. `most` flips at most: a criterion evaluated in floating point may
// disagree with itself near a tie.
template <typename Better>
void flipWhere(std::vector<Triangle>& triangles, const std::vector<Point2>& at, Better better,
               std::size_t most) {
    constexpr std::uint32_t kNone = ~std::uint32_t(0);
    // neighbour[t][i]: the triangle across side i, from corner i to corner i + 1
    std::vector<std::array<std::uint32_t, 3>> neighbour(triangles.size(), {kNone, kNone, kNone});
    {
        struct Side {
            std::uint32_t low, high, triangle;
            int index;
        };
        std::vector<Side> sides;
        sides.reserve(3 * triangles.size());
        for (std::uint32_t t = 0; t < triangles.size(); ++t)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
                sides.push_back({std::min(a, b), std::max(a, b), t, i});
            }
        std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
            return std::tie(x.low, x.high) < std::tie(y.low, y.high);
        });
        for (std::size_t k = 0; k + 1 < sides.size(); ++k)
            if (sides[k].low == sides[k + 1].low && sides[k].high == sides[k + 1].high) {
                neighbour[sides[k].triangle][sides[k].index] = sides[k + 1].triangle;
                neighbour[sides[k + 1].triangle][sides[k + 1].index] = sides[k].triangle;
            }
    }
    auto sideFrom = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
        for (int i = 0; i < 3; ++i)
            if (triangles[t][i] == a && triangles[t][(i + 1) % 3] == b) return i;
        return -1;
    };
    // a side as its two corners in its triangle's order, so that a flip since is noticed
    struct Pending {
        std::uint32_t triangle, from, to;
    };
    std::vector<Pending> pending;
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (int i = 0; i < 3; ++i)
            if (neighbour[t][i] != kNone && neighbour[t][i] > t)
                pending.push_back({t, triangles[t][i], triangles[t][(i + 1) % 3]});
    std::size_t flips = 0;
    while (!pending.empty() && flips < most) {
        const Pending side = pending.back();
        pending.pop_back();
        const std::uint32_t t = side.triangle;
        const int i = sideFrom(t, side.from, side.to);
        if (i < 0) continue;
        const std::uint32_t o = neighbour[t][i];
        if (o == kNone) continue;
        const std::uint32_t a = side.from, b = side.to, c = triangles[t][(i + 2) % 3];
        const int j = sideFrom(o, b, a);
        if (j < 0) continue;
        const std::uint32_t d = triangles[o][(j + 2) % 3];
        if (c == d || !better(a, b, c, d)) continue;
        if (!(cross(at[a], at[d], at[c]) > 0) || !(cross(at[d], at[b], at[c]) > 0)) continue;
        const std::uint32_t acrossBC = neighbour[t][(i + 1) % 3],
                            acrossCA = neighbour[t][(i + 2) % 3],
                            acrossAD = neighbour[o][(j + 1) % 3],
                            acrossDB = neighbour[o][(j + 2) % 3];
        triangles[t] = {a, d, c};
        neighbour[t] = {acrossAD, o, acrossCA};
        triangles[o] = {d, b, c};
        neighbour[o] = {acrossDB, acrossBC, t};
        // the two triangles that changed sides point at the new one
        if (acrossAD != kNone)
            if (const int k = sideFrom(acrossAD, d, a); k >= 0) neighbour[acrossAD][k] = t;
        if (acrossBC != kNone)
            if (const int k = sideFrom(acrossBC, c, b); k >= 0) neighbour[acrossBC][k] = o;
        pending.push_back({t, a, d});
        pending.push_back({t, c, a});
        pending.push_back({o, d, b});
        pending.push_back({o, b, c});
        ++flips;
    }
}

// Ear clipping leaves fans, which the bound refuses in a narrow strip whose zigzag it accepts.
// Flips to the Delaunay triangulation of the unrolled polygon first (Lawson's flips reach it
// from any triangulation): it joins each point to its nearest across a strip. Then flips that
// lower the wider angle span of two triangles, which leave the others as they were, so the spans
// sorted from the widest fall and those flips end.
void narrowBySpan(std::vector<Triangle>& triangles, const std::vector<Point2>& unrolled,
                  const std::vector<double>& angles) {
    const std::size_t most = 64 * triangles.size() + 64;
    flipWhere(
        triangles, unrolled,
        [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
            return insideCircle(unrolled[a], unrolled[b], unrolled[c], unrolled[d]);
        },
        most);
    auto span = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return spanOf(angles, a, b, c);
    };
    flipWhere(
        triangles, unrolled,
        [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
            const double before = std::max(span(a, b, c), span(b, a, d));
            const double after = std::max(span(a, d, c), span(d, b, c));
            return after < before * (1 - 1e-12);
        },
        most);
}

}  // namespace

std::optional<CylinderFrame> faceCylinderFrame(const BSplineSurface& surface,
                                               const Cylinder& cylinder, double flatness) {
    if (!(cylinder.radius > 0) || !std::isfinite(cylinder.radius) || !cylinder.origin.allFinite() ||
        !cylinder.axis.allFinite() || !(flatness >= 0))
        return std::nullopt;
    CylinderFrame frame;
    frame.origin = cylinder.origin;
    frame.axis = cylinder.axis.normalized();
    if (!frame.axis.allFinite()) return std::nullopt;
    frame.e1 = frame.axis.unitOrthogonal();
    frame.e2 = frame.axis.cross(frame.e1);
    frame.radius = cylinder.radius;
    const auto spansU = surface.knotsU().breakpoints();
    const auto spansV = surface.knotsV().breakpoints();
    if (spansU.size() < 2 || spansV.size() < 2) return std::nullopt;
    double side = 0;
    for (std::size_t i = 0; i + 1 < spansU.size(); ++i)
        for (std::size_t j = 0; j + 1 < spansV.size(); ++j)
            for (int s = 0; s <= 4; ++s)
                for (int t = 0; t <= 4; ++t) {
                    const double u = spansU[i] + (spansU[i + 1] - spansU[i]) * s / 4;
                    const double v = spansV[j] + (spansV[j + 1] - spansV[j]) * t / 4;
                    const auto d = surface.derivatives(u, v);
                    Vector3 radial = d.point - frame.origin;
                    radial -= radial.dot(frame.axis) * frame.axis;
                    if (!(std::abs(radial.norm() - frame.radius) <= flatness)) return std::nullopt;
                    if (s == 2 && t == 2) side += d.du.cross(d.dv).dot(radial);
                }
    if (!(std::abs(side) > 0) || !std::isfinite(side)) return std::nullopt;
    frame.side = side > 0 ? 1 : -1;
    return frame;
}

double unrolledTriangleBound(double radius, double angle) {
    return radius * angle * angle / 8;
}

std::optional<UnrolledTriangles> triangulateUnrolled(
    const CylinderFrame& frame, const std::vector<std::vector<Point3>>& rings) {
    if (rings.empty()) return std::nullopt;
    // each ring's angles unwrapped along it: a ring must come back to its first angle
    std::vector<std::vector<Point2>> unwrapped;
    std::vector<double> areas;
    for (const auto& ring : rings) {
        if (ring.size() < 3) return std::nullopt;
        std::vector<Point2> points;
        double previous = 0;
        for (const Point3& p : ring) {
            if (!p.allFinite()) return std::nullopt;
            Point2 at = angleAndHeight(frame, p);
            const double raw = at.x();
            if (!points.empty()) {
                const double step = wrapped(raw - previous);
                // a step near half a turn could unwrap either way; up to three eighths it is
                // clear (a quarter was too tight: a quarter cylinder's two chords of exactly a
                // quarter turn passed with the surface's points and failed with the shared ones)
                if (!(std::abs(step) <= 0.75 * kPi)) return std::nullopt;
                at.x() = points.back().x() + step;
            }
            previous = raw;
            points.push_back(at);
        }
        const double closing = wrapped(points.front().x() - previous);
        if (!(std::abs(points.back().x() + closing - points.front().x()) < 1e-6))
            return std::nullopt;
        double twiceArea = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Point2& a = points[i];
            const Point2& b = points[(i + 1) % points.size()];
            twiceArea += a.x() * b.y() - b.x() * a.y();
        }
        areas.push_back(std::abs(twiceArea));
        unwrapped.push_back(std::move(points));
    }
    // a hole's turn: the one that puts its angles within the outer ring's, which must be less
    // than a turn wide for that to be the only one
    const std::size_t outer =
        static_cast<std::size_t>(std::max_element(areas.begin(), areas.end()) - areas.begin());
    auto rangeOf = [](const std::vector<Point2>& ring) {
        double low = ring.front().x(), high = low;
        for (const Point2& p : ring) low = std::min(low, p.x()), high = std::max(high, p.x());
        return std::pair{low, high};
    };
    const auto [outerLow, outerHigh] = rangeOf(unwrapped[outer]);
    for (std::size_t r = 0; r < unwrapped.size(); ++r) {
        if (r == outer) continue;
        if (!(outerHigh - outerLow < 2 * kPi)) return std::nullopt;
        const auto [low, high] = rangeOf(unwrapped[r]);
        const double turn = 2 * kPi * std::round((outerLow + outerHigh - low - high) / (4 * kPi));
        if (!(low + turn >= outerLow && high + turn <= outerHigh)) return std::nullopt;
        for (Point2& p : unwrapped[r]) p.x() += turn;
    }
    // the unrolled plane: arc length along the circle (the way du x dv points), height
    std::vector<std::vector<Point2>> unrolledRings;
    std::vector<Point2> unrolled;
    std::vector<double> angles;
    for (const auto& ring : unwrapped) {
        unrolledRings.emplace_back();
        for (const Point2& p : ring) {
            const Point2 q(frame.side * frame.radius * p.x(), p.y());
            unrolledRings.back().push_back(q);
            unrolled.push_back(q);
            angles.push_back(p.x());
        }
    }
    auto triangles = triangulateRings(unrolledRings);
    if (!triangles) return std::nullopt;
    narrowBySpan(*triangles, unrolled, angles);
    UnrolledTriangles result;
    for (const auto& t : *triangles)
        result.bounds.push_back(
            unrolledTriangleBound(frame.radius, spanOf(angles, t[0], t[1], t[2])));
    result.triangles = std::move(*triangles);
    return result;
}

std::optional<ChordFractions> chordPointsForUnrolledBound(
    const CylinderFrame& frame, const std::vector<std::vector<Point3>>& rings, double surfaceShare,
    std::size_t fewerThan, const UnrolledTriangles* first) {
    if (fewerThan == 0 || !(surfaceShare > 0)) return std::nullopt;
    ChordFractions added(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) added[r].resize(rings[r].size());
    std::size_t addedCount = 0;
    // where each point of a round's rings comes from: its ring's side and fraction along it
    struct Source {
        std::size_t ring, side;
        double t;  // 0 for the side's first point
    };
    for (int round = 0; round < 12; ++round) {
        std::vector<std::vector<Point3>> withAdded;
        std::vector<Source> sources;
        std::vector<std::size_t> ringStart;
        for (std::size_t r = 0; r < rings.size(); ++r) {
            const std::size_t n = rings[r].size();
            ringStart.push_back(sources.size());
            withAdded.emplace_back();
            for (std::size_t i = 0; i < n; ++i) {
                const Point3& first = rings[r][i];
                withAdded.back().push_back(first);
                sources.push_back({r, i, 0});
                const Point3& second = rings[r][(i + 1) % n];
                for (const double t : added[r][i]) {
                    withAdded.back().push_back((1 - t) * first + t * second);
                    sources.push_back({r, i, t});
                }
            }
        }
        std::optional<UnrolledTriangles> own;
        if (round > 0 || !first) {
            own = triangulateUnrolled(frame, withAdded);
            if (!own) return std::nullopt;
        }
        const UnrolledTriangles* unrolled = own ? &*own : first;
        // the sides of the round's rings from point k to the next, and to k from the one before
        auto endOf = [&](std::size_t k) {
            const std::size_t ring = sources[k].ring;
            return ring + 1 < ringStart.size() ? ringStart[ring + 1] : sources.size();
        };
        auto nextOf = [&](std::size_t k) {
            return k + 1 < endOf(k) ? k + 1 : ringStart[sources[k].ring];
        };
        auto previousOf = [&](std::size_t k) {
            return k > ringStart[sources[k].ring] ? k - 1 : endOf(k) - 1;
        };
        ChordFractions halves(rings.size());
        for (std::size_t r = 0; r < rings.size(); ++r) halves[r].resize(rings[r].size());
        bool over = false;
        for (std::size_t t = 0; t < unrolled->triangles.size(); ++t) {
            if (unrolled->bounds[t] <= surfaceShare) continue;
            over = true;
            for (const std::uint32_t corner : unrolled->triangles[t])
                for (const std::size_t k : {previousOf(corner), std::size_t(corner)}) {
                    const Source& from = sources[k];
                    const Source& to = sources[nextOf(k)];
                    const double end = to.side == from.side && to.t > from.t ? to.t : 1.0;
                    halves[from.ring][from.side].push_back(0.5 * (from.t + end));
                }
        }
        if (!over) return added;
        for (std::size_t r = 0; r < rings.size(); ++r)
            for (std::size_t i = 0; i < halves[r].size(); ++i) {
                auto& list = added[r][i];
                for (const double t : halves[r][i])
                    if (std::find(list.begin(), list.end(), t) == list.end()) {
                        list.push_back(t);
                        ++addedCount;
                    }
                std::sort(list.begin(), list.end());
            }
        if (addedCount >= fewerThan) return std::nullopt;
    }
    return std::nullopt;
}

bool keepsBound(const UnrolledTriangles& unrolled, double surfaceShare) {
    return surfaceShare > 0 && std::all_of(unrolled.bounds.begin(), unrolled.bounds.end(),
                                           [&](double bound) { return bound <= surfaceShare; });
}

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulateOnCylinder(
    const CylinderFrame& frame, const std::vector<std::vector<Point3>>& rings,
    double surfaceShare) {
    auto unrolled = triangulateUnrolled(frame, rings);
    if (!unrolled || !keepsBound(*unrolled, surfaceShare)) return std::nullopt;
    return std::move(unrolled->triangles);
}

}  // namespace nurbslod
