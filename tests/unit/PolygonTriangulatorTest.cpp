#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <clipper.hpp>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "tessellate/PolygonTriangulator.hpp"

using nurbslod::IntegerPoint2;
using nurbslod::triangulatePolygon;
using nurbslod::Triangulation;

namespace {

__extension__ typedef __int128 Int128;

using Ring = std::vector<IntegerPoint2>;
using Rings = std::vector<Ring>;

Int128 twiceTriangleArea(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return (Int128(b.x) - a.x) * (Int128(c.y) - a.y) - (Int128(b.y) - a.y) * (Int128(c.x) - a.x);
}

Int128 twiceSignedArea(const Ring& ring) {
    Int128 sum = 0;
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
        sum += twiceTriangleArea(ring[0], ring[i], ring[i + 1]);
    }
    return sum;
}

Int128 magnitude(Int128 value) {
    return value < 0 ? -value : value;
}

// Twice the area of the polygon: the outer ring's minus the holes', whatever their orientation.
Int128 twicePolygonArea(const Rings& rings) {
    Int128 area = magnitude(twiceSignedArea(rings[0]));
    for (std::size_t r = 1; r < rings.size(); ++r) area -= magnitude(twiceSignedArea(rings[r]));
    return area;
}

Ring flatten(const Rings& rings) {
    Ring points;
    for (const Ring& ring : rings) points.insert(points.end(), ring.begin(), ring.end());
    return points;
}

using Key = std::pair<std::int64_t, std::int64_t>;
using DirectedEdge = std::pair<Key, Key>;
Key keyOf(const IntegerPoint2& p) {
    return {p.x, p.y};
}

// The ring edges with the polygon on their left: the outer ring counter-clockwise, holes
// clockwise, repeated points skipped. An edge that also occurs reversed is left out with its
// twin: there a hole touches the outer ring (or another hole) along a segment, as Clipper emits,
// and no area lies on either side.
std::set<DirectedEdge> boundaryEdges(const Rings& rings) {
    std::multiset<DirectedEdge> edges;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        Ring ring = rings[r];
        const bool counterClockwise = twiceSignedArea(ring) > 0;
        if (counterClockwise != (r == 0)) std::reverse(ring.begin(), ring.end());
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const IntegerPoint2& p = ring[i];
            const IntegerPoint2& q = ring[(i + 1) % ring.size()];
            if (!(p == q)) edges.insert({keyOf(p), keyOf(q)});
        }
    }
    std::set<DirectedEdge> boundary;
    for (const DirectedEdge& edge : edges) {
        if (!edges.count({edge.second, edge.first})) boundary.insert(edge);
    }
    return boundary;
}

// Checks everything a triangulation of a valid polygon with holes must satisfy: indices in range,
// every triangle counter-clockwise with positive area, areas summing exactly to the polygon's
// area, every point of the boundary used, and the triangles fitting together: each boundary edge
// is used once in its direction and never against it, every other edge once in each direction.
// Together these leave no room for overlaps or gaps.
void expectValidTriangulation(const Rings& rings, const Triangulation& result) {
    const Ring points = flatten(rings);
    EXPECT_TRUE(result.complete);
    Int128 areaSum = 0;
    std::map<DirectedEdge, int> edgeUses;
    std::set<Key> usedPoints;
    for (const auto& triangle : result.triangles) {
        for (const std::uint32_t index : triangle) ASSERT_LT(index, points.size());
        const IntegerPoint2& a = points[triangle[0]];
        const IntegerPoint2& b = points[triangle[1]];
        const IntegerPoint2& c = points[triangle[2]];
        const Int128 area = twiceTriangleArea(a, b, c);
        ASSERT_GT(area, 0) << "triangle " << triangle[0] << " " << triangle[1] << " " << triangle[2]
                           << " is not counter-clockwise with positive area";
        areaSum += area;
        for (int k = 0; k < 3; ++k) {
            ++edgeUses[{keyOf(points[triangle[k]]), keyOf(points[triangle[(k + 1) % 3]])}];
            usedPoints.insert(keyOf(points[triangle[k]]));
        }
    }
    EXPECT_TRUE(areaSum == twicePolygonArea(rings))
        << "the triangles' areas differ from the polygon's";

    const std::set<DirectedEdge> boundary = boundaryEdges(rings);
    for (const DirectedEdge& edge : boundary) {
        EXPECT_EQ(edgeUses.count(edge) ? edgeUses[edge] : 0, 1)
            << "a ring edge is not covered once";
        EXPECT_TRUE(usedPoints.count(edge.first))
            << "point (" << edge.first.first << ", " << edge.first.second << ") unused";
    }
    for (const auto& [edge, uses] : edgeUses) {
        EXPECT_EQ(uses, 1) << "an edge is used twice in one direction: triangles overlap";
        const DirectedEdge reverse{edge.second, edge.first};
        if (boundary.count(edge)) {
            EXPECT_EQ(edgeUses.count(reverse), 0u) << "a triangle lies outside a ring edge";
        } else {
            EXPECT_EQ(edgeUses.count(reverse), 1u)
                << "an inner edge has a triangle on one side only";
        }
    }
}

