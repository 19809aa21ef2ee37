#include "tessellate/PolygonTriangulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

namespace nurbslod {
namespace {

// GCC and Clang provide 128-bit integers; __extension__ keeps -Wpedantic quiet about them.
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UnsignedInt128;

using Triangle = std::array<std::uint32_t, 3>;

// ---------------------------------------------------------------------------------------------
// Exact predicates. Coordinates are at most 2^62 - 1 in magnitude, so differences stay below 2^63
// and each product of two differences below 2^126: a cross or dot product (a sum of two such
// products) is exact in 128 bits. Nothing here rounds, so the ear clipper's decisions are
// consistent with each other, which is what keeps it from looping or producing overlaps.
// ---------------------------------------------------------------------------------------------

int signOf(Int128 value) {
    return (value > 0) - (value < 0);
}

// Twice the signed area of the triangle (origin, a, b): positive when it turns counter-clockwise.
Int128 cross(const IntegerPoint2& origin, const IntegerPoint2& a, const IntegerPoint2& b) {
    const Int128 ax = Int128(a.x) - origin.x;
    const Int128 ay = Int128(a.y) - origin.y;
    const Int128 bx = Int128(b.x) - origin.x;
    const Int128 by = Int128(b.y) - origin.y;
    return ax * by - ay * bx;
}

int orientation(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return signOf(cross(a, b, c));
}

Int128 dot(const IntegerPoint2& origin, const IntegerPoint2& a, const IntegerPoint2& b) {
    const Int128 ax = Int128(a.x) - origin.x;
    const Int128 ay = Int128(a.y) - origin.y;
    const Int128 bx = Int128(b.x) - origin.x;
    const Int128 by = Int128(b.y) - origin.y;
    return ax * bx + ay * by;
}

// b is the tip of a zero-width spike: the boundary arrives at b and leaves it along the same line
// back towards where it came from. A spike encloses no area.
bool isSpike(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return orientation(a, b, c) == 0 && dot(b, a, c) > 0;
}

// b lies on the straight line from a to c, between them: a hanging point or a straight trimming
// run. Such a vertex has an angle of 180 degrees and must still become a triangle corner.
bool isStraight(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    return orientation(a, b, c) == 0 && dot(b, a, c) < 0;
}

// The magnitude of a product of up to 192 bits, as (high 64 bits, low 128 bits).
std::pair<std::uint64_t, UnsignedInt128> multiplyMagnitude(UnsignedInt128 value,
                                                           std::uint64_t factor) {
    const UnsignedInt128 lowProduct = UnsignedInt128(std::uint64_t(value)) * factor;
    const UnsignedInt128 highProduct = UnsignedInt128(std::uint64_t(value >> 64)) * factor;
    const UnsignedInt128 middle = (lowProduct >> 64) + std::uint64_t(highProduct);
    const std::uint64_t top = std::uint64_t(highProduct >> 64) + std::uint64_t(middle >> 64);
    return {top, (UnsignedInt128(std::uint64_t(middle)) << 64) | std::uint64_t(lowProduct)};
}

// The sign of a * b - c * d for positive b and d. The ray cast of the hole bridging compares two
// rational crossing positions numerator / denominator, whose cross products need 192 bits.
int compareProducts(Int128 a, std::uint64_t b, Int128 c, std::uint64_t d) {
    const int signA = signOf(a);
    const int signC = signOf(c);
    if (signA != signC) return signA > signC ? 1 : -1;
    if (signA == 0) return 0;
    const auto magnitude = [](Int128 v) {
        return v < 0 ? UnsignedInt128(0) - UnsignedInt128(v) : UnsignedInt128(v);
    };
    const auto left = multiplyMagnitude(magnitude(a), b);
    const auto right = multiplyMagnitude(magnitude(c), d);
    const int magnitudeOrder = left < right ? -1 : (right < left ? 1 : 0);
    return signA > 0 ? magnitudeOrder : -magnitudeOrder;
}

// The sign of a ring's area. The shoelace sum of many 127-bit terms may pass 2^127, so overflows
// are counted in a separate carry: the true sum is the wrapped sum plus carries * 2^128.
int ringAreaSign(const std::vector<IntegerPoint2>& ring) {
    Int128 wrappedSum = 0;
    std::int64_t carries = 0;
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
        const Int128 term = cross(ring[0], ring[i], ring[i + 1]);
        Int128 sum;
        if (__builtin_add_overflow(wrappedSum, term, &sum)) carries += term > 0 ? 1 : -1;
        wrappedSum = sum;
    }
    if (carries != 0) return carries > 0 ? 1 : -1;
    return signOf(wrappedSum);
}

// How close a triangle is to equilateral: 1 for equilateral, towards 0 for slivers. Used only to
// choose among triangles that are all valid, so rounding here cannot break anything.
double triangleQuality(const IntegerPoint2& a, const IntegerPoint2& b, const IntegerPoint2& c) {
    const auto squaredLength = [](const IntegerPoint2& p, const IntegerPoint2& q) {
        const double dx = double(Int128(q.x) - p.x);
        const double dy = double(Int128(q.y) - p.y);
        return dx * dx + dy * dy;
    };
    const double sumOfSquares = squaredLength(a, b) + squaredLength(b, c) + squaredLength(c, a);
    if (!(sumOfSquares > 0)) return 0;
    return 2.0 * std::sqrt(3.0) * double(cross(a, b, c)) / sumOfSquares;
}

// A ring point with the output index of its vertex.
struct RingVertex {
    IntegerPoint2 point;
    std::uint32_t index;
};

std::vector<IntegerPoint2> pointsOf(const std::vector<RingVertex>& ring) {
    std::vector<IntegerPoint2> points;
    points.reserve(ring.size());
    for (const RingVertex& vertex : ring) points.push_back(vertex.point);
    return points;
}

// Removes repeated consecutive points and spikes, which enclose no area and would otherwise give
// zero-area triangles. Runs in linear time: a stack for the open chain, then the closing seam.
std::vector<RingVertex> withoutRepeatsAndSpikes(const std::vector<RingVertex>& ring) {
    std::vector<RingVertex> kept;
    kept.reserve(ring.size());
    for (const RingVertex& vertex : ring) {
        while (kept.size() >= 2 &&
               isSpike(kept[kept.size() - 2].point, kept.back().point, vertex.point)) {
            kept.pop_back();
        }
        if (!kept.empty() && kept.back().point == vertex.point) continue;
        kept.push_back(vertex);
    }
    std::size_t begin = 0;
    std::size_t end = kept.size();
    while (end - begin >= 2) {
        if (kept[end - 1].point == kept[begin].point) {
            --end;
        } else if (end - begin >= 3 &&
                   isSpike(kept[end - 2].point, kept[end - 1].point, kept[begin].point)) {
            --end;
        } else if (end - begin >= 3 &&
                   isSpike(kept[end - 1].point, kept[begin].point, kept[begin + 1].point)) {
            ++begin;
        } else {
            break;
        }
    }
    return std::vector<RingVertex>(kept.begin() + std::ptrdiff_t(begin),
                                   kept.begin() + std::ptrdiff_t(end));
}

// Convex with counter-clockwise orientation: no right turn, no spike, and the boundary winds
// around only once. All left turns alone would admit a star that winds twice; such a boundary
// reverses its x direction four times or more, a convex one exactly twice.
bool isConvex(const std::vector<RingVertex>& ring) {
    const std::size_t n = ring.size();
    if (n < 3) return false;
    int firstDirection = 0;
    int previousDirection = 0;
    int directionChanges = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const IntegerPoint2& a = ring[(i + n - 1) % n].point;
        const IntegerPoint2& b = ring[i].point;
        const IntegerPoint2& c = ring[(i + 1) % n].point;
        const int turn = orientation(a, b, c);
        if (turn < 0 || (turn == 0 && !isStraight(a, b, c))) return false;
        const int direction = (c.x > b.x) - (c.x < b.x);
        if (direction == 0) continue;
        if (firstDirection == 0) firstDirection = direction;
        if (previousDirection != 0 && direction != previousDirection) ++directionChanges;
        previousDirection = direction;
    }
    if (previousDirection != firstDirection) ++directionChanges;
    return directionChanges <= 2;
}

