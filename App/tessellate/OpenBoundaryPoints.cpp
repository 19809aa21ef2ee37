#include "tessellate/OpenBoundaryPoints.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "tessellate/LeastBoundRing.hpp"

namespace nurbslod {

namespace {

using Triangle = RingTriangle;
using ring::cross;
using ring::emptyRingTriangle;
using ring::segmentsCross;
using ring::trianglesOfSplits;

// The vertices around v in counter-clockwise order n0 .. nm when v lies on the mesh's boundary
// and its triangles (v, n_i, n_i+1) form one fan; none otherwise (an inner vertex, a pinch).
std::optional<std::vector<std::uint32_t>> ringAround(std::uint32_t v,
                                                     const std::vector<Triangle>& triangles,
                                                     const std::vector<std::size_t>& fan) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;  // n_i -> n_i+1
    for (std::size_t t : fan) {
        const Triangle& tri = triangles[t];
        int at = 0;
        while (tri[at] != v) ++at;
        links.push_back({tri[(at + 1) % 3], tri[(at + 2) % 3]});
    }
    std::optional<std::uint32_t> start;
    for (const auto& [from, to] : links) {
        const bool isTarget = std::any_of(links.begin(), links.end(),
                                          [&](const auto& link) { return link.second == from; });
        if (isTarget) continue;
        if (start) return std::nullopt;  // two open ends: not one fan
        start = from;
    }
    if (!start) return std::nullopt;  // a closed ring: an inner vertex
    std::vector<std::uint32_t> ring{*start};
    while (ring.size() <= links.size()) {
        auto next = std::find_if(links.begin(), links.end(),
                                 [&](const auto& link) { return link.first == ring.back(); });
        if (next == links.end()) return std::nullopt;
        ring.push_back(next->second);
    }
    std::vector<std::uint32_t> sorted = ring;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return std::nullopt;
    return ring;
}

// The longest diagonal searched that has no end at the chord's ends (leastChangingTriangulation).
constexpr std::size_t kLocalSpan = 8;

// A closed axis-aligned box: two segments whose boxes do not meet cannot cross.
struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box& other) const {
        return x0 <= other.x1 && other.x0 <= x1 && y0 <= other.y1 && other.y0 <= y1;
    }
};

Box boxOf(const Point2& a, const Point2& b) {
    return {std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()),
            std::max(a.y(), b.y())};
}

// An old inner edge in the plane normal to the mean normal, with its ends' heights along it.
struct PlanarEdge {
    std::uint32_t a, b;
    Point2 from, to;
    double fromHeight, toHeight;
};

// An old inner edge laid out by one of its ends on the ring: `other` is the ring index of its
// other end (-1: a dropped point).
struct EdgeFromRing {
    Point2 from, direction;
    double fromHeight, heightChange;
    int other;
};

// The search's arrays, kept per thread from one call to the next. A strip whose cells cut its
// free chords at thousands of points tries tens of thousands of small rings, most of which fail
// (the generated ruled face between a circle and an ellipse at relative 1e-4: 29,000 rings of 6
// points on average), and allocating the n x n tables as rows was about half of each try.
struct SearchTables {
    std::vector<Point2> ringUv, ringPlanar;
    std::vector<double> ringHeight;
    std::vector<PlanarEdge> inner;
    std::vector<int> innerRing;  // the ring indices of each inner edge's ends, two per edge
    std::vector<EdgeFromRing> fromRing;
    std::vector<std::size_t> fromRingStart;
    // where each ring point's next edge goes in fromRing, while they are laid out
    std::vector<std::size_t> fromRingNext;
    std::vector<std::size_t> crossable;
    std::vector<Box> sideBoxes;
    // size x size, row-major
    std::vector<double> diagonal, cost;
    std::vector<std::size_t> split;