// Points from (x0, y0) to (x1, y1), end excluded, with count points in all.
Ring straightRun(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1, int count) {
    Ring run;
    for (int i = 0; i < count; ++i)
        run.push_back({x0 + (x1 - x0) * i / count, y0 + (y1 - y0) * i / count});
    return run;
}

Ring square(std::int64_t x, std::int64_t y, std::int64_t size) {
    return {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
}

// The rings as C++ source, so that a failing random case can become a test of its own.
std::string describe(const Rings& rings) {
    std::ostringstream text;
    text << "{";
    for (const Ring& ring : rings) {
        text << "{";
        for (const IntegerPoint2& p : ring) text << "{" << p.x << ", " << p.y << "}, ";
        text << "}, ";
    }
    text << "}";
    return text.str();
}

Ring reversed(Ring ring) {
    std::reverse(ring.begin(), ring.end());
    return ring;
}

// A random polygon star-shaped around (centerX, centerY), points on a grid of the given spacing.
ClipperLib::Path randomStar(std::mt19937_64& random, double centerX, double centerY, double radius,
                            double spacing) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int count = std::uniform_int_distribution<int>(3, 12)(random);
    ClipperLib::Path star;
    for (int i = 0; i < count; ++i) {
        const double angle = 2 * std::numbers::pi * (i + 0.8 * unit(random)) / count;
        const double r = radius * (0.3 + 0.7 * unit(random));
        star.push_back(
            {std::llround((centerX + r * std::cos(angle)) / spacing) * std::int64_t(spacing),
             std::llround((centerY + r * std::sin(angle)) / spacing) * std::int64_t(spacing)});
    }
    return star;
}

// Whether two passes of the boundary through one point cross there: each pass arrives from one
// neighbour and leaves towards another, and the passes cross when their directions interleave.
bool passesCross(const IntegerPoint2& point,
                 const std::vector<std::pair<IntegerPoint2, IntegerPoint2>>& passes) {
    const auto angle = [&](const IntegerPoint2& q) {
        return std::atan2(double(q.y - point.y), double(q.x - point.x));
    };
    for (std::size_t i = 0; i < passes.size(); ++i) {
        for (std::size_t j = i + 1; j < passes.size(); ++j) {
            const double low = std::min(angle(passes[i].first), angle(passes[i].second));
            const double high = std::max(angle(passes[i].first), angle(passes[i].second));
            const double a = angle(passes[j].first);
            const double b = angle(passes[j].second);
            if (a == low || a == high || b == low || b == high) continue;  // edges on one line
            if ((low < a && a < high) != (low < b && b < high)) return true;
        }
    }
    return false;
}

// Whether the rings cross themselves or each other: two edges crossing at a point inside both,
// a point inside an edge, two passes through a shared point that cross there, or an edge run
// twice the same way. Rings may share points and run along each other the opposite way where
// they touch (Clipper emits such rings).
bool ringsCross(const Rings& rings) {
    std::map<Key, std::vector<std::pair<IntegerPoint2, IntegerPoint2>>> passesThrough;
    for (const Ring& ring : rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            passesThrough[keyOf(ring[i])].push_back(
                {ring[(i + ring.size() - 1) % ring.size()], ring[(i + 1) % ring.size()]});
        }
    }
    for (const auto& [key, passes] : passesThrough) {
        if (passesCross({key.first, key.second}, passes)) return true;
    }
    // One edge twice in one direction (outer ring counter-clockwise, holes clockwise): the
    // winding number steps by two across it.
    std::set<DirectedEdge> directedEdges;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = rings[r];
        const bool reverse = (twiceSignedArea(ring) > 0) != (r == 0);
        for (std::size_t i = 0; i < ring.size(); ++i) {
            DirectedEdge edge{keyOf(ring[i]), keyOf(ring[(i + 1) % ring.size()])};
            if (reverse) std::swap(edge.first, edge.second);
            if (!directedEdges.insert(edge).second) return true;
        }
    }
    std::vector<std::pair<IntegerPoint2, IntegerPoint2>> edges;
    for (const Ring& ring : rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            if (!(ring[i] == ring[(i + 1) % ring.size()])) {
                edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
            }
        }
    }
    const auto sign = [](Int128 value) { return (value > 0) - (value < 0); };
    const auto isInside = [&](const IntegerPoint2& p, const IntegerPoint2& a,
                              const IntegerPoint2& b) {
        return sign(twiceTriangleArea(a, b, p)) == 0 && !(p == a) && !(p == b) &&
               std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
               std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
    };
    for (std::size_t i = 0; i < edges.size(); ++i) {
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const auto& [a, b] = edges[i];
            const auto& [c, d] = edges[j];
            if (isInside(c, a, b) || isInside(d, a, b) || isInside(a, c, d) || isInside(b, c, d)) {
                return true;
            }
            if (sign(twiceTriangleArea(a, b, c)) * sign(twiceTriangleArea(a, b, d)) < 0 &&
                sign(twiceTriangleArea(c, d, a)) * sign(twiceTriangleArea(c, d, b)) < 0) {
                return true;
            }
        }
    }
    return false;
}