// ---------------------------------------------------------------------------------------------
// The fast path of paper section 7 for convex polygons: a kd-tree cell is a rectangle with
// hanging points on its sides. Start with the triangle at a corner, then walk the diagonal
// along both chains, adding at each step the triangle with the better of the two adjacent
// vertices. Collinear points need one rule the paper leaves implicit: a diagonal must never join
// two points of the same side (the triangle beyond it would have zero area). With the sides
// numbered, that rule always leaves at least one of the two steps open, so the walk emits
// exactly n - 2 triangles, none of zero area, in linear time.
// ---------------------------------------------------------------------------------------------
bool triangulateConvex(const std::vector<RingVertex>& ring, std::vector<Triangle>& triangles) {
    const std::size_t n = ring.size();
    if (n == 3) {
        triangles.push_back({ring[0].index, ring[1].index, ring[2].index});
        return true;
    }
    const auto at = [&](std::size_t i) -> const IntegerPoint2& { return ring[i % n].point; };
    const auto isCorner = [&](std::size_t i) {
        return orientation(at(i + n - 1), at(i), at(i + 1)) > 0;
    };
    std::size_t firstCorner = 0;
    while (firstCorner < n && !isCorner(firstCorner)) ++firstCorner;
    if (firstCorner == n) return false;

    // sideOfEdge[i] numbers the side that holds the edge from vertex i to vertex i + 1.
    std::vector<std::size_t> sideOfEdge(n);
    std::size_t side = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = (firstCorner + k) % n;
        if (k > 0 && isCorner(i)) ++side;
        sideOfEdge[i] = side;
    }
    const auto shareSide = [&](std::size_t i, std::size_t j) {
        const std::size_t sidesOfI[2] = {sideOfEdge[(i + n - 1) % n], sideOfEdge[i % n]};
        const std::size_t sidesOfJ[2] = {sideOfEdge[(j + n - 1) % n], sideOfEdge[j % n]};
        for (std::size_t s : sidesOfI)
            for (std::size_t t : sidesOfJ)
                if (s == t) return true;
        return false;
    };

    // A corner whose two neighbours lie on different sides; only a triangle with no hanging
    // points next to one corner rules that corner out, and then the next corner qualifies.
    std::optional<std::size_t> start;
    for (std::size_t i = 0; i < n && !start; ++i) {
        if (isCorner(i) && !shareSide(i + n - 1, i + 1)) start = i;
    }
    if (!start) return false;

    std::vector<Triangle> fan;
    fan.reserve(n - 2);
    const auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
        fan.push_back({ring[a % n].index, ring[b % n].index, ring[c % n].index});
    };
    // The remaining polygon is the chain right, right + 1, ..., left closed by the diagonal
    // left -> right; indices grow without wrapping so that right < left always holds.
    std::size_t left = *start + n - 1;
    std::size_t right = *start + 1;
    emit(left, *start, right);
    while (left - right + 1 > 3) {
        const bool rightStepOpen = !shareSide(left, right + 1);
        const bool leftStepOpen = !shareSide(left - 1, right);
        bool stepRight = rightStepOpen;
        if (rightStepOpen && leftStepOpen) {
            stepRight = triangleQuality(at(left), at(right), at(right + 1)) >=
                        triangleQuality(at(left - 1), at(left), at(right));
        } else if (!rightStepOpen && !leftStepOpen) {
            return false;  // impossible for a convex ring; the ear clipper takes over
        }
        if (stepRight) {
            emit(left, right, right + 1);
            ++right;
        } else {
            emit(left - 1, left, right);
            --left;
        }
    }
    emit(left, right, right + 1);
    triangles.insert(triangles.end(), fan.begin(), fan.end());
    return true;
}

// ---------------------------------------------------------------------------------------------
// The general path (paper section 7 names Garey et al. for non-convex polygons; ear clipping
// gives the same triangles-from-input-points result and is simpler at the few dozen points a
// trimmed cell has). Holes are joined to the outer ring by two-way bridges (Eberly,
// "Triangulation by Ear Clipping", section 3), which turns the polygon with holes into one
// weakly simple ring: bridge ends and points where rings touch occur more than once.
// ---------------------------------------------------------------------------------------------
class EarClipper {
public:
    // outer runs counter-clockwise, each hole clockwise; none is empty.
    EarClipper(const std::vector<RingVertex>& outer,
               const std::vector<std::vector<RingVertex>>& holes) {
        std::size_t total = outer.size() + 1;
        for (const auto& hole : holes) total += hole.size() + 2;
        nodes_.reserve(total);
        start_ = addRing(outer);
        count_ = outer.size();
        std::vector<std::pair<std::uint32_t, std::size_t>> holeStarts;  // rightmost node, size
        for (const auto& hole : holes) {
            const std::uint32_t first = addRing(hole);
            std::uint32_t rightmost = first;
            for (std::uint32_t node = nodes_[first].next; node != first; node = nodes_[node].next) {
                const IntegerPoint2& p = nodes_[node].point;
                const IntegerPoint2& best = nodes_[rightmost].point;
                if (p.x > best.x || (p.x == best.x && p.y > best.y)) rightmost = node;
            }
            holeStarts.emplace_back(rightmost, hole.size());
        }
        // Rightmost holes first: a ray cast to the right from a hole then meets only the outer
        // ring and holes already joined to it.
        std::stable_sort(holeStarts.begin(), holeStarts.end(), [&](const auto& a, const auto& b) {
            const IntegerPoint2& p = nodes_[a.first].point;
            const IntegerPoint2& q = nodes_[b.first].point;
            return std::tie(p.x, p.y) > std::tie(q.x, q.y);
        });
        for (const auto& [rightmost, size] : holeStarts) mergeHole(rightmost, size);
    }