    // Rings up to this size keep their tables (3 x 256^2 x 8 bytes = 1.5 MB a thread); a larger
    // one gives its memory back when its search ends (up to 24 MB at kLargestRing), so that no
    // thread of a long-running FreeCAD process holds it.
    static constexpr std::size_t kKeptRing = 256;
    void releaseAfter(std::size_t size) {
        if (size <= kKeptRing) return;
        *this = SearchTables{};
    }
};

// Calls tables.releaseAfter(size) when the search ends, by whichever return.
struct ReleaseTablesAfter {
    SearchTables& tables;
    std::size_t size;
    ~ReleaseTablesAfter() { tables.releaseAfter(size); }
};

// The triangulation of the ring n0 .. nm (closed by the chord nm -> n0 that the points to drop
// lie on) that least changes the surface, and that change. `old` are the triangles about those
// points (their union is a disk whose boundary is the ring and the chord). Both the old
// triangles and the new ones are graphs of heights along their mean normal over one region of
// the plane normal to it, where every triangle faces that normal: a point of the new triangles
// is then within their height difference of the old ones. The difference is linear on the
// overlay of the two triangulations, so it is largest at the overlay's vertices: the ring's
// points (no difference), the dropped points (on the new chord) and where an old inner edge
// crosses a new diagonal. Each diagonal's largest difference is its own, so the best
// triangulation (of those whose diagonals are searched, see `searched`) is found by the polygon
// triangulation recurrence over the ring, minimising the largest difference. None where no
// triangulation is valid in (u, v) and in space. forbidden[i * ring.size() + j] tells that the
// diagonal (i, j) may not be made (it is already an edge outside the old triangles). None too where
// every triangulation changes the surface by more than `limit` (what the caller could still
// accept): the diagonals that alone change it more are not searched, which leaves the best one, if
// it is within the limit, as it was.
std::optional<std::pair<std::vector<Triangle>, double>> leastChangingTriangulation(
    const std::vector<std::uint32_t>& dropped, const std::vector<std::uint32_t>& ring,
    const std::vector<Triangle>& old, const FaceMesh& mesh, const std::vector<char>& forbidden,
    double limit) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    thread_local SearchTables tables;
    const ReleaseTablesAfter release{tables, ring.size()};
    auto position = [&](std::uint32_t i) -> const Point3& { return mesh.vertices[i].position; };
    std::vector<Point2>& ringUv = tables.ringUv;
    ringUv.resize(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) ringUv[i] = mesh.vertices[ring[i]].uv;
    auto uv = [&](std::size_t i) -> const Point2& { return ringUv[i]; };
    auto areaNormal = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) -> Vector3 {
        return (position(b) - position(a)).cross(position(c) - position(a));
    };
    const std::size_t size = ring.size(), m = size - 1;
    // how far the dropped points are from the chord, which the new triangles follow there
    const Point3& first = position(ring.front());
    const Point3& last = position(ring.back());
    const Vector3 chord = first - last;
    double ontoChord = 0;
    for (std::uint32_t v : dropped) {
        const double t =
            std::clamp((position(v) - last).dot(chord) / chord.squaredNorm(), 0.0, 1.0);
        ontoChord = std::max(ontoChord, (last + t * chord - position(v)).norm());
    }
    if (ontoChord > limit) return std::nullopt;
    Vector3 normal = Vector3::Zero();
    for (const Triangle& t : old) normal += areaNormal(t[0], t[1], t[2]);
    if (!(normal.norm() > 0)) return std::nullopt;
    normal.normalize();
    auto facesNormal = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const Vector3 n = areaNormal(a, b, c);
        return n.dot(normal) > 1e-6 * n.norm();
    };
    for (const Triangle& t : old)
        if (!facesNormal(t[0], t[1], t[2])) return std::nullopt;
    const Vector3 across = normal.unitOrthogonal(), along = normal.cross(across);
    auto planar = [&](std::uint32_t i) {
        return Point2(across.dot(position(i)), along.dot(position(i)));
    };
    // the ring's points in the plane and their heights along the normal, once
    std::vector<Point2>& ringPlanar = tables.ringPlanar;
    std::vector<double>& ringHeight = tables.ringHeight;
    ringPlanar.resize(size);
    ringHeight.resize(size);
    for (std::size_t i = 0; i < size; ++i) {
        ringPlanar[i] = planar(ring[i]);
        ringHeight[i] = normal.dot(position(ring[i]));
    }
    // One sheet: every old triangle faces the normal, so each point of the plane inside the
    // boundary is covered as many times as the boundary winds round it, once where the ring
    // closed by the chord is a simple polygon in the plane.
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = i + 2; j < size; ++j) {
            if (i == 0 && j == m) continue;  // adjacent through the chord
            if (segmentsCross(ringPlanar[i], ringPlanar[(i + 1) % size], ringPlanar[j],
                              ringPlanar[(j + 1) % size]))
                return std::nullopt;
        }
    if (dropped.size() == 1) {
        // the old fan turns once about its point (half a turn, the point being on the chord)
        const Point2 centre = planar(dropped.front());
        double turn = 0;
        for (std::size_t i = 0; i < m; ++i) {
            const Point2 a = ringPlanar[i] - centre, b = ringPlanar[i + 1] - centre;
            turn += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        }
        if (!(turn < 1.5 * std::numbers::pi)) return std::nullopt;
    }
    double extent = 0;
    for (std::size_t i = 0; i < size; ++i)
        for (std::size_t j = 0; j < size; ++j)
            extent = std::max(extent, (uv(i) - uv(j)).squaredNorm());
    const double minimumArea = 1e-14 * extent;

    // the old inner edges (each in two old triangles), in the plane with their heights
    std::vector<PlanarEdge>& inner = tables.inner;
    inner.clear();
    for (std::size_t t = 0; t < old.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = old[t][k], b = old[t][(k + 1) % 3];
            if (a > b) continue;  // each inner edge once, from the side where a < b
            const bool twice = std::any_of(old.begin(), old.end(), [&](const Triangle& other) {
                for (int l = 0; l < 3; ++l)
                    if (other[l] == b && other[(l + 1) % 3] == a) return true;
                return false;
            });
            if (twice)
                inner.push_back(
                    {a, b, planar(a), planar(b), normal.dot(position(a)), normal.dot(position(b))});
        }

    // The inner edges by their ends on the ring (the others end at dropped points). In the
    // plane the old triangles tile the polygon ring + chord once, and a diagonal (i, j) that a
    // valid triangulation uses lies inside it (its triangles all face the normal and tile the
    // polygon too), so the inner edges it crosses are those from a ring point between i and j
    // to a dropped point or to a ring point beyond i .. j: only they are visited. A diagonal
    // outside the polygon, which no valid triangulation uses, may be under-counted. They are
    // laid out by ring point in one array (read for every diagonal over it), each with the ring
    // index of its other end (-1: a dropped point); an edge between two ring points is listed
    // at both.
    auto ringIndexOf = [&](std::uint32_t vertex) {
        const auto at = std::find(ring.begin(), ring.end(), vertex);
        return at == ring.end() ? -1 : static_cast<int>(at - ring.begin());
    };
    // counted by ring point, then laid out in the order of `inner` within each
    std::vector<int>& innerRing = tables.innerRing;
    innerRing.resize(2 * inner.size());
    std::vector<std::size_t>& fromRingStart = tables.fromRingStart;
    fromRingStart.assign(size + 1, 0);
    for (std::size_t k = 0; k < inner.size(); ++k) {
        innerRing[2 * k] = ringIndexOf(inner[k].a);
        innerRing[2 * k + 1] = ringIndexOf(inner[k].b);
        for (const int end : {innerRing[2 * k], innerRing[2 * k + 1]})
            if (end >= 0) ++fromRingStart[static_cast<std::size_t>(end) + 1];
    }
    for (std::size_t k = 0; k < size; ++k) fromRingStart[k + 1] += fromRingStart[k];
    std::vector<EdgeFromRing>& fromRing = tables.fromRing;
    fromRing.resize(fromRingStart[size]);
    {
        std::vector<std::size_t>& next = tables.fromRingNext;
        next.assign(fromRingStart.begin(), fromRingStart.end() - 1);
        for (std::size_t k = 0; k < inner.size(); ++k) {
            const PlanarEdge& edge = inner[k];
            const int a = innerRing[2 * k], b = innerRing[2 * k + 1];
            EdgeFromRing laidOut{edge.from, edge.to - edge.from, edge.fromHeight,
                                 edge.toHeight - edge.fromHeight, b};
            if (a >= 0) fromRing[next[static_cast<std::size_t>(a)]++] = laidOut;
            laidOut.other = a;
            if (b >= 0) fromRing[next[static_cast<std::size_t>(b)]++] = laidOut;
        }
    }

    // The ring's sides that a diagonal could cross in (u, v), with their boxes to pass over
    // those far from it. A side with every ring point on one side of its line (or on it) is
    // crossed by no diagonal: segmentsCross needs the diagonal's ends strictly on both sides,
    // and measures them with the same cross products. On the strips along a free edge the
    // ring is all but convex and few sides are left (wing.brep: none): the test per diagonal
    // was a third of the search.
    std::vector<std::size_t>& crossable = tables.crossable;
    std::vector<Box>& sideBoxes = tables.sideBoxes;
    crossable.clear();
    sideBoxes.clear();
    for (std::size_t k = 0; k < m; ++k) {
        bool left = false, right = false;
        for (std::size_t w = 0; w < size && !(left && right); ++w) {
            const double side = cross(uv(k), uv(k + 1), uv(w));
            left |= side > 0;
            right |= side < 0;
        }
        if (!(left && right)) continue;
        crossable.push_back(k);
        sideBoxes.push_back(boxOf(uv(k), uv(k + 1)));
    }

    // The diagonals searched: those from the chord's ends n0 and nm, and those that span at most
    // kLocalSpan sides of the ring. The best triangulation of a strip along a chord is two fans
    // from its ends, met by one triangle on the chord, with small local changes: on the corpus
    // the meshes are byte for byte those of the search over every diagonal (even with a span of
    // 1), at O(n^2 + n kLocalSpan^2) in place of O(n^3); the wing's rings of 250 took 15 ms each.
    // Whatever the search finds, its change is measured exactly, so a diagonal left out can only
    // cost a triangulation, never the bound.
    auto searched = [&](std::size_t i, std::size_t j) {
        return i == 0 || j == m || j - i <= kLocalSpan;
    };

    // the largest height difference along the diagonal (i, j), infinite where it may not be made
    auto measureDiagonal = [&](std::size_t i, std::size_t j) -> double {
        if (forbidden[i * size + j] || !searched(i, j)) return kNever;
        // the edges from ring points i + 1 .. j - 1 lie together in fromRing
        const Point2 d2 = ringPlanar[j] - ringPlanar[i];
        const double heightAtI = ringHeight[i], heightChange = ringHeight[j] - heightAtI;
        double largest = 0;
        for (std::size_t at = fromRingStart[i + 1]; at < fromRingStart[j]; ++at) {
            const EdgeFromRing& edge = fromRing[at];
            // an edge between two ring points on one side, or one meeting the diagonal at
            // its ends, crosses nothing (the latter made no difference before either)
            if (edge.other >= static_cast<int>(i) && edge.other <= static_cast<int>(j)) continue;
            // from + s direction = n_i + r (n_j - n_i) in the plane; s and r are kept as
            // numerators over the determinant, which spares two divisions per edge (this
            // loop is most of the search)
            const Point2& d1 = edge.direction;
            const Point2 w = ringPlanar[i] - edge.from;
            const double determinant = d1.x() * d2.y() - d1.y() * d2.x();
            if (determinant == 0) continue;
            const double sTimes = w.x() * d2.y() - w.y() * d2.x();
            const double rTimes = w.x() * d1.y() - w.y() * d1.x();
            const bool outside =
                determinant > 0
                    ? (sTimes < 0 || sTimes > determinant || rTimes < 0 || rTimes > determinant)
                    : (sTimes > 0 || sTimes < determinant || rTimes > 0 || rTimes < determinant);
            if (outside) continue;
            // (was - now) times the determinant
            const double differenceTimes = (edge.fromHeight - heightAtI) * determinant +
                                           sTimes * edge.heightChange - rTimes * heightChange;
            if (std::abs(differenceTimes) > largest * std::abs(determinant))
                largest = std::abs(differenceTimes / determinant);
            if (largest > limit) break;
        }
        // A diagonal that alone changes the surface by more than the limit is in no
        // triangulation the caller could take: the search leaves it out (its cost stays
        // infinite) without testing its crossings.
        if (largest > limit) return kNever;
        // only a side whose box meets the diagonal's can cross it
        const Box diagonalBox = boxOf(uv(i), uv(j));
        bool crosses = false;
        for (std::size_t c = 0; c < crossable.size() && !crosses; ++c) {
            const std::size_t k = crossable[c];
            crosses =
                sideBoxes[c].meets(diagonalBox) && segmentsCross(uv(i), uv(j), uv(k), uv(k + 1));
        }
        if (crosses) return kNever;
        return largest;
    };
    std::vector<double>& diagonal = tables.diagonal;
    diagonal.assign(size * size, kNever);
    auto setDiagonal = [&](std::size_t i, std::size_t j) {
        diagonal[i * size + j] = diagonal[j * size + i] = measureDiagonal(i, j);
    };
    // The diagonals from the chord's ends first: every triangulation has the triangle
    // (n0, nk, nm) on the chord, so where no k has both its sides within the limit there is none
    // to search. Most rings tried on a strip whose cells leave thousands of points on its free
    // chords end here (the generated ruled face between a circle and an ellipse at relative
    // 1e-4: 25,785 of the 25,796 that fail).
    for (std::size_t j = 2; j < m; ++j) setDiagonal(0, j);
    for (std::size_t i = 1; i + 2 <= m; ++i) setDiagonal(i, m);
    bool chordTriangle = false;
    for (std::size_t k = 1; k < m && !chordTriangle; ++k)
        chordTriangle =
            (k == 1 || diagonal[k] != kNever) && (k + 1 == m || diagonal[k * size + m] != kNever);
    if (!chordTriangle) return std::nullopt;
    for (std::size_t i = 1; i < size; ++i)
        for (std::size_t j = i + 2; j < m; ++j) setDiagonal(i, j);
    // sides (consecutive points and the chord) cost nothing; diagonal is symmetric, so that the
    // search below reads (k, j) as the row j, in order
    for (std::size_t i = 0; i < m; ++i)
        diagonal[i * size + i + 1] = diagonal[(i + 1) * size + i] = 0.0;
    diagonal[m] = diagonal[m * size] = 0.0;
    auto triangleValid = [&](std::size_t i, std::size_t k, std::size_t j) {
        return emptyRingTriangle(uv, size, i, k, j, minimumArea) &&
               facesNormal(ring[i], ring[k], ring[j]);
    };
    // cost (i, j): the least largest difference over triangulations of the sub-polygon i .. j,
    // kept in both halves (cost (j, i) too) so that the search reads rows only
    std::vector<double>& cost = tables.cost;
    std::vector<std::size_t>& split = tables.split;
    cost.assign(size * size, 0.0);
    split.assign(size * size, 0);
    for (std::size_t length = 2; length <= m; ++length)
        for (std::size_t i = 0; i + length <= m; ++i) {
            const std::size_t j = i + length;
            double best = kNever;
            const double outer = diagonal[i * size + j];
            if (outer != kNever) {
                const double* fromI = &cost[i * size];
                const double* toJ = &cost[j * size];
                const double* diagonalsOfI = &diagonal[i * size];
                const double* diagonalsOfJ = &diagonal[j * size];
                // no split costs less than the outer diagonal: once one reaches it, the first
                // such split is the one kept
                for (std::size_t k = i + 1; k < j && best > outer; ++k) {
                    const double c =
                        std::max({fromI[k], toJ[k], diagonalsOfI[k], diagonalsOfJ[k], outer});
                    if (c < best && triangleValid(i, k, j)) best = c, split[i * size + j] = k;
                }
            }
            cost[i * size + j] = cost[j * size + i] = best;
        }
    if (cost[m] == kNever) return std::nullopt;
    return std::make_pair(trianglesOfSplits(ring, split), std::max(cost[m], ontoChord));
}