// The winding number of ring around p, or nullopt when p lies on the ring.
std::optional<int> windingNumber(const IntegerPoint2& p, const Ring& ring) {
    int winding = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const IntegerPoint2& a = ring[i];
        const IntegerPoint2& b = ring[(i + 1) % ring.size()];
        const Int128 side = twiceTriangleArea(a, b, p);
        const bool between = std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
                             std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
        if (side == 0 && between) return std::nullopt;
        if (a.y <= p.y && p.y < b.y && side > 0) ++winding;
        if (b.y <= p.y && p.y < a.y && side < 0) --winding;
    }
    return winding;
}

// Whether every hole lies inside the outer ring and outside the other holes, judged at the
// midpoints of its edges (coordinates doubled to keep them integer). With rings that do not
// cross, that decides it.
bool holesLieInside(const Rings& rings) {
    const auto doubled = [](const Ring& ring) {
        Ring result;
        for (const IntegerPoint2& p : ring) result.push_back({2 * p.x, 2 * p.y});
        return result;
    };
    std::vector<Ring> doubledRings;
    for (const Ring& ring : rings) doubledRings.push_back(doubled(ring));
    for (std::size_t h = 1; h < rings.size(); ++h) {
        const Ring& hole = rings[h];
        for (std::size_t i = 0; i < hole.size(); ++i) {
            const IntegerPoint2& p = hole[i];
            const IntegerPoint2& q = hole[(i + 1) % hole.size()];
            const IntegerPoint2 midpoint{p.x + q.x, p.y + q.y};
            const std::optional<int> outer = windingNumber(midpoint, doubledRings[0]);
            if (outer && *outer == 0) return false;
            for (std::size_t other = 1; other < rings.size(); ++other) {
                if (other == h) continue;
                const std::optional<int> inOther = windingNumber(midpoint, doubledRings[other]);
                if (inOther && *inOther != 0) return false;
            }
        }
    }
    return true;
}

void collectPolygons(const ClipperLib::PolyNode& node, std::vector<Rings>& polygons) {
    for (const ClipperLib::PolyNode* child : node.Childs) {
        if (child->IsHole()) continue;
        Rings rings;
        const auto toRing = [](const ClipperLib::Path& path) {
            Ring ring;
            for (const ClipperLib::IntPoint& p : path) ring.push_back({p.X, p.Y});
            return ring;
        };
        rings.push_back(toRing(child->Contour));
        for (const ClipperLib::PolyNode* hole : child->Childs) {
            rings.push_back(toRing(hole->Contour));
            collectPolygons(*hole, polygons);  // islands inside the holes
        }
        polygons.push_back(rings);
    }
}

}  // namespace