    // Appends the triangles; false when the input was not a valid polygon with holes.
    bool triangulate(std::vector<Triangle>& triangles) {
        bool valid = bridgesFound_;
        if (count_ > kIndexedFrom) buildCandidateIndex();
        std::uint32_t current = start_;
        while (count_ > 3) {
            const std::optional<std::uint32_t> ear = findEar(current);
            if (!ear) {
                clipWithoutChecks(current, triangles);
                return false;
            }
            current = clip(*ear, triangles);
        }
        if (count_ == 3) {
            const Node& tip = nodes_[current];
            const int turn =
                orientation(nodes_[tip.previous].point, tip.point, nodes_[tip.next].point);
            if (turn > 0) emitTriangle(current, triangles);
            if (turn < 0) valid = false;
        }
        return valid;
    }

private:
    struct Node {
        IntegerPoint2 point;
        std::uint32_t index;
        std::uint32_t previous;
        std::uint32_t next;
    };

    // Ears are taken at once when at least this close to equilateral; otherwise the best of
    // kEarLookahead candidates is preferred, which keeps slivers out of the mesh where a choice
    // exists.
    static constexpr double kGoodEarQuality = 0.5;
    static constexpr std::size_t kEarLookahead = 8;
    // A ring of more nodes than this indexes the nodes that can keep a triangle from being an
    // ear (buildCandidateIndex) in a grid of buckets: the ear test then visits those in the
    // cells its triangle's box meets, instead of every node of the ring. The ear test is what
    // makes ear clipping O(n^2). On bottle.brep at relative 1e-4 the unrolled cylinders' rings
    // (up to 1,080 points, triangulated again each round of chordPointsForUnrolledBound) are
    // most of the ear clipping: its ear tests took 98 million instructions with every node
    // indexed along a Z-order curve (the ears of a strip span its height, and their boxes' codes
    // most of the ring's), 49 million now. An index from 16 nodes did no better.
    static constexpr std::size_t kIndexedFrom = 80;