// The search keeps n x n tables of the ring: a larger ring keeps its points (wing.brep's
// largest at relative 1e-4 is 251).
constexpr std::size_t kLargestRing = 1024;
// The rings bounded against the surface (leastBoundTriangulation, which bounds each of its
// O(n^3) triangles): those of one or two points on a chord have 4 to 6. Up to 8 took one open
// edge fewer on 4 of the 26 runs of the free-edge models (shell1.brep, MAT.brep and the
// generated fitted surface and ruled face) for 0.6% more time over the 26.
constexpr std::size_t kLargestBoundedRing = 8;
// A face's rings are bounded so while no more than kBoundedTries and kBoundedTriesPerTaken for
// each one taken have failed: on a strip of cells far thinner than the chords they cut (the
// generated ruled face between a circle and an ellipse at relative 1e-4: 190 of 20,830 taken)
// the bounds would cost more than the rest of the face.
constexpr std::size_t kBoundedTries = 16, kBoundedTriesPerTaken = 8;

// v lies on the chord from `last` to `first` in space, strictly between them.
bool onChord(const FaceMesh& mesh, std::uint32_t v, std::uint32_t last, std::uint32_t first) {
    const Point3& from = mesh.vertices[last].position;
    const Vector3 chord = mesh.vertices[first].position - from;
    const double length2 = chord.squaredNorm();
    if (!(length2 > 0)) return false;
    const Vector3 fromLast = mesh.vertices[v].position - from;
    const double t = fromLast.dot(chord) / length2;
    return t > 0 && t < 1 && (fromLast - t * chord).squaredNorm() <= 1e-18 * length2;
}