TEST(PolygonTriangulator, RectangleGivesTwoTriangles) {
    const Rings rings{{{0, 0}, {10, 0}, {10, 5}, {0, 5}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 2u);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, RectangleWithHangingPointsUsesEveryPointWithoutZeroAreaTriangles) {
    // A kd-tree cell whose smaller neighbours put 3, 1, 4 and 2 extra points on its sides.
    Ring cell;
    for (const Ring& side : {straightRun(0, 0, 800, 0, 4), straightRun(800, 0, 800, 400, 2),
                             straightRun(800, 400, 0, 400, 5), straightRun(0, 400, 0, 0, 3)}) {
        cell.insert(cell.end(), side.begin(), side.end());
    }
    ASSERT_EQ(cell.size(), 14u);
    const Rings rings{cell};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), cell.size() - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, LongCellWithHangingPointsGivesNoSlivers) {
    // A fan from a corner would give triangles 100 long and 1 wide; the zigzag of paper
    // section 7 pairs points across the cell instead.
    Ring cell = straightRun(0, 0, 100, 0, 10);
    const Ring top = straightRun(100, 10, 0, 10, 10);
    cell.push_back({100, 0});
    cell.insert(cell.end(), top.begin(), top.end());
    cell.push_back({0, 10});
    const Triangulation result = triangulatePolygon({cell});
    EXPECT_EQ(result.triangles.size(), cell.size() - 2);
    expectValidTriangulation({cell}, result);
    for (const auto& triangle : result.triangles) {
        const IntegerPoint2& a = cell[triangle[0]];
        const IntegerPoint2& b = cell[triangle[1]];
        const IntegerPoint2& c = cell[triangle[2]];
        const auto squared = [](const IntegerPoint2& p, const IntegerPoint2& q) {
            return double((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
        };
        const double longestSquared = std::max({squared(a, b), squared(b, c), squared(c, a)});
        const double height = double(twiceTriangleArea(a, b, c)) / std::sqrt(longestSquared);
        EXPECT_GT(height, 4.0) << "a sliver: height " << height;
    }
}

TEST(PolygonTriangulator, TriangleWithHangingPointsOnOneSideAvoidsTheDegenerateFan) {
    // Fanning from the corner opposite the hanging points would leave a collinear remainder.
    for (int rotation = 0; rotation < 5; ++rotation) {
        Ring ring{{0, 0}, {25, 0}, {50, 0}, {75, 0}, {100, 0}, {50, 80}};
        std::rotate(ring.begin(), ring.begin() + rotation, ring.end());
        const Rings rings{ring};
        const Triangulation result = triangulatePolygon(rings);
        EXPECT_EQ(result.triangles.size(), 4u);
        expectValidTriangulation(rings, result);
    }
}

TEST(PolygonTriangulator, TriangleWithHangingPointsOnEverySide) {
    const Rings rings{{{0, 0}, {2, 0}, {4, 0}, {3, 2}, {2, 4}, {1, 2}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 4u);
    expectValidTriangulation(rings, result);
}

// Large enough for the ear test's index, which leaves straight nodes out: a triangle with 40
// hanging points on each side (straight nodes only, besides its corners), where an ear whose
// new side runs along a side of hanging points must still be refused; and a strip whose lower
// rim is straight and whose upper rim zigzags by one unit, as an unrolled cylinder's helix
// rounds to the integer grid.
TEST(PolygonTriangulator, ManyStraightNodesInTheIndexedEarTest) {
    Ring triangle;
    const std::array<IntegerPoint2, 3> corners{{{0, 0}, {8200, 0}, {4100, 8200}}};
    for (int side = 0; side < 3; ++side) {
        const IntegerPoint2& from = corners[side];
        const IntegerPoint2& to = corners[(side + 1) % 3];
        for (int k = 0; k < 41; ++k)
            triangle.push_back(
                {from.x + (to.x - from.x) * k / 41, from.y + (to.y - from.y) * k / 41});
    }
    Ring strip;
    for (int k = 0; k <= 200; ++k) strip.push_back({50 * k, 0});
    for (int k = 200; k >= 0; --k) strip.push_back({50 * k + 7, 3000 + (k % 2)});
    for (const Rings& rings : {Rings{triangle}, Rings{strip}}) {
        const Triangulation result = triangulatePolygon(rings);
        EXPECT_EQ(result.triangles.size(), rings.front().size() - 2);
        expectValidTriangulation(rings, result);
    }
}

TEST(PolygonTriangulator, ConvexPolygon) {
    const Rings rings{{{0, -10}, {7, -7}, {10, 0}, {7, 7}, {0, 10}, {-7, 7}, {-10, 0}, {-7, -7}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 6u);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, LShape) {
    const Rings rings{{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 30}, {0, 30}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 4u);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, Comb) {
    // Ten teeth pointing up from a spine, with the spine's top points between the teeth.
    Ring comb{{0, 0}, {100, 0}};
    for (int tooth = 9; tooth >= 0; --tooth) {
        const std::int64_t left = tooth * 10;
        comb.push_back({left + 6, 10});
        comb.push_back({left + 6, 50});
        comb.push_back({left + 2, 50});
        comb.push_back({left + 2, 10});
    }
    const Rings rings{comb};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), comb.size() - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, CollinearRunsInANonConvexPolygon) {
    // An L-shape whose sides carry many points, as straight trimming runs and hanging points do.
    Ring ring;
    for (const Ring& side : {straightRun(0, 0, 60, 0, 6), straightRun(60, 0, 60, 20, 4),
                             straightRun(60, 20, 20, 20, 8), straightRun(20, 20, 20, 60, 5),
                             straightRun(20, 60, 0, 60, 2), straightRun(0, 60, 0, 0, 7)}) {
        ring.insert(ring.end(), side.begin(), side.end());
    }
    const Rings rings{ring};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), ring.size() - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, OneHole) {
    const Rings rings{square(0, 0, 100), reversed(square(30, 40, 20))};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 8u + 2 * 1 - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, ThreeHolesInACellWithHangingPoints) {
    Ring cell;
    for (const Ring& side : {straightRun(0, 0, 120, 0, 3), straightRun(120, 0, 120, 60, 2),
                             straightRun(120, 60, 0, 60, 4), straightRun(0, 60, 0, 0, 1)}) {
        cell.insert(cell.end(), side.begin(), side.end());
    }
    // Holes of both orientations, one of them not convex.
    const Rings rings{cell,
                      square(10, 10, 20),
                      reversed(square(50, 20, 20)),
                      {{85, 10}, {100, 30}, {85, 50}, {85, 40}, {78, 20}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), flatten(rings).size() + 2 * 3 - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, HoleTouchingTheOuterRingAtItsRightmostPoint) {
    // Clipper emits a hole that touches its outer ring at a common vertex.
    const Rings rings{{{0, 0}, {10, 0}, {10, 5}, {10, 10}, {0, 10}}, {{10, 5}, {5, 3}, {5, 7}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 5u + 3 - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, HoleTouchingTheOuterRingAwayFromTheBridge) {
    const Rings rings{{{0, 0}, {4, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 0}, {3, 4}, {6, 3}}};
    const Triangulation result = triangulatePolygon(rings);
    // Seven distinct points, all on the boundary of a region with one hole: Euler's formula
    // V - E + T = 0 with 2E = 3T + 8 ring edges gives six triangles.
    EXPECT_EQ(result.triangles.size(), 6u);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, HolesTouchingEachOther) {
    const Rings rings{
        square(0, 0, 30), {{10, 10}, {15, 15}, {10, 20}}, {{15, 15}, {20, 10}, {20, 20}}};
    const Triangulation result = triangulatePolygon(rings);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, HoleLyingAgainstTheOuterRingAlongASegment) {
    // The hole shares the bottom edge's middle segment: a notch, no area on either side of it.
    const Rings rings{{{0, 0}, {4, 0}, {6, 0}, {10, 0}, {10, 10}, {0, 10}},
                      {{4, 0}, {5, 3}, {6, 0}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 7u - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, ContactsFoundInClipperOutput) {
    // Cases the randomized Clipper test found: a hole lying against its outer ring along two
    // edges, a hole touching its outer ring at three points (which cuts the polygon into three),
    // and a lobe hanging from the rest on a string of two edges run there and back.
    const std::vector<Rings> cases{
        {{{20, -9},
          {8, 16},
          {-13, 30},
          {-18, 30},
          {-15, 11},
          {-15, 10},
          {-15, 9},
          {-13, -6},
          {20, -17}},
         {{-15, 9},
          {-15, 10},
          {-15, 11},
          {-12, 13},
          {-5, 20},
          {3, 10},
          {-3, 9},
          {-8, 3},
          {-13, 2}}},
        {{{8, 13},
          {8, 14},
          {7, 15},
          {3, 18},
          {0, 16},
          {-9, 18},
          {-6, 14},
          {-7, 9},
          {-14, 6},
          {-12, 0},
          {3, 0},
          {18, 0}},
         {{-2, 8}, {-7, 9}, {7, 15}, {8, 13}, {11, 7}, {7, 4}}},
        {{{-20, 11},
          {-19, 12},
          {-18, 15},
          {-16, 16},
          {-12, 23},
          {-5, 24},
          {-8, 27},
          {-12, 23},
          {-13, 23},
          {-18, 15},
          {-19, 12},
          {-20, 11},
          {-22, 10},
          {-25, 9},
          {-25, 8},
          {-25, 1}}},
    };
    for (const Rings& rings : cases) {
        ASSERT_FALSE(ringsCross(rings));
        expectValidTriangulation(rings, triangulatePolygon(rings));
    }
}

TEST(PolygonTriangulator, HoleTouchingItselfAtItsRightmostPoint) {
    // Two hole lobes meet at the hole's rightmost point; the bridge must leave from the pass
    // that faces it.
    const Rings rings{
        square(-20, -20, 40),
        {{-12, -13}, {-9, -11}, {-15, -8}, {-15, -6}, {-14, -5}, {-10, -7}, {-9, -11}, {-10, -13}}};
    ASSERT_FALSE(ringsCross(rings));
    expectValidTriangulation(rings, triangulatePolygon(rings));
}

TEST(PolygonTriangulator, DuplicatePointsMapToOneVertex) {
    // A repeated corner, a repeated hanging point and a closing point equal to the first.
    const Rings rings{{{0, 0}, {5, 0}, {5, 0}, {10, 0}, {10, 10}, {10, 10}, {0, 10}, {0, 0}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 5u - 2);
    expectValidTriangulation(rings, result);
    for (const auto& triangle : result.triangles) {
        for (const std::uint32_t index : triangle) {
            EXPECT_NE(index, 2u);  // the lowest index of a repeated point is reported
            EXPECT_NE(index, 5u);
            EXPECT_NE(index, 7u);
        }
    }
}

TEST(PolygonTriangulator, ClockwiseInputGivesCounterClockwiseTriangles) {
    const Rings rings{reversed({{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 30}, {0, 30}}),
                      square(2, 2, 5)};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 10u + 2 - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, SpiralOfTwoThousandPointsIsFast) {
    // Two arms of an Archimedean spiral five turns long, 3000 units apart: a long, thin,
    // strongly non-convex polygon whose ears are hard to find.
    const int pointsPerArm = 1000;
    const double turns = 5;
    Ring outerArm, innerArm;
    for (int i = 0; i < pointsPerArm; ++i) {
        const double angle = turns * 2 * std::numbers::pi * i / (pointsPerArm - 1);
        const double radius = 5000 + 1000 * angle;
        outerArm.push_back(
            {std::llround(radius * std::cos(angle)), std::llround(radius * std::sin(angle))});
        innerArm.push_back({std::llround((radius - 3000) * std::cos(angle)),
                            std::llround((radius - 3000) * std::sin(angle))});
    }
    Ring spiral = outerArm;
    spiral.insert(spiral.end(), innerArm.rbegin(), innerArm.rend());
    const Rings rings{spiral};

    const auto begin = std::chrono::steady_clock::now();
    const Triangulation result = triangulatePolygon(rings);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();

    EXPECT_LT(seconds, 1.0);
    EXPECT_EQ(result.triangles.size(), spiral.size() - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, DegenerateInputGivesNoTriangles) {
    for (const Rings& rings : std::vector<Rings>{
             {},
             {{}},
             {{{1, 1}}},
             {{{0, 0}, {5, 5}}},
             {{{3, 3}, {3, 3}, {3, 3}, {3, 3}}},
             {{{0, 0}, {1, 1}, {2, 2}, {5, 5}, {3, 3}}},
             {{{0, 0}, {4, 0}, {0, 0}, {4, 0}}},
             {{{0, 0}, {0, 7}}, square(1, 1, 2)},
         }) {
        const Triangulation result = triangulatePolygon(rings);
        EXPECT_TRUE(result.triangles.empty());
        EXPECT_TRUE(result.complete);
    }
}

TEST(PolygonTriangulator, ZeroAreaHoleIsIgnored) {
    const Rings rings{square(0, 0, 10), {{2, 2}, {4, 4}, {6, 6}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 2u);
    EXPECT_TRUE(result.complete);
}

TEST(PolygonTriangulator, InvalidInputEndsAndSaysSo) {
    // A bow tie (self-intersecting), a hole outside the outer ring, overlapping holes, and a
    // coordinate beyond Clipper's range: none may crash or hang, and each is reported.
    const Rings bowTie{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
    const Rings holeOutside{square(0, 0, 10), square(20, 20, 5)};
    const Rings overlappingHoles{square(0, 0, 100), square(10, 10, 30), square(20, 20, 30)};
    const Rings outOfRange{{{0, 0}, {nurbslod::kMaximumTriangulationCoordinate + 1, 0}, {0, 1}}};
    for (const Rings& rings : {bowTie, holeOutside, overlappingHoles, outOfRange}) {
        const Triangulation result = triangulatePolygon(rings);
        EXPECT_FALSE(result.complete);
        const Ring points = flatten(rings);
        for (const auto& triangle : result.triangles) {
            for (const std::uint32_t index : triangle) ASSERT_LT(index, points.size());
            EXPECT_GT(
                twiceTriangleArea(points[triangle[0]], points[triangle[1]], points[triangle[2]]),
                0);
        }
    }
}

TEST(PolygonTriangulator, HugeCoordinatesAreExact) {
    // Near Clipper's range limit products of coordinate differences need all 128 bits, and the
    // bridge's ray cast needs more; doubles would misjudge these nearly collinear points.
    const std::int64_t big = std::int64_t(1) << 61;
    const Rings rings{{{-big, -big}, {0, -big}, {big, -big}, {big, big}, {1, big}, {-big, big}},
                      {{-3, -7}, {big / 2, 1}, {big / 2 + 1, big / 3}, {-5, big / 2 + 3}}};
    const Triangulation result = triangulatePolygon(rings);
    EXPECT_EQ(result.triangles.size(), 10u + 2 - 2);
    expectValidTriangulation(rings, result);
}

TEST(PolygonTriangulator, RandomConvexCellsWithHangingPoints) {
    std::mt19937_64 random(7);
    for (int trial = 0; trial < 300; ++trial) {
        const std::int64_t width = std::uniform_int_distribution<std::int64_t>(1, 1000)(random);
        const std::int64_t height = std::uniform_int_distribution<std::int64_t>(1, 1000)(random);
        const IntegerPoint2 corners[4] = {{0, 0}, {width, 0}, {width, height}, {0, height}};
        Ring cell;
        for (int side = 0; side < 4; ++side) {
            const IntegerPoint2& from = corners[side];
            const IntegerPoint2& to = corners[(side + 1) % 4];
            const std::int64_t length = std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
            std::set<std::int64_t> steps{0};
            const int extra = std::uniform_int_distribution<int>(0, 6)(random);
            for (int k = 0; k < extra && length > 1; ++k) {
                steps.insert(std::uniform_int_distribution<std::int64_t>(1, length - 1)(random));
            }
            for (const std::int64_t step : steps) {
                cell.push_back({from.x + (to.x - from.x) / length * step,
                                from.y + (to.y - from.y) / length * step});
            }
        }
        const Rings rings{trial % 2 ? reversed(cell) : cell};
        const Triangulation result = triangulatePolygon(rings);
        EXPECT_EQ(result.triangles.size(), cell.size() - 2);
        expectValidTriangulation(rings, result);
        if (HasFailure()) return;
    }
}

// Star-shaped polygons of fewest to most points with random square holes, triangulated
// soundly: every point used, no overlaps, the triangles' area the polygon's.
static void expectRandomStarShapedPolygonsWithSquareHoles(std::uint64_t seed, int trials,
                                                          int fewest, int most) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < trials; ++trial) {
        // A polygon star-shaped around the origin: points at increasing angles, random radii.
        // Coordinates are multiples of 4, so edge midpoints are integer hanging points.
        const int count = std::uniform_int_distribution<int>(fewest, most)(random);
        Ring star;
        for (int i = 0; i < count; ++i) {
            const double angle = 2 * std::numbers::pi * (i + 0.4 * unit(random)) / count;
            const double radius = 250000 * (0.5 + 0.5 * unit(random));
            star.push_back({4 * std::llround(radius * std::cos(angle)),
                            4 * std::llround(radius * std::sin(angle))});
        }
        // The disk around the origin up to the nearest edge lies inside the polygon.
        double inscribed = 1e300;
        for (int i = 0; i < count; ++i) {
            const IntegerPoint2& p = star[i];
            const IntegerPoint2& q = star[(i + 1) % count];
            const double length = std::hypot(double(q.x - p.x), double(q.y - p.y));
            inscribed =
                std::min(inscribed, std::abs(double(twiceTriangleArea({0, 0}, p, q))) / length);
        }
        Ring outer;
        for (int i = 0; i < count; ++i) {
            const IntegerPoint2& p = star[i];
            const IntegerPoint2& q = star[(i + 1) % count];
            outer.push_back(p);
            if (unit(random) < 0.3) outer.push_back({(p.x + q.x) / 2, (p.y + q.y) / 2});
        }
        if (trial % 3 == 0) outer = reversed(outer);
        Rings rings{outer};

        // Square holes in the cells of a 4 x 4 grid inside the inscribed disk.
        const double half = 0.65 * inscribed;
        const double cellSize = 2 * half / 4;
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column < 4; ++column) {
                if (unit(random) < 0.5) continue;
                const double size = cellSize * (0.2 + 0.6 * unit(random));
                // A margin keeps rounding from letting neighbouring holes touch.
                const double x =
                    -half + column * cellSize + 4 + (cellSize - size - 8) * unit(random);
                const double y = -half + row * cellSize + 4 + (cellSize - size - 8) * unit(random);
                const std::int64_t side = std::max<std::int64_t>(2, std::llround(size) / 2 * 2);
                Ring hole = square(std::llround(x), std::llround(y), side);
                if (unit(random) < 0.5)
                    hole.insert(hole.begin() + 1, {hole[0].x + side / 2, hole[0].y});
                if (unit(random) < 0.5) hole = reversed(hole);
                std::rotate(hole.begin(), hole.begin() + std::ptrdiff_t(random() % hole.size()),
                            hole.end());
                rings.push_back(hole);
            }
        }

        const Triangulation result = triangulatePolygon(rings);
        const std::size_t holeCount = rings.size() - 1;
        EXPECT_EQ(result.triangles.size(), flatten(rings).size() + 2 * holeCount - 2);
        expectValidTriangulation(rings, result);
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "trial " << trial << ": " << describe(rings);
            return;
        }
    }
}

TEST(PolygonTriangulator, RandomStarShapedPolygonsWithSquareHoles) {
    expectRandomStarShapedPolygonsWithSquareHoles(2004, 400, 4, 40);
}

// Rings of more than 80 nodes take the ear test's index of the nodes that turn right or repeat
// a point: the same checks.
TEST(PolygonTriangulator, RandomStarShapedPolygonsOfManyPointsWithSquareHoles) {
    expectRandomStarShapedPolygonsWithSquareHoles(2026, 100, 81, 600);
}

TEST(PolygonTriangulator, ClipperOutputOfCellsClippedByRandomTrimmingRegions) {
    // What the tessellator does: clip a kd-tree cell (with hanging points) against a trimming
    // region with Clipper, collinear points kept, and triangulate each polygon of the PolyTree.
    // Coarse grids give Clipper many touching rings, shared vertices and collinear runs.
    std::mt19937_64 random(1);
    int simplePolygonCount = 0;
    int crossingPolygonCount = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double spacing = trial % 2 ? 1.0 : 1000.0;
        const double scale = 40 * spacing;
        ClipperLib::Paths region{randomStar(random, 0, 0, scale, spacing)};
        ClipperLib::Paths removed;
        const int cutouts = std::uniform_int_distribution<int>(0, 4)(random);
        for (int k = 0; k < cutouts; ++k) {
            std::uniform_real_distribution<double> offset(-0.5 * scale, 0.5 * scale);
            removed.push_back(
                randomStar(random, offset(random), offset(random), 0.3 * scale, spacing));
        }
        ClipperLib::Clipper trimming;
        trimming.AddPaths(region, ClipperLib::ptSubject, true);
        trimming.AddPaths(removed, ClipperLib::ptClip, true);
        ClipperLib::Paths trimmed;
        trimming.Execute(ClipperLib::ctDifference, trimmed, ClipperLib::pftNonZero,
                         ClipperLib::pftNonZero);

        // A cell covering part of the region, with hanging points on its sides.
        const std::int64_t step = std::int64_t(spacing) * 5;
        const std::int64_t left = -step * std::uniform_int_distribution<int>(0, 8)(random);
        const std::int64_t bottom = -step * std::uniform_int_distribution<int>(0, 8)(random);
        const std::int64_t width = step * std::uniform_int_distribution<int>(1, 12)(random);
        const std::int64_t height = step * std::uniform_int_distribution<int>(1, 12)(random);
        ClipperLib::Path cell;
        for (const Ring& side :
             {straightRun(left, bottom, left + width, bottom, 3),
              straightRun(left + width, bottom, left + width, bottom + height, 2),
              straightRun(left + width, bottom + height, left, bottom + height, 1),
              straightRun(left, bottom + height, left, bottom, 4)}) {
            for (const IntegerPoint2& p : side) cell.push_back({p.x, p.y});
        }

        ClipperLib::Clipper clipper;
        clipper.PreserveCollinear(true);
        clipper.StrictlySimple(trial % 3 == 0);
        clipper.AddPath(cell, ClipperLib::ptSubject, true);
        clipper.AddPaths(trimmed, ClipperLib::ptClip, true);
        ClipperLib::PolyTree tree;
        clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        std::vector<Rings> polygons;
        collectPolygons(tree, polygons);
        for (const Rings& rings : polygons) {
            const Triangulation result = triangulatePolygon(rings);
            if (ringsCross(rings) || !holesLieInside(rings)) {
                // Clipper rounds crossings to the grid, which can make its output cross itself
                // by a fraction of a unit or put a hole partly outside its outer ring. Such
                // input must still give sound triangles.
                ++crossingPolygonCount;
                const Ring points = flatten(rings);
                for (const auto& triangle : result.triangles) {
                    for (const std::uint32_t index : triangle) ASSERT_LT(index, points.size());
                    EXPECT_GT(twiceTriangleArea(points[triangle[0]], points[triangle[1]],
                                                points[triangle[2]]),
                              0);
                }
            } else {
                ++simplePolygonCount;
                expectValidTriangulation(rings, result);
            }
            if (HasFailure()) {
                ADD_FAILURE() << "trial " << trial << ": " << describe(rings);
                return;
            }
        }
    }
    EXPECT_GT(simplePolygonCount, 1500);
    EXPECT_LT(crossingPolygonCount, simplePolygonCount / 10);
}

TEST(PolygonTriangulator, ArbitraryPointSoupsEndWithSoundTriangles) {
    // Rings of random points on a small grid cross themselves, repeat points, run along each
    // other and put holes anywhere. Nothing may crash or hang, and every triangle returned must
    // still be counter-clockwise and name input points.
    std::mt19937_64 random(99);
    for (int trial = 0; trial < 3000; ++trial) {
        const int grid = std::uniform_int_distribution<int>(2, 12)(random);
        std::uniform_int_distribution<std::int64_t> coordinate(0, grid);
        Rings rings(std::uniform_int_distribution<std::size_t>(1, 4)(random));
        for (Ring& ring : rings) {
            ring.resize(std::uniform_int_distribution<std::size_t>(0, 14)(random));
            for (IntegerPoint2& p : ring) p = {coordinate(random), coordinate(random)};
        }
        const Triangulation result = triangulatePolygon(rings);
        const Ring points = flatten(rings);
        for (const auto& triangle : result.triangles) {
            for (const std::uint32_t index : triangle) ASSERT_LT(index, points.size());
            ASSERT_GT(
                twiceTriangleArea(points[triangle[0]], points[triangle[1]], points[triangle[2]]), 0)
                << describe(rings);
        }
        const Ring all = flatten(rings);
        const std::set<Key> distinct([&] {
            std::set<Key> keys;
            for (const IntegerPoint2& p : all) keys.insert(keyOf(p));
            return keys;
        }());
        if (distinct.size() == all.size() && !ringsCross(rings) && !rings[0].empty() &&
            holesLieInside(rings)) {
            // Valid by chance (simple rings that do not touch, holes inside the outer ring):
            // then the triangulation must be exact.
            expectValidTriangulation(rings, result);
            if (HasFailure()) {
                ADD_FAILURE() << "trial " << trial << ": " << describe(rings);
                return;
            }
        }
    }
}