    std::uint32_t addRing(const std::vector<RingVertex>& ring) {
        const auto first = std::uint32_t(nodes_.size());
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const auto id = std::uint32_t(nodes_.size());
            const std::uint32_t previous = i == 0 ? first + std::uint32_t(ring.size()) - 1 : id - 1;
            const std::uint32_t next = i + 1 == ring.size() ? first : id + 1;
            nodes_.push_back({ring[i].point, ring[i].index, previous, next});
        }
        return first;
    }

    const IntegerPoint2& pointOf(std::uint32_t node) const { return nodes_[node].point; }
    std::uint32_t previousOf(std::uint32_t node) const { return nodes_[node].previous; }
    std::uint32_t nextOf(std::uint32_t node) const { return nodes_[node].next; }

    void link(std::uint32_t first, std::uint32_t second) {
        nodes_[first].next = second;
        nodes_[second].previous = first;
    }

    void remove(std::uint32_t node) {
        link(previousOf(node), nextOf(node));
        if (start_ == node) start_ = nextOf(node);
        --count_;
        if (!candidate_.empty()) {
            removed_[node] = 1;
            // its neighbours' angles changed; one that turns right now joins the candidates
            for (const std::uint32_t neighbour : {previousOf(node), nextOf(node)})
                if (!candidate_[neighbour] && turnsRight(neighbour)) {
                    candidate_[neighbour] = 1;
                    lateCandidates_.push_back(neighbour);
                }
        }
    }

    // The grid cell of a coordinate along one axis (0 x, 1 y), clamped to the grid.
    std::int64_t cellAlong(int axis, std::int64_t value) const {
        const double cell = (double(value) - gridLow_[axis]) * cellsPerUnit_[axis];
        return std::int64_t(std::clamp(cell, 0.0, double(cells_[axis] - 1)));
    }

    // whether the node turns right, or back on itself (a spike, a repeated point)
    bool turnsRight(std::uint32_t node) const {
        const IntegerPoint2 &a = pointOf(previousOf(node)), &b = pointOf(node),
                            &c = pointOf(nextOf(node));
        const int turn = orientation(a, b, c);
        return turn < 0 || (turn == 0 && !isStraight(a, b, c));
    }

    // The nodes an ear test must visit besides the two next to its triangle, in a grid of
    // buckets over the ring's box (about one node a cell; candidates_): those that turn right
    // (turnsRight), and those whose point occurs more than once (bridge ends, touching rings). A
    // vertex inside the closed triangle of a strictly convex tip makes one of these, or a neighbour
    // of the triangle, lie in it too (Eberly, "Triangulation by Ear Clipping", section 2). Of the
    // vertices in it take those farthest from the side between the tip's neighbours: no edge
    // crosses the tip's two sides, so their edges run back from the tip or along that side's
    // direction, while the ring's inside lies towards the tip. One whose two edges run back turns
    // right; otherwise a straight run of them ends at a vertex whose edge runs back (it turns
    // right), at a repeated corner point, or, where the run lies on that side, at the triangle's
    // own neighbour. Straight vertices, most of a strip's (an unrolled cylinder's rims), need no
    // visit. A node that turns right later, as its neighbour is cut off, joins lateCandidates_.
    void buildCandidateIndex() {
        std::vector<std::uint32_t> ring;
        ring.reserve(count_);
        std::uint32_t node = start_;
        for (std::size_t step = 0; step < count_; ++step, node = nextOf(node)) ring.push_back(node);
        double lowX = double(pointOf(start_).x), highX = lowX;
        double lowY = double(pointOf(start_).y), highY = lowY;
        for (const std::uint32_t n : ring) {
            const double x = double(pointOf(n).x), y = double(pointOf(n).y);
            lowX = std::min(lowX, x);
            highX = std::max(highX, x);
            lowY = std::min(lowY, y);
            highY = std::max(highY, y);
        }
        // as many cells as nodes, as near square as the box allows
        const double width = std::max(highX - lowX, 1.0), height = std::max(highY - lowY, 1.0);
        const double side = std::sqrt(width * height / double(ring.size()));
        gridLow_ = {lowX, lowY};
        cells_ = {
            std::clamp<std::int64_t>(std::int64_t(width / side), 1, std::int64_t(ring.size())),
            std::clamp<std::int64_t>(std::int64_t(height / side), 1, std::int64_t(ring.size()))};
        cellsPerUnit_ = {double(cells_[0]) / width, double(cells_[1]) / height};
        candidate_.assign(nodes_.size(), 0);
        removed_.assign(nodes_.size(), 0);
        for (const std::uint32_t n : ring) candidate_[n] = turnsRight(n) ? 1 : 0;
        std::vector<std::uint32_t> byPoint = ring;
        std::sort(byPoint.begin(), byPoint.end(), [&](std::uint32_t a, std::uint32_t b) {
            return std::tie(pointOf(a).x, pointOf(a).y) < std::tie(pointOf(b).x, pointOf(b).y);
        });
        for (std::size_t i = 0; i + 1 < byPoint.size(); ++i)
            if (pointOf(byPoint[i]) == pointOf(byPoint[i + 1]))
                candidate_[byPoint[i]] = candidate_[byPoint[i + 1]] = 1;
        // the buckets as one array, cell by cell (bucketStart_: where each cell's begin)
        auto cellOf = [&](std::uint32_t n) {
            return std::size_t(cellAlong(1, pointOf(n).y) * cells_[0] + cellAlong(0, pointOf(n).x));
        };
        bucketStart_.assign(std::size_t(cells_[0] * cells_[1]) + 1, 0);
        for (const std::uint32_t n : ring)
            if (candidate_[n]) ++bucketStart_[cellOf(n) + 1];
        for (std::size_t c = 1; c < bucketStart_.size(); ++c)
            bucketStart_[c] += bucketStart_[c - 1];
        candidates_.resize(bucketStart_.back());
        std::vector<std::uint32_t> filled(bucketStart_.begin(), bucketStart_.end() - 1);
        for (const std::uint32_t n : ring)
            if (candidate_[n]) candidates_[filled[cellOf(n)]++] = n;
    }

    std::uint32_t copyOf(std::uint32_t node) {
        nodes_.push_back(nodes_[node]);
        return std::uint32_t(nodes_.size() - 1);
    }

    // Removes repeated points and spikes at the joint between node and its successor, where a
    // clip or a splice has just made two vertices neighbours. Both enclose no area, and the
    // repeated point keeps its vertex through the copy that stays. Returns a node that remains.
    std::uint32_t removeDegenerateAt(std::uint32_t node) {
        while (count_ >= 3) {
            const std::uint32_t next = nextOf(node);
            if (pointOf(next) == pointOf(node)) {
                remove(next);
            } else if (isSpike(pointOf(previousOf(node)), pointOf(node), pointOf(next))) {
                const std::uint32_t previous = previousOf(node);
                remove(node);
                node = previous;
            } else if (isSpike(pointOf(node), pointOf(next), pointOf(nextOf(next)))) {
                remove(next);
            } else {
                break;
            }
        }
        return node;
    }

    // Whether the point towards lies strictly inside the polygon's angle at node, so that a
    // segment from node towards it starts inside the polygon.
    bool isLocallyInside(std::uint32_t node, const IntegerPoint2& towards) const {
        const IntegerPoint2& previous = pointOf(previousOf(node));
        const IntegerPoint2& here = pointOf(node);
        const IntegerPoint2& next = pointOf(nextOf(node));
        const bool leftOfIncoming = orientation(previous, here, towards) > 0;
        const bool leftOfOutgoing = orientation(here, next, towards) > 0;
        const bool convexOrStraight =
            orientation(previous, here, next) > 0 || isStraight(previous, here, next);
        return convexOrStraight ? leftOfIncoming && leftOfOutgoing
                                : leftOfIncoming || leftOfOutgoing;
    }

    // Of the nodes at target (a point can occur several times: bridge ends, touching rings), the
    // one whose angle contains the most of the facing points; nullopt when none is at target.
    std::optional<std::uint32_t> chooseCopy(const IntegerPoint2& target,
                                            std::initializer_list<IntegerPoint2> facing) const {
        std::optional<std::uint32_t> best;
        int bestScore = -1;
        std::uint32_t node = start_;
        for (std::size_t step = 0; step < count_; ++step, node = nextOf(node)) {
            if (!(pointOf(node) == target)) continue;
            int score = 0;
            for (const IntegerPoint2& point : facing) score += isLocallyInside(node, point) ? 1 : 0;
            if (score > bestScore) {
                best = node;
                bestScore = score;
            }
        }
        return best;
    }

    // The outer-ring node the hole's rightmost point hole can be joined to by a segment that
    // crosses no edge (Eberly, section 3).
    std::optional<std::uint32_t> findBridgeTarget(std::uint32_t hole) const {
        const IntegerPoint2 m = pointOf(hole);

        // The hole touches the outer ring at m (RingGraph resolves such contacts; this one is
        // left where the rings also cross): a bridge of length zero, at the copy of m whose
        // angle holds the hole's two edges.
        if (const auto touching =
                chooseCopy(m, {pointOf(previousOf(hole)), pointOf(nextOf(hole))})) {
            return touching;
        }

        // Cast a ray from m towards +x and find the nearest edge it meets. The crossing with
        // the upward edge (low, high) lies at m.x + numerator / denominator; both are exact.
        std::optional<std::uint32_t> hitEdge;
        Int128 hitNumerator = 0;
        std::uint64_t hitDenominator = 1;
        std::uint32_t node = start_;
        for (std::size_t step = 0; step < count_; ++step, node = nextOf(node)) {
            const IntegerPoint2& p = pointOf(node);
            const IntegerPoint2& q = pointOf(nextOf(node));
            if (p.y == q.y) continue;  // a horizontal edge on the ray is met at its end points
            const IntegerPoint2& low = p.y < q.y ? p : q;
            const IntegerPoint2& high = p.y < q.y ? q : p;
            if (m.y < low.y || m.y > high.y) continue;
            const Int128 denominator = Int128(high.y) - low.y;
            const Int128 numerator = (Int128(low.x) - m.x) * denominator +
                                     (Int128(m.y) - low.y) * (Int128(high.x) - low.x);
            if (numerator < 0) continue;
            if (!hitEdge || compareProducts(numerator, hitDenominator, hitNumerator,
                                            std::uint64_t(denominator)) < 0) {
                hitEdge = node;
                hitNumerator = numerator;
                hitDenominator = std::uint64_t(denominator);
            }
        }
        if (!hitEdge) return std::nullopt;  // the hole is not inside the outer ring

        const IntegerPoint2& p = pointOf(*hitEdge);
        const IntegerPoint2& q = pointOf(nextOf(*hitEdge));
        const IntegerPoint2& low = p.y < q.y ? p : q;
        const IntegerPoint2& high = p.y < q.y ? q : p;
        // The ray meets a vertex: nothing lies between it and m.
        if (low.y == m.y) return chooseCopy(low, {m});
        if (high.y == m.y) return chooseCopy(high, {m});

        // The ray meets the inside of an edge. Its end point further right is visible unless
        // some vertex lies in the triangle (m, crossing, end point); then the one at the
        // smallest angle to the ray is, and the nearest of those on one line through m.
        const IntegerPoint2& end = high.x >= low.x ? high : low;
        const int side = end.y > m.y ? 1 : -1;
        IntegerPoint2 target = end;
        node = start_;
        for (std::size_t step = 0; step < count_; ++step, node = nextOf(node)) {
            const IntegerPoint2& r = pointOf(node);
            if (r == end || r == m) continue;
            if ((r.y > m.y ? 1 : (r.y < m.y ? -1 : 0)) * side < 0) continue;
            if (orientation(low, high, r) < 0) continue;  // beyond the hit edge
            if (orientation(m, end, r) * side > 0) continue;
            const Int128 rise = r.y > m.y ? Int128(r.y) - m.y : Int128(m.y) - r.y;
            const Int128 run = Int128(r.x) - m.x;
            const Int128 targetRise =
                target.y > m.y ? Int128(target.y) - m.y : Int128(m.y) - target.y;
            const Int128 targetRun = Int128(target.x) - m.x;
            const Int128 slopeOrder = rise * targetRun - targetRise * run;
            if (slopeOrder < 0 || (slopeOrder == 0 && run < targetRun)) target = r;
        }
        return chooseCopy(target, {m});
    }

    // A hole that touches itself passes its rightmost point twice, and the bridge must leave
    // from the pass whose side of the hole the bridge runs on; otherwise the joined ring crosses
    // itself at that point. Returns the node at hole's point whose angle holds target.
    std::uint32_t holeCopyFacing(std::uint32_t hole, const IntegerPoint2& target) const {
        if (pointOf(hole) == target) return hole;
        std::uint32_t node = hole;
        do {
            if (pointOf(node) == pointOf(hole) && isLocallyInside(node, target)) return node;
            node = nextOf(node);
        } while (node != hole);
        return hole;
    }

    // Joins a hole to the outer ring: outer, hole, ..., hole's predecessor, hole copy, outer
    // copy, outer's old successor.
    void mergeHole(std::uint32_t hole, std::size_t holeSize) {
        std::optional<std::uint32_t> target = findBridgeTarget(hole);
        if (!target) {
            bridgesFound_ = false;  // a hole outside the outer ring; join it anywhere
            target = start_;
        }
        const std::uint32_t outer = *target;
        hole = holeCopyFacing(hole, pointOf(outer));
        const std::uint32_t outerCopy = copyOf(outer);
        const std::uint32_t holeCopy = copyOf(hole);
        const std::uint32_t outerNext = nextOf(outer);
        const std::uint32_t holePrevious = previousOf(hole);
        link(outer, hole);
        link(outerCopy, outerNext);
        link(holeCopy, outerCopy);
        link(holePrevious, holeCopy);
        count_ += holeSize + 2;
        // A bridge of length zero leaves repeated points at both joints.
        removeDegenerateAt(holeCopy);
        removeDegenerateAt(outer);
    }

    void emitTriangle(std::uint32_t tip, std::vector<Triangle>& triangles) const {
        triangles.push_back(
            {nodes_[previousOf(tip)].index, nodes_[tip].index, nodes_[nextOf(tip)].index});
    }

    // Cuts off the ear at tip and returns a node next to the cut.
    std::uint32_t clip(std::uint32_t tip, std::vector<Triangle>& triangles) {
        emitTriangle(tip, triangles);
        const std::uint32_t previous = previousOf(tip);
        remove(tip);
        return removeDegenerateAt(previous);
    }

    // Whether the segment from corner towards q starts strictly inside the triangle's angle at
    // corner, whose sides run to first and second (counter-clockwise).
    static bool entersAngle(const IntegerPoint2& corner, const IntegerPoint2& first,
                            const IntegerPoint2& second, const IntegerPoint2& q) {
        return orientation(corner, first, q) > 0 && orientation(corner, second, q) < 0;
    }

    // An ear: a strictly convex tip (so no zero-area triangle) whose closed triangle holds no
    // other vertex. Another occurrence of a corner point (a bridge end, a touching ring) is
    // allowed only if neither of its edges runs into the triangle. An edge of it along the new
    // diagonal is allowed: it closes a lobe of the ring that the ear fills, and the spike left
    // behind is removed.
    bool isEar(std::uint32_t tip) const {
        const std::uint32_t previous = previousOf(tip);
        const std::uint32_t next = nextOf(tip);
        const IntegerPoint2& a = pointOf(previous);
        const IntegerPoint2& b = pointOf(tip);
        const IntegerPoint2& c = pointOf(next);
        if (orientation(a, b, c) <= 0) return false;
        const std::int64_t minimumX = std::min({a.x, b.x, c.x});
        const std::int64_t maximumX = std::max({a.x, b.x, c.x});
        const std::int64_t minimumY = std::min({a.y, b.y, c.y});
        const std::int64_t maximumY = std::max({a.y, b.y, c.y});
        // whether another node keeps the triangle from being an ear
        const auto blocks = [&](std::uint32_t node) {
            const IntegerPoint2& p = pointOf(node);
            if (p.x < minimumX || p.x > maximumX || p.y < minimumY || p.y > maximumY) return false;
            if (p == a || p == b || p == c) {
                for (const std::uint32_t neighbour : {previousOf(node), nextOf(node)}) {
                    const IntegerPoint2& q = pointOf(neighbour);
                    if (p == a && entersAngle(a, b, c, q)) return true;
                    if (p == b && entersAngle(b, c, a, q)) return true;
                    if (p == c && entersAngle(c, a, b, q)) return true;
                }
                return false;
            }
            return orientation(a, b, p) >= 0 && orientation(b, c, p) >= 0 &&
                   orientation(c, a, p) >= 0;
        };
        if (candidate_.empty()) {
            for (std::uint32_t node = nextOf(next); node != previous; node = nextOf(node))
                if (blocks(node)) return false;
            return true;
        }
        // the triangle's two neighbours, and the candidates in the cells its box meets (cut-off
        // ones skipped)
        const auto other = [&](std::uint32_t node) {
            return !removed_[node] && node != previous && node != tip && node != next;
        };
        for (const std::uint32_t node : {previousOf(previous), nextOf(next)})
            if (other(node) && blocks(node)) return false;
        const std::int64_t lowColumn = cellAlong(0, minimumX), highColumn = cellAlong(0, maximumX);
        for (std::int64_t row = cellAlong(1, minimumY); row <= cellAlong(1, maximumY); ++row) {
            const std::size_t first = std::size_t(row * cells_[0] + lowColumn);
            const std::size_t last = std::size_t(row * cells_[0] + highColumn);
            for (std::uint32_t k = bucketStart_[first]; k < bucketStart_[last + 1]; ++k)
                if (other(candidates_[k]) && blocks(candidates_[k])) return false;
        }
        for (const std::uint32_t node : lateCandidates_)
            if (other(node) && blocks(node)) return false;
        return true;
    }

    // One lap around the ring from current for an ear. A convex vertex shaped well enough is
    // tried at once; others are gathered kEarLookahead at a time and tried best first. The
    // shape costs O(1) and the emptiness test O(n), so looking ahead costs little: most often
    // the best of a group is an ear. Nullopt when the ring has no ear at all.
    std::optional<std::uint32_t> findEar(std::uint32_t current) const {
        std::array<std::pair<double, std::uint32_t>, kEarLookahead> group;
        std::size_t groupSize = 0;
        const auto tryGroup = [&]() -> std::optional<std::uint32_t> {
            // Best first: take out the best remaining candidate until one is an ear.
            while (groupSize > 0) {
                std::size_t best = 0;
                for (std::size_t k = 1; k < groupSize; ++k) {
                    if (group[k].first > group[best].first) best = k;
                }
                const std::uint32_t candidate = group[best].second;
                group[best] = group[--groupSize];
                if (isEar(candidate)) return candidate;
            }
            return std::nullopt;
        };
        std::uint32_t node = current;
        for (std::size_t step = 0; step < count_; ++step, node = nextOf(node)) {
            const IntegerPoint2& a = pointOf(previousOf(node));
            const IntegerPoint2& b = pointOf(node);
            const IntegerPoint2& c = pointOf(nextOf(node));
            if (orientation(a, b, c) <= 0) continue;
            const double quality = triangleQuality(a, b, c);
            if (quality >= kGoodEarQuality) {
                if (isEar(node)) return node;
                continue;
            }
            group[groupSize++] = {quality, node};
            if (groupSize == group.size()) {
                if (const auto ear = tryGroup()) return ear;
            }
        }
        return tryGroup();
    }

    // The ring has no ear: it crosses itself. Cut off convex vertices without the emptiness
    // check (the triangles may overlap) and drop collinear ones, each step removing one vertex.
    void clipWithoutChecks(std::uint32_t current, std::vector<Triangle>& triangles) {
        while (count_ > 3) {
            std::optional<std::uint32_t> convex;
            std::optional<std::uint32_t> flat;
            std::uint32_t node = current;
            for (std::size_t step = 0; step < count_ && !convex; ++step, node = nextOf(node)) {
                const int turn =
                    orientation(pointOf(previousOf(node)), pointOf(node), pointOf(nextOf(node)));
                if (turn > 0) convex = node;
                if (turn == 0 && !flat) flat = node;
            }
            if (convex) {
                emitTriangle(*convex, triangles);
                current = previousOf(*convex);
                remove(*convex);
            } else if (flat) {
                current = previousOf(*flat);
                remove(*flat);
            } else {
                return;  // every vertex turns right: nothing with positive area is left
            }
        }
        if (count_ == 3 && orientation(pointOf(previousOf(current)), pointOf(current),
                                       pointOf(nextOf(current))) > 0) {
            emitTriangle(current, triangles);
        }
    }

    std::vector<Node> nodes_;
    // the ear tests' index of a large ring (buildCandidateIndex), empty below kIndexedFrom
    // nodes: the grid (its low corner, cells per unit and cells along x and y), the candidates
    // cell by cell (row by row, x fastest) with where each cell's begin, per node whether it is
    // a candidate or cut off, and the nodes that became candidates since
    std::array<double, 2> gridLow_{}, cellsPerUnit_{};
    std::array<std::int64_t, 2> cells_{};
    std::vector<std::uint32_t> candidates_, bucketStart_;
    std::vector<char> candidate_, removed_;
    std::vector<std::uint32_t> lateCandidates_;
    std::uint32_t start_ = 0;
    std::size_t count_ = 0;
    bool bridgesFound_ = true;
};