// The disk of the live triangles about `points` (consecutive points of one chord): its boundary
// from the chord's one end round to the other (the ring n0 .. nm, the points then following
// from nm back to n0), and its triangles; none where they are not one disk with every vertex
// on that boundary.
std::optional<std::pair<std::vector<std::uint32_t>, std::vector<std::size_t>>> diskAbout(
    const std::vector<std::uint32_t>& points, const std::vector<Triangle>& triangles,
    const std::vector<std::vector<std::size_t>>& trianglesOf, const std::vector<char>& removed) {
    std::vector<std::size_t> disk;
    for (std::uint32_t p : points)
        for (std::size_t t : trianglesOf[p])
            if (!removed[t]) disk.push_back(t);
    std::sort(disk.begin(), disk.end());
    disk.erase(std::unique(disk.begin(), disk.end()), disk.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges, boundary;
    for (std::size_t t : disk)
        for (int k = 0; k < 3; ++k) edges.push_back({triangles[t][k], triangles[t][(k + 1) % 3]});
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges)
        if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)))
            boundary.push_back({a, b});
    // one boundary edge out of every vertex, one cycle through all of them
    std::vector<std::uint32_t> vertices;
    for (const auto& [a, b] : edges) vertices.push_back(a);
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    if (boundary.size() != vertices.size() || disk.size() + 2 != vertices.size())
        return std::nullopt;
    for (std::size_t i = 0; i + 1 < boundary.size(); ++i)
        if (boundary[i].first == boundary[i + 1].first) return std::nullopt;
    auto next = [&](std::uint32_t a) {
        return std::lower_bound(boundary.begin(), boundary.end(), std::make_pair(a, 0u))->second;
    };
    // the cycle runs ..., nm, the points from the last to the first, n0, ...
    std::vector<std::uint32_t> cycle{next(points.front())};
    while (cycle.size() < vertices.size() && cycle.back() != points.back())
        cycle.push_back(next(cycle.back()));
    if (cycle.back() != points.back()) return std::nullopt;
    cycle.pop_back();
    if (cycle.size() + points.size() != vertices.size()) return std::nullopt;
    std::uint32_t at = points.back();
    for (std::size_t k = points.size(); k-- > 0;) {
        if (at != points[k]) return std::nullopt;
        at = next(at);
    }
    if (at != cycle.front()) return std::nullopt;
    return std::make_pair(std::move(cycle), std::move(disk));
}

}  // namespace