// All rings as one successor permutation over their points, so that rings can be joined and
// split by relinking. Clipper's output for one polygon may have rings that touch: a hole lying
// against its outer ring at a point or along a segment, two holes touching, an outer ring
// touching itself. The ear clipper reads the polygon's inside from the turn at each vertex, and
// that reading is wrong where two passes of the boundary meet, so such contacts are resolved
// here, before holes are bridged.
class RingGraph {
public:
    explicit RingGraph(const std::vector<std::vector<RingVertex>>& rings) {
        for (const std::vector<RingVertex>& ring : rings) {
            const std::size_t first = vertices_.size();
            for (std::size_t i = 0; i < ring.size(); ++i) {
                next_.push_back(i + 1 == ring.size() ? first : vertices_.size() + 1);
                vertices_.push_back(ring[i]);
            }
        }
    }

    // Where the boundary runs along one segment in both directions, both sides of it have the
    // same winding number. It is 1 for a slit, which has area on both sides and which the ear
    // clipper handles like a bridge. It is 0 where a hole lies against its outer ring or another
    // hole, or where a lobe hangs from the rest on a string: no area on either side. The ear
    // clipper cannot tell the two apart and would fill the hole, so each pair of the second kind
    // is cancelled: exchanging the successors of the two edges' start points removes both edges
    // and joins their rings into one (or splits one ring in two); the repeated points this
    // leaves are for the caller's cleaning.
    void cancelSharedEdges() {
        const auto edgeKey = [&](std::size_t edge) {
            const IntegerPoint2& from = vertices_[edge].point;
            const IntegerPoint2& to = vertices_[next_[edge]].point;
            return std::make_tuple(from.x, from.y, to.x, to.y);
        };
        std::vector<std::size_t> byKey(vertices_.size());
        std::iota(byKey.begin(), byKey.end(), std::size_t(0));
        std::sort(byKey.begin(), byKey.end(),
                  [&](std::size_t a, std::size_t b) { return edgeKey(a) < edgeKey(b); });
        std::vector<bool> paired(vertices_.size(), false);
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for (std::size_t edge = 0; edge < vertices_.size(); ++edge) {
            if (paired[edge]) continue;
            const auto [fromX, fromY, toX, toY] = edgeKey(edge);
            const auto reversedKey = std::make_tuple(toX, toY, fromX, fromY);
            auto twin =
                std::lower_bound(byKey.begin(), byKey.end(), reversedKey,
                                 [&](std::size_t e, const auto& key) { return edgeKey(e) < key; });
            while (twin != byKey.end() && edgeKey(*twin) == reversedKey && paired[*twin]) ++twin;
            if (twin == byKey.end() || edgeKey(*twin) != reversedKey) continue;
            paired[edge] = paired[*twin] = true;
            if (windingBeside(edge, *twin) == 0) pairs.emplace_back(edge, *twin);
        }
        for (const auto& [edge, twin] : pairs) std::swap(next_[edge], next_[twin]);
    }

    // Where the boundary passes one point several times (a hole touching its outer ring at a
    // vertex, an outer ring touching itself), each pass arrives at the point and leaves it, and
    // the polygon lies to the left of each pass. Which arrival belongs with which departure is
    // decided by the region, not by the order the rings were written in: sorted around the
    // point, departures and arrivals alternate, and the polygon fills the angle from each
    // departure counter-clockwise to the next arrival. Relinking each departure to that arrival
    // cuts the rings into loops that touch no more: a touching hole joins its outer ring (a
    // bridge of length zero), a hole touching it twice splits the polygon in two, an outer ring
    // touching itself falls apart into its lobes. Points where the passes do not alternate (the
    // rings cross) are left alone.
    void separateTouchingPasses() {
        std::vector<std::size_t> previous(vertices_.size());
        for (std::size_t node = 0; node < vertices_.size(); ++node) previous[next_[node]] = node;
        std::vector<std::size_t> byPoint(vertices_.size());
        std::iota(byPoint.begin(), byPoint.end(), std::size_t(0));
        std::sort(byPoint.begin(), byPoint.end(), [&](std::size_t a, std::size_t b) {
            const IntegerPoint2& p = vertices_[a].point;
            const IntegerPoint2& q = vertices_[b].point;
            return std::tie(p.x, p.y) < std::tie(q.x, q.y);
        });
        for (std::size_t begin = 0; begin < byPoint.size();) {
            std::size_t end = begin + 1;
            while (end < byPoint.size() &&
                   vertices_[byPoint[end]].point == vertices_[byPoint[begin]].point) {
                ++end;
            }
            if (end - begin >= 2) {
                relinkPasses({byPoint.begin() + std::ptrdiff_t(begin),
                              byPoint.begin() + std::ptrdiff_t(end)},
                             previous);
            }
            begin = end;
        }
    }