std::size_t removeOpenBoundaryPoints(FaceMesh& mesh, const std::vector<double>& sharedOffsets,
                                     const std::vector<double>& slack, double allowance,
                                     const TriangleBound& triangleBound, double surfaceShare) {
    const std::size_t vertexCount = mesh.vertices.size();
    std::vector<std::vector<std::size_t>> trianglesOf(vertexCount);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t i : mesh.triangles[t]) trianglesOf[i].push_back(t);
    std::vector<char> removed(mesh.triangles.size(), 0);
    // how far each triangle may be from the face's first triangles, less its cell's slack (the
    // first triangles are within the cell's bound of the surface, the surface share less the
    // slack): a re-triangulation of triangles that an earlier one made adds to what that one
    // changed
    std::vector<double> changed(mesh.triangles.size(), 0.0);
    for (std::size_t t = 0; t < changed.size() && t < slack.size(); ++t)
        changed[t] = -std::max(0.0, slack[t]);
    std::vector<char> dropped(vertexCount, 0), chordTried(vertexCount, 0);
    std::size_t boundedTried = 0, boundedTaken = 0;
    std::size_t count = 0;

    // the ring about v where v is the face's own point, its triangles one fan, and it lies on
    // the chord between its two boundary neighbours in space
    auto chordRing = [&](std::uint32_t v) -> std::optional<std::vector<std::uint32_t>> {
        if (mesh.vertices[v].shared || dropped[v]) return std::nullopt;
        std::vector<std::size_t>& fan = trianglesOf[v];
        fan.erase(std::remove_if(fan.begin(), fan.end(), [&](std::size_t t) { return removed[t]; }),
                  fan.end());
        if (fan.empty()) return std::nullopt;
        auto ring = ringAround(v, mesh.triangles, fan);
        if (!ring || !onChord(mesh, v, ring->back(), ring->front())) return std::nullopt;
        return ring;
    };

    // Adds to `points` (consecutive on one chord) the chord's points beyond its first one
    // (towardFront, starting at `next`) or beyond its last: each one's ring holds the point
    // before it as its neighbour on that side.
    auto extendAlongChord = [&](std::vector<std::uint32_t>& points, std::uint32_t next,
                                bool towardFront) {
        for (std::uint32_t previous = towardFront ? points.front() : points.back();
             points.size() < vertexCount;) {
            const auto nextRing = chordRing(next);
            if (!nextRing || (towardFront ? nextRing->back() : nextRing->front()) != previous)
                break;
            points.insert(towardFront ? points.begin() : points.end(), next);
            previous = next;
            next = towardFront ? nextRing->front() : nextRing->back();
        }
    };

    // drops `points` (consecutive on one chord, the first next to the ring's first point) when
    // their disk's re-triangulation is within the allowance
    auto drop = [&](const std::vector<std::uint32_t>& points) {
        const auto disk = diskAbout(points, mesh.triangles, trianglesOf, removed);
        if (!disk) return false;
        const auto& [ring, inside] = *disk;
        const std::size_t size = ring.size();
        if (size < 3 || size > kLargestRing) return false;
        // a new diagonal that is already an edge outside the disk would make a non-manifold edge
        std::vector<char> forbidden(size * size, 0);
        for (std::size_t a = 0; a < size; ++a)
            for (std::size_t t : trianglesOf[ring[a]]) {
                if (removed[t] || std::binary_search(inside.begin(), inside.end(), t)) continue;
                for (std::uint32_t b : mesh.triangles[t]) {
                    const auto at = std::find(ring.begin(), ring.end(), b);
                    if (at == ring.end()) continue;
                    const std::size_t j = static_cast<std::size_t>(at - ring.begin());
                    forbidden[a * size + j] = forbidden[j * size + a] = 1;
                }
            }
        std::vector<Triangle> old;
        for (std::size_t t : inside) old.push_back(mesh.triangles[t]);
        double ringOffset = 0;
        for (std::uint32_t i : ring)
            if (mesh.vertices[i].shared)
                ringOffset = std::max(ringOffset, sharedOffsets[mesh.vertices[i].sharedId]);
        double before = -std::numeric_limits<double>::infinity();
        for (std::size_t t : inside) before = std::max(before, changed[t]);
        // the new triangles and how far each may be from the surface beyond the surface share
        // (what `changed` holds)
        std::optional<std::vector<Triangle>> chosen;
        double newChange = 0;
        const double limit = allowance - before - ringOffset;
        if (limit >= 0)
            if (auto best = leastChangingTriangulation(points, ring, old, mesh, forbidden, limit);
                best && before + best->second + ringOffset <= allowance) {
                chosen = std::move(best->first);
                newChange = before + best->second;
            }
        if (!chosen && triangleBound && size <= kLargestBoundedRing &&
            boundedTried < kBoundedTries + kBoundedTriesPerTaken * boundedTaken) {
            ++boundedTried;
            // bounded against the surface instead (their corners' offsets included), turned
            // against the surface's normals as the old triangles are
            const auto bounded =
                leastBoundTriangulation(ring, mesh, forbidden, ring::facingOf(mesh, old),
                                        triangleBound, surfaceShare + allowance);
            if (bounded) {
                chosen = std::move(bounded->first);
                newChange = bounded->second - surfaceShare;
                ++boundedTaken;
            }
        }
        if (!chosen) return false;
        for (std::size_t t : inside) removed[t] = 1;
        for (std::uint32_t p : points) {
            dropped[p] = 1;
            trianglesOf[p].clear();
        }
        for (const Triangle& triangle : *chosen) {
            const std::size_t index = mesh.triangles.size();
            mesh.triangles.push_back(triangle);
            removed.push_back(0);
            changed.push_back(newChange);
            for (std::uint32_t i : triangle) trianglesOf[i].push_back(index);
        }
        count += points.size();
        return true;
    };

    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        const auto ring = chordRing(v);
        if (!ring) continue;
        if (!chordTried[v]) {
            // every such point of v's chord at once: dropped one by one, each one's new
            // triangles join the next one's fan, whose ring grows with every point
            std::vector<std::uint32_t> points{v};
            extendAlongChord(points, ring->front(), true);
            extendAlongChord(points, ring->back(), false);
            for (std::uint32_t p : points) chordTried[p] = 1;
            if (points.size() > 1) {
                const std::uint32_t first = chordRing(points.front())->front();
                const std::uint32_t last = chordRing(points.back())->back();
                const bool oneChord =
                    std::all_of(points.begin(), points.end(),
                                [&](std::uint32_t p) { return onChord(mesh, p, last, first); });
                if (oneChord) {
                    // all at once, else each half (the halves' rings then hold the points the
                    // other half keeps, still on the chord)
                    std::vector<std::vector<std::uint32_t>> runs{points};
                    while (!runs.empty()) {
                        const std::vector<std::uint32_t> run = std::move(runs.back());
                        runs.pop_back();
                        if (drop(run) || run.size() == 1) continue;
                        const auto middle = run.begin() + run.size() / 2;
                        runs.emplace_back(middle, run.end());
                        runs.emplace_back(run.begin(), middle);
                    }
                    continue;
                }
            }
        }
        // v alone, its fan as it is now
        drop({v});
    }
    ring::dropRemoved(mesh.triangles, removed);
    return count;
}

}  // namespace nurbslod