    std::vector<std::vector<RingVertex>> rings() const {
        std::vector<std::vector<RingVertex>> result;
        std::vector<bool> visited(vertices_.size(), false);
        for (std::size_t first = 0; first < vertices_.size(); ++first) {
            if (visited[first]) continue;
            std::vector<RingVertex> ring;
            for (std::size_t node = first; !visited[node]; node = next_[node]) {
                visited[node] = true;
                ring.push_back(vertices_[node]);
            }
            result.push_back(std::move(ring));
        }
        return result;
    }

private:
    // The winding number of all rings but the edge pair at the pair's midpoint m, or nullopt
    // when m lies on another edge. Exact with doubled coordinates: 2m = from + to, and the
    // orientation of m against an edge (a, b) is the sum of those of from and to.
    std::optional<int> windingBeside(std::size_t edge, std::size_t twin) const {
        const IntegerPoint2& from = vertices_[edge].point;
        const IntegerPoint2& to = vertices_[next_[edge]].point;
        const Int128 twiceX = Int128(from.x) + to.x;
        const Int128 twiceY = Int128(from.y) + to.y;
        int winding = 0;
        for (std::size_t other = 0; other < vertices_.size(); ++other) {
            if (other == edge || other == twin) continue;
            const IntegerPoint2& a = vertices_[other].point;
            const IntegerPoint2& b = vertices_[next_[other]].point;
            const Int128 fromSide = cross(a, b, from);
            const Int128 toSide = cross(a, b, to);
            Int128 sum;
            const int side =
                __builtin_add_overflow(fromSide, toSide, &sum) ? signOf(fromSide) : signOf(sum);
            const bool betweenX = std::min(2 * Int128(a.x), 2 * Int128(b.x)) <= twiceX &&
                                  twiceX <= std::max(2 * Int128(a.x), 2 * Int128(b.x));
            const bool betweenY = std::min(2 * Int128(a.y), 2 * Int128(b.y)) <= twiceY &&
                                  twiceY <= std::max(2 * Int128(a.y), 2 * Int128(b.y));
            if (side == 0 && betweenX && betweenY) return std::nullopt;
            if (2 * Int128(a.y) <= twiceY && twiceY < 2 * Int128(b.y) && side > 0) ++winding;
            if (2 * Int128(b.y) <= twiceY && twiceY < 2 * Int128(a.y) && side < 0) --winding;
        }
        return winding;
    }

    struct Pass {
        IntegerPoint2 direction;  // towards the neighbour, relative to the shared point
        bool departs;
        std::size_t node;
    };

    // Counter-clockwise order of directions, starting at +x; exact.
    static bool turnsBefore(const IntegerPoint2& a, const IntegerPoint2& b) {
        const auto half = [](const IntegerPoint2& d) { return d.y < 0 || (d.y == 0 && d.x < 0); };
        if (half(a) != half(b)) return half(b);
        return orientation({0, 0}, a, b) > 0;
    }

    void relinkPasses(const std::vector<std::size_t>& nodes, std::vector<std::size_t>& previous) {
        const IntegerPoint2& shared = vertices_[nodes.front()].point;
        const auto relative = [&](std::size_t node) {
            const IntegerPoint2& p = vertices_[node].point;
            return IntegerPoint2{p.x - shared.x, p.y - shared.y};
        };
        std::vector<Pass> passes;
        for (const std::size_t node : nodes) {
            passes.push_back({relative(next_[node]), true, node});
            passes.push_back({relative(previous[node]), false, node});
        }
        for (const Pass& pass : passes) {
            if (pass.direction == IntegerPoint2{0, 0}) return;  // a repeated point, not cleaned
        }
        std::sort(passes.begin(), passes.end(), [](const Pass& a, const Pass& b) {
            return turnsBefore(a.direction, b.direction);
        });
        const std::size_t count = passes.size();
        for (std::size_t i = 0; i < count; ++i) {
            const Pass& pass = passes[i];
            const Pass& following = passes[(i + 1) % count];
            const bool sameDirection = !turnsBefore(pass.direction, following.direction) &&
                                       !turnsBefore(following.direction, pass.direction);
            if (sameDirection || pass.departs == following.departs)
                return;  // edges overlap or cross
        }
        // Each departure takes the arrival that follows it counter-clockwise; compute all new
        // predecessors before relinking, as they refer to the old ones.
        std::vector<std::pair<std::size_t, std::size_t>> relinks;  // (departing node, predecessor)
        for (std::size_t i = 0; i < count; ++i) {
            if (!passes[i].departs) continue;
            relinks.emplace_back(passes[i].node, previous[passes[(i + 1) % count].node]);
        }
        for (const auto& [node, predecessor] : relinks) {
            next_[predecessor] = node;
            previous[node] = predecessor;
        }
    }

    std::vector<RingVertex> vertices_;
    std::vector<std::size_t> next_;
};

// The winding number of ring around p, or nullopt when p lies on the ring (Sunday's crossing
// rule, exact).
std::optional<int> windingNumber(const IntegerPoint2& p, const std::vector<RingVertex>& ring) {
    int winding = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const IntegerPoint2& a = ring[i].point;
        const IntegerPoint2& b = ring[(i + 1) % ring.size()].point;
        const int side = orientation(a, b, p);
        if (side == 0 && dot(p, a, b) <= 0) return std::nullopt;  // on the edge
        if (a.y <= p.y && p.y < b.y && side > 0) ++winding;
        if (b.y <= p.y && p.y < a.y && side < 0) --winding;
    }
    return winding;
}

// The outer ring a hole lies in: the first outer ring with a hole point strictly inside it.
std::size_t enclosingOuterRing(const std::vector<RingVertex>& hole,
                               const std::vector<std::vector<RingVertex>>& outers) {
    for (const RingVertex& vertex : hole) {
        for (std::size_t o = 0; o < outers.size(); ++o) {
            const std::optional<int> winding = windingNumber(vertex.point, outers[o]);
            if (winding && *winding != 0) return o;
        }
    }
    return 0;  // every point lies on an outer ring or outside all: input beyond repair
}

bool isWithinRange(const IntegerPoint2& p) {
    constexpr std::int64_t limit = kMaximumTriangulationCoordinate;
    return p.x >= -limit && p.x <= limit && p.y >= -limit && p.y <= limit;
}

// For every input point, the lowest index of a point with the same coordinates.
std::vector<std::uint32_t> representativeIndices(const std::vector<IntegerPoint2>& points) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::tie(points[a].x, points[a].y, a) < std::tie(points[b].x, points[b].y, b);
    });
    std::vector<std::uint32_t> representative(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const bool startsGroup = k == 0 || !(points[order[k]] == points[order[k - 1]]);
        representative[order[k]] = startsGroup ? order[k] : representative[order[k - 1]];
    }
    return representative;
}

}  // namespace

Triangulation triangulatePolygon(const std::vector<std::vector<IntegerPoint2>>& rings) {
    Triangulation result;
    if (rings.empty()) return result;

    std::vector<IntegerPoint2> points;
    std::vector<std::size_t> ringOffsets;
    for (const auto& ring : rings) {
        ringOffsets.push_back(points.size());
        points.insert(points.end(), ring.begin(), ring.end());
    }
    ringOffsets.push_back(points.size());
    if (points.size() > std::numeric_limits<std::uint32_t>::max() ||
        !std::all_of(points.begin(), points.end(), isWithinRange)) {
        result.complete = false;
        return result;
    }
    const std::vector<std::uint32_t> representative = representativeIndices(points);

    // Clean each ring and bring it to the orientation the ear clipper expects: the outer ring
    // counter-clockwise, holes clockwise. Rings that enclose no area are left out.
    std::vector<std::vector<RingVertex>> orientedRings;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        std::vector<RingVertex> ring;
        ring.reserve(rings[r].size());
        for (std::size_t i = ringOffsets[r]; i < ringOffsets[r + 1]; ++i) {
            ring.push_back({points[i], representative[i]});
        }
        // Removing spikes takes a ring whose points all lie on one line down to two points or
        // fewer; a longer ring without area crosses itself (a bow tie).
        ring = withoutRepeatsAndSpikes(ring);
        const int areaSign = ring.size() < 3 ? 0 : ringAreaSign(pointsOf(ring));
        if (areaSign == 0) {
            if (ring.size() >= 3) result.complete = false;
            if (r == 0) return result;  // nothing to cover
            continue;
        }
        if ((r == 0) != (areaSign > 0)) std::reverse(ring.begin(), ring.end());
        orientedRings.push_back(std::move(ring));
    }

    // Rings touch only at points that occur more than once; most cells have none and skip the
    // contact resolution. Resolving contacts can join the outer ring with holes and split it
    // into several outer rings; the orientation tells which is which, as the outer ring ran
    // counter-clockwise.
    std::vector<bool> occurs(points.size(), false);
    bool anyPointRepeats = false;
    for (const std::vector<RingVertex>& ring : orientedRings) {
        for (const RingVertex& vertex : ring) {
            anyPointRepeats = anyPointRepeats || occurs[vertex.index];
            occurs[vertex.index] = true;
        }
    }
    std::vector<std::vector<RingVertex>> separatedRings = orientedRings;
    if (anyPointRepeats) {
        RingGraph withSharedEdges(orientedRings);
        withSharedEdges.cancelSharedEdges();
        std::vector<std::vector<RingVertex>> withoutSharedEdges;
        for (std::vector<RingVertex>& ring : withSharedEdges.rings()) {
            withoutSharedEdges.push_back(withoutRepeatsAndSpikes(ring));
        }
        RingGraph withTouchingPasses(withoutSharedEdges);
        withTouchingPasses.separateTouchingPasses();
        separatedRings = withTouchingPasses.rings();
    }
    std::vector<std::vector<RingVertex>> outers;
    std::vector<std::vector<RingVertex>> holes;
    for (std::vector<RingVertex>& ring : separatedRings) {
        ring = withoutRepeatsAndSpikes(ring);
        const int areaSign = ring.size() < 3 ? 0 : ringAreaSign(pointsOf(ring));
        if (areaSign > 0) outers.push_back(std::move(ring));
        if (areaSign < 0) holes.push_back(std::move(ring));
    }
    std::vector<std::vector<std::vector<RingVertex>>> holesOfOuter(outers.size());
    for (std::vector<RingVertex>& hole : holes) {
        if (outers.empty()) {
            result.complete = false;  // holes cover the outer ring more than once
            break;
        }
        const std::size_t o = outers.size() == 1 ? 0 : enclosingOuterRing(hole, outers);
        holesOfOuter[o].push_back(std::move(hole));
    }

    for (std::size_t o = 0; o < outers.size(); ++o) {
        if (holesOfOuter[o].empty() && isConvex(outers[o]) &&
            triangulateConvex(outers[o], result.triangles)) {
            continue;
        }
        EarClipper clipper(outers[o], holesOfOuter[o]);
        if (!clipper.triangulate(result.triangles)) result.complete = false;
    }
    return result;
}

}  // namespace nurbslod
