#include "tessellate/FaceTessellator.hpp"

#include <algorithm>
#include <array>
#include <boost/sort/spreadsort/integer_sort.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "geometry/PointSetEvaluator.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "tessellate/CellTriangulation.hpp"
#include "tessellate/InteriorPoints.hpp"
#include "tessellate/IsoRunLines.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "tessellate/NeedleSplit.hpp"
#include "tessellate/OpenBoundaryPoints.hpp"
#include "tessellate/PolygonTriangulator.hpp"
#include "tessellate/RectangleInRegion.hpp"
#include "tessellate/TriangleAffineMap.hpp"
#include "tessellate/TriangleDeviation.hpp"
#include "tessellate/WindingRectangleClip.hpp"

namespace nurbslod {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

// The loops' points in space, one ring per loop, each point where `position` puts it.
template <typename Position>
std::vector<std::vector<Point3>> ringsInSpace(const std::vector<BoundaryLoop>& loops,
                                              const Position& position) {
    std::vector<std::vector<Point3>> rings;
    for (const auto& loop : loops) {
        rings.emplace_back();
        for (const auto& bp : loop.points) rings.back().push_back(position(bp));
    }
    return rings;
}

// Integer steps across the boundary's bounding box (KdTreeGrid, which the edges align with).
constexpr cInt kScale = kKdTreeFrameScale;
// Deep enough for 2^-60 of a face; a face that needs more is broken, and is reported.
constexpr int kMaxDepth = 60;

std::int64_t keyOf(cInt x, cInt y) {
    return (x << 32) ^ (y & 0xffffffff);
}

struct Rect {
    cInt x0, y0, x1, y1;
    Path path() const { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
};

// One clipper per thread, cleared between uses: a new one allocated its lists anew for every
// kd-tree cell and leaf.
ClipperLib::Clipper& threadClipper() {
    thread_local ClipperLib::Clipper clipper;
    clipper.Clear();
    return clipper;
}

// A cell's piece of a one-ring region, the kd-tree's common case (about 11 points a piece on
// bug33398.step), in one pass over its points (clipSimpleRing): the clipper's sweep spent about
// 18,000 instructions on each, 17% of that model's at relative 1e-4. The piece is the same point
// set; it keeps a boundary point where the ring runs along the cell's side, which the clipper
// keeps or drops depending on the direction it runs (no guaranteed mesh of the corpus changed
// but for 2 triangles of one trj7 face at 1e-4). Only for a region known to be one simple ring
// (oneSimpleRing); the piece, one simple ring or none, is then one too. None (std::nullopt)
// where the region is not such a ring or clipSimpleRing leaves it to the clipper.
std::optional<Paths> simpleRingPiece(const Paths& region, bool oneSimpleRing, const Rect& r) {
    if (!oneSimpleRing || region.size() != 1) return std::nullopt;
    auto ring = clipSimpleRing(region[0], r.x0, r.y0, r.x1, r.y1);
    if (!ring) return std::nullopt;
    Paths piece;  // moved in: a braced list would copy the ring
    if (!ring->empty()) piece.push_back(std::move(*ring));
    return piece;
}

// The region's piece of r: simpleRingPiece where it answers (a piece that keeps collinear
// points), else the clipper's; `simpleOut`, where given, tells whether it was the former.
Paths clip(const Paths& subject, const Rect& r, bool preserveCollinear, bool oneSimpleRing,
           bool* simpleOut = nullptr) {
    if (simpleOut) *simpleOut = false;
    if (preserveCollinear)
        if (auto piece = simpleRingPiece(subject, oneSimpleRing, r)) {
            if (simpleOut) *simpleOut = true;
            return std::move(*piece);
        }
    ClipperLib::Clipper& clipper = threadClipper();
    clipper.PreserveCollinear(preserveCollinear);
    clipper.AddPaths(subject, ClipperLib::ptSubject, true);
    clipper.AddPath(r.path(), ClipperLib::ptClip, true);
    Paths out;
    clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    return out;
}

// A region of one ring that visits no point twice: the clipper's union makes its rings simple
// but may let one touch itself at a point, which clipSimpleRing is not for.
bool isOneRingWithoutTouch(const Paths& region) {
    if (region.size() != 1) return false;
    Path sorted = region[0];
    std::sort(sorted.begin(), sorted.end(), [](const IntPoint& a, const IntPoint& b) {
        return a.X < b.X || (a.X == b.X && a.Y < b.Y);
    });
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// The region covers the rectangle grown by one step: no boundary point can lie on the cell.
bool coversWithMargin(const Paths& region, const Rect& r) {
    const Rect grown{r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1};
    const Paths inside = clip(region, grown, false, false);
    if (inside.size() != 1 || inside[0].size() != 4) return false;
    for (const IntPoint& p : inside[0])
        if ((p.X != grown.x0 && p.X != grown.x1) || (p.Y != grown.y0 && p.Y != grown.y1))
            return false;
    return true;
}

// The region's piece of a cell is the whole cell: one path through its four corners with every
// point on its sides (the boundary runs along them, or beyond them by up to the margin).
bool isWholeCell(const Paths& piece, const Rect& r, bool oneSimpleRing) {
    const Paths inside = clip(piece, r, true, oneSimpleRing);
    if (inside.size() != 1) return false;
    int corners = 0;
    for (const IntPoint& p : inside[0]) {
        const bool onX = p.X == r.x0 || p.X == r.x1, onY = p.Y == r.y0 || p.Y == r.y1;
        if (!onX && !onY) return false;
        corners += onX && onY;
    }
    return corners == 4;
}

// How far the corners of cell r's polygon (the region's piece of it: one ring, no hole) lie
// from the cell's border, for CellErrorBound::nearSides: the largest distance that a corner moves
// along u onto the border, as a fraction of the cell's width, and along v, of its height. Each
// segment of the ring goes with the side that its two ends are nearest together (the larger of
// their distances the least), and each corner moves onto its segments' sides: onto the one
// side, or into the corner of two. None where a segment keeps more than a quarter of the cell
// from every side, two segments of a corner go with opposite sides, the moved corners do not
// keep the ring's order around the border (one turn, never back), or the ring holds no more
// than the bands along the sides that those distances make (it then holds the cell but for
// them). A point that the second pass adds on a segment (a cut of another face's cell side)
// moves onto the line between its ends' moved points, on their side, no farther than they do;
// two units are added for the rounding of such points to the frame's integers.
std::optional<std::array<double, 2>> nearSideOffsets(const Paths& piece, const Rect& r,
                                                     bool oneSimpleRing) {
    Paths inside = clip(piece, r, true, oneSimpleRing);
    if (inside.size() != 1 || inside[0].size() < 3) return std::nullopt;
    Path& ring = inside[0];
    const double area = ClipperLib::Area(ring);
    if (area < 0) std::reverse(ring.begin(), ring.end());
    const std::size_t count = ring.size();
    const cInt width = r.x1 - r.x0, height = r.y1 - r.y0;
    // sides counterclockwise from the bottom: 0 bottom, 1 right, 2 top, 3 left
    auto fromSide = [&](const IntPoint& p, int side) {
        switch (side) {
            case 0:
                return double(p.Y - r.y0) / double(height);
            case 1:
                return double(r.x1 - p.X) / double(width);
            case 2:
                return double(r.y1 - p.Y) / double(height);
            default:
                return double(p.X - r.x0) / double(width);
        }
    };
    std::vector<int> segmentSide(count);
    for (std::size_t i = 0; i < count; ++i) {
        const IntPoint &a = ring[i], &b = ring[(i + 1) % count];
        double nearest = std::numeric_limits<double>::infinity();
        for (int side = 0; side < 4; ++side) {
            const double far = std::max(fromSide(a, side), fromSide(b, side));
            if (far < nearest) nearest = far, segmentSide[i] = side;
        }
        if (nearest > 0.25) return std::nullopt;
    }
    std::array<double, 2> largest{0, 0};
    const cInt perimeter = 2 * (width + height);
    cInt turn = 0, first = 0, previous = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const int before = segmentSide[(i + count - 1) % count], after = segmentSide[i];
        if ((before - after + 4) % 4 == 2) return std::nullopt;  // opposite sides
        IntPoint q = ring[i];
        for (const int side : {before, after}) {
            if (side % 2 == 0) {
                q.Y = side == 0 ? r.y0 : r.y1;
                largest[1] =
                    std::max(largest[1], double(std::abs(q.Y - ring[i].Y) + 2) / double(height));
            } else {
                q.X = side == 1 ? r.x1 : r.x0;
                largest[0] =
                    std::max(largest[0], double(std::abs(q.X - ring[i].X) + 2) / double(width));
            }
        }
        // the moved point's place along the border, counterclockwise from (x0, y0)
        cInt along;
        if (q.Y == r.y0 && q.X < r.x1)
            along = q.X - r.x0;
        else if (q.X == r.x1 && q.Y < r.y1)
            along = width + (q.Y - r.y0);
        else if (q.Y == r.y1 && q.X > r.x0)
            along = width + height + (r.x1 - q.X);
        else
            along = 2 * width + height + (r.y1 - q.Y);
        if (i == 0)
            first = along;
        else
            turn += ((along - previous) % perimeter + perimeter) % perimeter;
        previous = along;
    }
    turn += ((first - previous) % perimeter + perimeter) % perimeter;
    if (turn != perimeter) return std::nullopt;
    const double bands = 2 * largest[0] + 2 * largest[1];
    if (!(std::abs(area) > bands * double(width) * double(height))) return std::nullopt;
    return largest;
}

// The smallest rectangle holding every point of `paths` (an empty one, x0 > x1, if none).
Rect boundsOf(const Paths& paths) {
    constexpr cInt kLow = std::numeric_limits<cInt>::lowest(),
                   kHigh = std::numeric_limits<cInt>::max();
    Rect box{kHigh, kHigh, kLow, kLow};
    for (const Path& path : paths)
        for (const IntPoint& p : path) {
            box.x0 = std::min(box.x0, p.X), box.y0 = std::min(box.y0, p.Y);
            box.x1 = std::max(box.x1, p.X), box.y1 = std::max(box.y1, p.Y);
        }
    return box;
}

// The part of `cell` that `box` (a region's piece) covers, as width fraction times height
// fraction (CellErrorBound::pieceFraction). The box is grown by two steps: the crossings added
// before triangulate() move the boundary by the rounding to the integer grid.
double fractionOfCell(const Rect& box, const Rect& cell) {
    auto extent = [](cInt lo, cInt hi, cInt cellLo, cInt cellHi) {
        lo = std::max(lo - 2, cellLo);
        hi = std::min(hi + 2, cellHi);
        return std::clamp(double(hi - lo) / double(cellHi - cellLo), 0.0, 1.0);
    };
    return extent(box.x0, box.x1, cell.x0, cell.x1) * extent(box.y0, box.y1, cell.y0, cell.y1);
}

// The rectangle the region is, where it is one (a cylinder, cone or torus between circles: one
// counter-clockwise path, each side along its bounding box's sides, the box's sides holding
// the edges' points); none otherwise.
std::optional<Rect> regionRectangle(const Paths& region) {
    if (region.size() != 1 || region[0].size() < 4 || !ClipperLib::Orientation(region[0]))
        return std::nullopt;
    const Path& path = region[0];
    const Rect box = boundsOf(region);
    if (!(box.x0 < box.x1 && box.y0 < box.y1)) return std::nullopt;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const IntPoint &a = path[i], &b = path[(i + 1) % path.size()];
        const bool alongX = a.Y == b.Y && (a.Y == box.y0 || a.Y == box.y1);
        const bool alongY = a.X == b.X && (a.X == box.x0 || a.X == box.x1);
        if (!alongX && !alongY) return std::nullopt;
    }
    return box;
}

bool contains(const Rect& outer, const Rect& inner) {
    return outer.x0 <= inner.x0 && inner.x1 <= outer.x1 && outer.y0 <= inner.y0 &&
           inner.y1 <= outer.y1;
}

// The error a full cell (inside the trimmed region with a margin) may spend on its surface.
// In guaranteed mode the verifier measures both ways: from each mesh point to the face, and
// from each face point to the mesh. A full cell's triangles have every corner on the surface at
// a parameter on the cell's sides (its corners and its neighbours', none on a trimming curve
// nor shared with another face), so each triangle point is within untrimmed() of a surface
// point S(x) of the cell and each S(x) within it of a triangle point (CellErrorBound: x is the
// triangle point's own (u, v), or where the cell's corners are a flat quadrilateral, the
// parameter of the same point of it), and S(x) is a point of the face, as the whole cell lies
// inside the trimmed region: both ways the distance is at most the cell bound. None of the trimming
// share (chords and their simplification) nor of the shared-edge gap is spent there: those errors
// are measured on triangles that touch the boundary, which are in trimmed cells. So a full cell
// may take the surface share plus both trimming shares plus the half gap (0.95 of the
// tolerance with ErrorBudget::of) and keep the same slack; a trimmed cell keeps the surface
// share. The approximate mode promises nothing and keeps its surface share everywhere.
double wholeCellTarget(const ErrorBudget& budget, ErrorMode mode) {
    if (mode != ErrorMode::Guaranteed) return budget.surface;
    return budget.surface + budget.lineApproximation + budget.lineSimplification +
           0.5 * budget.shareGap + budget.openChords;
}

// Where a cell the boundary crosses is split along `direction`: through the boundary point
// nearest `at` within a quarter of the cell, if there is one. A split line elsewhere cuts the
// boundary's segments at new points, which both faces of the edge then get: on a cylinder the
// kd-tree's columns would cut its circles between the edge's own points, and the circles would
// carry both sets. Through a boundary point the line adds none there. A point on the cell's side
// counts only where both ends of the line are on the boundary (the cylinder's two circles):
// with one end inside the face, the neighbour across that side would split at its own boundary
// point, and the two lines would end a hair apart on the side they share. The children's bounds
// are checked like any others, so the guarantee does not depend on where the line goes.
cInt throughBoundaryPoint(const Paths& region, const Rect& r, int direction, cInt at) {
    const cInt lo = direction == 0 ? r.x0 : r.y0, hi = direction == 0 ? r.x1 : r.y1;
    const cInt otherLo = direction == 0 ? r.y0 : r.x0, otherHi = direction == 0 ? r.y1 : r.x1;
    const cInt window = splitThroughPointWindow(lo, hi);
    cInt inside = at, insideDistance = window, onSide = at, onSideDistance = window;
    bool onLowSide = false, onHighSide = false;
    for (const Path& path : region)
        for (const IntPoint& p : path) {
            const cInt along = direction == 0 ? p.X : p.Y, across = direction == 0 ? p.Y : p.X;
            // points on the grown margin are where the clip cut the boundary, not its own
            if (along <= lo || along >= hi || across < otherLo || across > otherHi) continue;
            const cInt distance = std::abs(along - at);
            if (across == otherLo || across == otherHi) {
                onLowSide |= across == otherLo;
                onHighSide |= across == otherHi;
                if (distance < onSideDistance) onSide = along, onSideDistance = distance;
            } else if (distance < insideDistance) {
                inside = along, insideDistance = distance;
            }
        }
    return onLowSide && onHighSide && onSideDistance <= insideDistance ? onSide : inside;
}

// A split that cuts the part of a cell the boundary runs through off the rest, where that part
// is a band along one side (at most kWidestBand of the cell): the rest then holds the boundary
// along its own sides only, so the region fills it or misses it. A boundary that follows a
// cell's side but for a wiggle (a sloppy edge's shared points projected onto the surface, a hair
// off its iso-line) otherwise makes every cell along it a trimmed one, bound by the twist of the
// whole cell (CellErrorBound::trimmed) and halved, band and all, until that twist is small. Cut
// off, the band is a thin trimmed cell whose twist is as thin, and the rest a cell that the
// bound for corners on its sides covers (hammer.iges at relative 1e-4: 16,097 -> 11,841
// triangles). The line goes through the band's farthest point: it adds no point to the boundary
// there. None where the boundary reaches farther into the cell, or does not enter it.
// The band may be up to three quarters of the cell (kWidestBand): the boundary-free rest is a
// filled cell whatever the band's width, which is then split on its own bound instead of the
// whole cell being halved across the edge along its free side (bug33398.step's half cones under
// a wavy curve, whose columns cut their circles: 37,340 -> 36,936 triangles at relative 1e-4;
// a half gave 36,984).
constexpr double kWidestBand = 0.75;
// A trimmed cell's bound for corners on its sides is the sum interior + boundary of E
// (CellErrorBound: spreadToEdges is measured for cells the region fills only), about twice the
// measured one where E bulges to one side. Where that sum is above the target but within
// kMeasuredSidesWithin of it, the kd-tree measures the bound for corners on the sides before it
// gives up a band split (bandSplit): bottle.brep's thread flanks, whose sloppy sides wander 0.07%
// of a cell off their iso-lines, at relative 1e-4 took 22,096 triangles with the sum and 21,752
// with the measured bound, bug33398.step 31,562 and 31,450. A band split so found is kept to
// bands of at most kThinBand of the cell unless the trimmed cell's own bound is above
// kFarAboveTarget times the target: a cell just above it settles after one halving, while a band
// line cuts each row of a strip at its own place and its neighbours fan to it (trj7_b1-ec-214.stp
// at 1e-4: 29,425 triangles with the sum, 29,433 with the limits, 29,595 without them; its
// strips 398, 399, 412 and 413 take 129, 141 and 193 triangles each).
constexpr double kMeasuredSidesWithin = 3.0;
constexpr double kThinBand = 0.05;
constexpr double kFarAboveTarget = 2.0;
std::optional<std::pair<int, cInt>> bandSplit(const Paths& region, const Rect& r,
                                              double widest = kWidestBand) {
    // the extent of the boundary's segments within the closed cell
    double low[2] = {std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity()};
    double high[2] = {-std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity()};
    const double box[2][2] = {{double(r.x0), double(r.x1)}, {double(r.y0), double(r.y1)}};
    for (const Path& path : region)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const IntPoint& a = path[i];
            const IntPoint& b = path[(i + 1) % path.size()];
            // along a side the boundary is where the cell's own sides are (CellChoices::
            // filledCellsBySides)
            if ((a.X == b.X && (a.X == r.x0 || a.X == r.x1)) ||
                (a.Y == b.Y && (a.Y == r.y0 || a.Y == r.y1)))
                continue;
            // Liang-Barsky: the segment's parameters within the cell
            const double from[2] = {double(a.X), double(a.Y)};
            const double step[2] = {double(b.X - a.X), double(b.Y - a.Y)};
            double t0 = 0, t1 = 1;
            for (int axis = 0; axis < 2 && t0 <= t1; ++axis) {
                if (step[axis] == 0) {
                    if (from[axis] < box[axis][0] || from[axis] > box[axis][1]) t0 = 2;
                    continue;
                }
                double enter = (box[axis][0] - from[axis]) / step[axis];
                double leave = (box[axis][1] - from[axis]) / step[axis];
                if (enter > leave) std::swap(enter, leave);
                t0 = std::max(t0, enter);
                t1 = std::min(t1, leave);
            }
            if (t0 > t1) continue;
            for (int axis = 0; axis < 2; ++axis)
                for (const double t : {t0, t1}) {
                    const double x =
                        std::clamp(from[axis] + t * step[axis], box[axis][0], box[axis][1]);
                    low[axis] = std::min(low[axis], x);
                    high[axis] = std::max(high[axis], x);
                }
        }
    std::optional<std::pair<int, cInt>> best;
    double thinnest = widest;
    for (int axis = 0; axis < 2; ++axis) {
        if (!(low[axis] <= high[axis])) return std::nullopt;  // no boundary in the cell
        const cInt lo = axis == 0 ? r.x0 : r.y0, hi = axis == 0 ? r.x1 : r.y1;
        const double width = double(hi - lo);
        // a band along the low side: the line through its farthest point, the rest beyond
        const auto nearLow = static_cast<cInt>(std::ceil(high[axis]));
        if (nearLow > lo && nearLow < hi - 1 && double(nearLow - lo) / width <= thinnest) {
            thinnest = double(nearLow - lo) / width;
            best = {axis, nearLow};
        }
        const auto nearHigh = static_cast<cInt>(std::floor(low[axis]));
        if (nearHigh < hi && nearHigh > lo + 1 && double(hi - nearHigh) / width <= thinnest) {
            thinnest = double(hi - nearHigh) / width;
            best = {axis, nearHigh};
        }
    }
    return best;
}

// Squared distance from p to segment ab, and the parameter of the nearest point.
std::pair<double, double> segmentDistance(const IntPoint& p, const IntPoint& a, const IntPoint& b) {
    const double ax = double(a.X), ay = double(a.Y);
    const double dx = double(b.X) - ax, dy = double(b.Y) - ay;
    const double length2 = dx * dx + dy * dy;
    double t = length2 > 0 ? ((double(p.X) - ax) * dx + (double(p.Y) - ay) * dy) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = ax + t * dx - double(p.X), ey = ay + t * dy - double(p.Y);
    return {ex * ex + ey * ey, t};
}

}  // namespace

// The face's integer frame and the loop data the cutting looks up.
struct FaceTessellator::Frame {
    double u0 = 0, v0 = 0, scaleU = 1, scaleV = 1;
    std::vector<cInt> breaksX, breaksY;  // Bezier span borders strictly inside the frame
    // whether the even columns along u and v (CellChoices::evenColumns) are on this frame
    std::array<bool, 2> even{false, false};

    IntPoint toInteger(const Point2& uv) const {
        return {static_cast<cInt>(std::llround((uv.x() - u0) * scaleU)),
                static_cast<cInt>(std::llround((uv.y() - v0) * scaleV))};
    }
    Point2 toParameter(cInt x, cInt y) const {
        return {u0 + static_cast<double>(x) / scaleU, v0 + static_cast<double>(y) / scaleV};
    }
};

// A kd-tree node: a leaf (a cell to triangulate) or a split into two children. The tree is kept
// so that the second pass can cut the completed boundary down it again, node by node.
struct FaceTessellator::Leaf {
    Rect rect;
    bool full = false;  // inside the region with a margin: no boundary point touches it
    int children[2] = {-1, -1};
    bool leaf = false;
    // How far the leaf's bound is below the surface share, which its triangles then leave
    // unspent (guaranteed mode, a cell the boundary crosses; 0 where not measured): the
    // removal of open boundary points may spend it (removeOpenBoundaryPoints).
    double slack = 0;
};

namespace {

// Boundary polygons and a coarse grid over their segments, to find which segment a point that
// the clipper made lies on.
struct BoundaryIndex {
    struct Segment {
        IntPoint a, b;
        int loop, index;
    };
    std::vector<Segment> segments;
    std::unordered_map<std::int64_t, std::pair<int, int>> corners;  // integer point -> loop, index
    int cellsPerSide = 1;
    std::vector<std::vector<int>> buckets;

    int bucketOf(cInt c) const {
        return static_cast<int>(
            std::clamp<cInt>(c * cellsPerSide / (kScale + 1), 0, cellsPerSide - 1));
    }

    void build(const std::vector<std::vector<IntPoint>>& loops) {
        for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
            const auto& loop = loops[l];
            for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
                corners.emplace(keyOf(loop[i].X, loop[i].Y), std::make_pair(l, i));
                segments.push_back({loop[i], loop[(i + 1) % loop.size()], l, i});
            }
        }
        cellsPerSide = std::clamp(static_cast<int>(std::sqrt(double(segments.size()))), 1, 512);
        buckets.assign(static_cast<size_t>(cellsPerSide * cellsPerSide), {});
        for (int s = 0; s < static_cast<int>(segments.size()); ++s) {
            const auto& seg = segments[s];
            const int bx0 = bucketOf(std::min(seg.a.X, seg.b.X) - 2);
            const int bx1 = bucketOf(std::max(seg.a.X, seg.b.X) + 2);
            const int by0 = bucketOf(std::min(seg.a.Y, seg.b.Y) - 2);
            const int by1 = bucketOf(std::max(seg.a.Y, seg.b.Y) + 2);
            for (int bx = bx0; bx <= bx1; ++bx)
                for (int by = by0; by <= by1; ++by) buckets[bx * cellsPerSide + by].push_back(s);
        }
    }

    // The segment p lies on (within `reach` steps), with the parameter along it, or -1.
    std::pair<int, double> segmentAt(const IntPoint& p, double reach) const {
        int best = -1;
        double bestDistance = reach * reach, bestT = 0;
        for (int s : buckets[bucketOf(p.X) * cellsPerSide + bucketOf(p.Y)]) {
            auto [d, t] = segmentDistance(p, segments[s].a, segments[s].b);
            if (d <= bestDistance) best = s, bestDistance = d, bestT = t;
        }
        return {best, bestT};
    }

    // Whether ring[i] is a point the clipper made on a boundary chord between two other points
    // of that chord, turning nothing: where a chord runs within a step of a cell side, rounding
    // can give it a vertex that no cut of a cell side made. The first pass may not see such a
    // point (its rounding depends on the rest of the region), so the other face of the edge
    // does not know it, and kept it would open the edge.
    bool isCollinearOnChord(const Path& ring, std::size_t i) const {
        const IntPoint& p = ring[i];
        if (corners.count(keyOf(p.X, p.Y))) return false;
        const int s = segmentAt(p, 1.5).first;
        if (s < 0) return false;
        const IntPoint& before = ring[(i + ring.size() - 1) % ring.size()];
        const IntPoint& after = ring[(i + 1) % ring.size()];
        const auto& chord = segments[s];
        return segmentDistance(before, chord.a, chord.b).first <= 2.25 &&
               segmentDistance(after, chord.a, chord.b).first <= 2.25;
    }

    // The nearest polygon corner within `reach` steps, or (-1, -1).
    std::pair<int, int> cornerNear(const IntPoint& p, cInt reach) const {
        std::pair<int, int> best{-1, -1};
        double bestDistance = std::numeric_limits<double>::max();
        for (int s : buckets[bucketOf(p.X) * cellsPerSide + bucketOf(p.Y)]) {
            for (const IntPoint* q : {&segments[s].a, &segments[s].b}) {
                const cInt dx = q->X - p.X, dy = q->Y - p.Y;
                if (std::abs(dx) > reach || std::abs(dy) > reach) continue;
                const double d = double(dx) * double(dx) + double(dy) * double(dy);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = corners.at(keyOf(q->X, q->Y));
                }
            }
        }
        return best;
    }
};

}  // namespace

FaceTessellator::FaceTessellator(const TrimmedSurface& face, const ErrorBudget& budget,
                                 ErrorMode mode, const CellChoices& choices,
                                 std::shared_ptr<const BezierPatchGrid> patches)
    : face_(face),
      budget_(budget),
      mode_(mode),
      choices_(choices),
      patches_(patches ? std::move(patches)
                       : std::make_shared<const BezierPatchGrid>(face.surface)),
      // flat to a twentieth of the surface share: the triangles in its plane spend at most twice
      // that of the share, which the kd-tree's cells would have spent in full
      plane_(facePlane(face.surface, 0.05 * budget.surface)) {
    // on the cylinder to the same twentieth: its points' offsets stay within the share
    if (!plane_ && face.cylinder)
        cylinder_ = faceCylinderFrame(face.surface, *face.cylinder, 0.05 * budget.surface);
}

FaceTessellator::~FaceTessellator() = default;

double FaceTessellator::unrolledShare() const {
    // A trimmed cell's share for every triangle (each may have a chord for a side), less twice
    // the flatness that faceCylinderFrame allowed: the corners lie on the NURBS form, which may
    // be that far from the cylinder that the bound is for, and so may the surface under them.
    return 0.9 * budget_.surface;
}

std::optional<std::vector<std::array<std::uint32_t, 3>>> FaceTessellator::developedTriangles(
    const std::vector<std::vector<Point3>>& positions) const {
    if (plane_) return triangulateInPlane(*plane_, positions);
    if (cylinder_) return triangulateOnCylinder(*cylinder_, positions, unrolledShare());
    return std::nullopt;
}

std::optional<std::vector<BoundaryCrossing>> FaceTessellator::unrolledCrossings(
    const std::vector<BoundaryLoop>& loops, const std::vector<std::vector<Point3>>& rings,
    const UnrolledTriangles& first, std::size_t fewerThan) const {
    if (!cylinder_) return std::nullopt;
    const auto added =
        chordPointsForUnrolledBound(*cylinder_, rings, unrolledShare(), fewerThan, &first);
    if (!added) return std::nullopt;
    // each point a cut of its edge's chord, as a kd-tree cell's side makes one (ModelTessellator
    // puts it on the 3D chord, where the fraction put it)
    std::vector<BoundaryCrossing> crossings;
    for (std::size_t l = 0; l < loops.size(); ++l)
        for (std::size_t i = 0; i < (*added)[l].size(); ++i) {
            if ((*added)[l][i].empty()) continue;
            const BoundarySegmentOrigin& origin = loops[l].origins[i];
            if (origin.edge < 0) return std::nullopt;
            const Point2& a = loops[l].points[i].uv;
            const Point2& b = loops[l].points[(i + 1) % loops[l].points.size()].uv;
            for (const double t : (*added)[l][i]) {
                const IntPoint q = frame_->toInteger((1 - t) * a + t * b);
                crossings.push_back({origin.edge, origin.segment, origin.use,
                                     origin.forward ? t : 1 - t, std::clamp<cInt>(q.X, 0, kScale),
                                     std::clamp<cInt>(q.Y, 0, kScale)});
            }
        }
    return crossings;
}

void FaceTessellator::setFrame(const std::vector<BoundaryLoop>& loops) {
    double u0 = std::numeric_limits<double>::max(), v0 = u0;
    double u1 = -u0, v1 = -u0;
    for (const auto& loop : loops)
        for (const auto& p : loop.points) {
            if (!p.uv.allFinite())
                throw std::runtime_error("a trimming curve evaluates to a non-finite point");
            u0 = std::min(u0, p.uv.x()), u1 = std::max(u1, p.uv.x());
            v0 = std::min(v0, p.uv.y()), v1 = std::max(v1, p.uv.y());
        }
    const double scaleOfDomain =
        std::max({std::abs(u0), std::abs(u1), std::abs(v0), std::abs(v1), 1e-300});
    if (!(u1 - u0 > 1e-12 * scaleOfDomain) || !(v1 - v0 > 1e-12 * scaleOfDomain))
        throw FaceWithoutArea("the trimming loops enclose no area (degenerate face)");
    frame_ = std::make_unique<Frame>();
    frame_->u0 = u0;
    frame_->v0 = v0;
    frame_->scaleU = static_cast<double>(kScale) / (u1 - u0);
    frame_->scaleV = static_cast<double>(kScale) / (v1 - v0);
    // The even columns were chosen on the frame of the pcurves' ends (ModelTessellator,
    // kdTreeLinesBeforeDiscretisation); the boundary's points may span a box that differs from
    // it in the last bits, and the columns were dropped for that on a face in 19 of the
    // benchmark's 64 runs (the tori of the generated shapes, bottle.brep's, trj7's): an axis
    // whose ends are within a frame step of the columns' frame takes that frame. A point outside
    // it by less than a step is held inside, as a chord's point is (integerBoundary). A torus
    // fillet of filleted_cylinder.brep took 9,018 or 11,990 triangles at relative 1e-4 as the
    // last bit of one pcurve's end fell.
    if (choices_.evenColumns) {
        const KdTreeGrid* grid = choices_.evenColumns->data();
        if (grid[0].hasEvenColumns() && grid[0].framesWithinAStep(u0, u1))
            frame_->u0 = grid[0].low(), frame_->scaleU = grid[0].scale();
        if (grid[1].hasEvenColumns() && grid[1].framesWithinAStep(v0, v1))
            frame_->v0 = grid[1].low(), frame_->scaleV = grid[1].scale();
    }
    const std::vector<std::int64_t> borders[2] = {
        spanBordersInFrame(frame_->u0, frame_->scaleU, patches_->breakpointsU()),
        spanBordersInFrame(frame_->v0, frame_->scaleV, patches_->breakpointsV())};
    frame_->breaksX.assign(borders[0].begin(), borders[0].end());
    frame_->breaksY.assign(borders[1].begin(), borders[1].end());
    if (choices_.evenColumns) {
        const double low[2] = {frame_->u0, frame_->v0}, scale[2] = {frame_->scaleU, frame_->scaleV};
        for (int axis = 0; axis < 2; ++axis) {
            const KdTreeGrid& grid = (*choices_.evenColumns)[axis];
            frame_->even[axis] =
                grid.hasEvenColumns() && grid.hasFrame(low[axis], scale[axis], borders[axis]);
        }
    }
}

std::vector<std::vector<IntPoint>> FaceTessellator::integerBoundary(
    const std::vector<BoundaryLoop>& loops) const {
    std::vector<std::vector<IntPoint>> out;
    for (const auto& loop : loops) {
        std::vector<IntPoint> path;
        // The frame is the first pass's box; a point that the second pass adds on a chord may
        // round a step or two outside it, where every cell would cut it off (the face then
        // skips a point its neighbour has: an open edge). It is held inside instead.
        for (const auto& p : loop.points) {
            const IntPoint q = p.exact ? IntPoint{p.x, p.y} : frame_->toInteger(p.uv);
            path.push_back({std::clamp<cInt>(q.X, 0, kScale), std::clamp<cInt>(q.Y, 0, kScale)});
        }
        out.push_back(std::move(path));
    }
    return out;
}

Paths FaceTessellator::regionOf(const std::vector<BoundaryLoop>& loops) const {
    // The union by the even-odd rule is the repair of section 5.1: loops that cross themselves
    // or each other become simple polygons, outer ones counter-clockwise, holes clockwise.
    ClipperLib::Clipper clipper;
    clipper.PreserveCollinear(true);
    for (const auto& loop : integerBoundary(loops))
        if (loop.size() >= 3) clipper.AddPath(loop, ClipperLib::ptSubject, true);
    Paths region;
    clipper.Execute(ClipperLib::ctUnion, region, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    return region;
}

// What the bounds said of a cell (they depend on the cell alone, up to rounding: its piece of
// the surface, and its piece of the region, which is the region clipped to the cell whatever
// cells it was clipped to before): whether it settles, and where not, in which direction the
// bound would cut it. The kd-tree built twice (findCrossings) bounds most of its cells once:
// the two builds differ in their upper cuts only. Trimmed cells too: with the filled ones
// alone, the second builds took 25 ms of trj7_b1-ec-214.stp's 0.42 s at relative 1e-4 (2,755
// trimmed cells bounded again); with them, 10 ms, and the same meshes.
struct FaceTessellator::CellDecisions {
    struct Decision {
        bool full = false;  // filled, and only taken for the cell filled again
        bool settles = false;
        int preferredDirection = 0;
        double bound = 0;  // the bound a cell settled on (a trimmed cell's slack)
        // a trimmed cell's bound for corners on its sides would do (bandSplit), and the widest
        // band it may cut off
        bool sidesWouldDo = false;
        double widestBand = 0;
    };
    struct RectHash {
        std::size_t operator()(const std::array<cInt, 4>& key) const {
            std::size_t h = 0;
            for (const cInt value : key) h = h * 0x9E3779B97F4A7C15ull + std::hash<cInt>()(value);
            return h;
        }
    };
    bool record = false;
    std::unordered_map<std::array<cInt, 4>, Decision, RectHash> byRect;
};

double FaceTessellator::triangleBound(const std::array<Point2, 3>& uv,
                                      const std::array<Point3, 3>& position, double target,
                                      bool sampleFirst) const {
    constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    // only corners on the surface's domain: beyond it no piece holds the surface (its spans'
    // borders, first to last)
    const auto& domainU = patches_->breakpointsU();
    const auto& domainV = patches_->breakpointsV();
    for (const Point2& q : uv)
        if (!(q.x() >= domainU.front() && q.x() <= domainU.back() && q.y() >= domainV.front() &&
              q.y() <= domainV.back()))
            return kUnbounded;
    // the affine map through the corners: position = X0 + G (q - q0)
    const auto map = TriangleAffineMap::through(uv, position);
    if (!map) return kUnbounded;
    const TriangleAffineMap& affineAt = *map;
    // The surface's distance from the triangle at its centre and at its sides' middles is a
    // lower bound of any bound: where it is over the target already, no piece is bounded (most
    // triangles that removeOpenBoundaryPoints tries on a strip of thin cells are far over it).
    double seen = 0;
    if (sampleFirst)
        for (const auto& [wa, wb, wc] :
             {std::array{1.0 / 3, 1.0 / 3, 1.0 / 3}, std::array{0.5, 0.5, 0.0},
              std::array{0.0, 0.5, 0.5}, std::array{0.5, 0.0, 0.5}}) {
            const Point2 q = wa * uv[0] + wb * uv[1] + wc * uv[2];
            seen = std::max(seen, (patches_->point(q.x(), q.y()) - affineAt(q)).norm());
        }
    if (!(seen <= target)) return seen;
    // over the triangle itself where the surface's degrees allow (far closer than over its box)
    if (const auto deviation = triangleDeviation(*patches_, uv, affineAt, target, kMostSpansInCell))
        return *deviation;
    // the box of the corners, a step beyond each side (the frame's rounding), cut at span borders
    const Point2 low = uv[0].cwiseMin(uv[1]).cwiseMin(uv[2]);
    const Point2 high = uv[0].cwiseMax(uv[1]).cwiseMax(uv[2]);
    const IntPoint a = frame_->toInteger(low), b = frame_->toInteger(high);
    std::vector<cInt> xs{a.X - 1}, ys{a.Y - 1};
    for (cInt x : frame_->breaksX)
        if (x > a.X - 1 && x < b.X + 1) xs.push_back(x);
    for (cInt y : frame_->breaksY)
        if (y > a.Y - 1 && y < b.Y + 1) ys.push_back(y);
    xs.push_back(b.X + 1);
    ys.push_back(b.Y + 1);
    if ((xs.size() - 1) * (ys.size() - 1) > kMostSpansInCell) return kUnbounded;
    double bound = 0;
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
            Point2 from = frame_->toParameter(xs[i], ys[j]);
            Point2 to = frame_->toParameter(xs[i + 1], ys[j + 1]);
            const Point2 middle = 0.5 * (from + to);
            const int su = patches_->spanIndexU(middle.x()), sv = patches_->spanIndexV(middle.y());
            // within the span (the step beyond may pass the surface's domain), so that the
            // piece maps [from, to] linearly and the corners' local parameters hold
            from = from.cwiseMax(Point2(domainU[su], domainV[sv]));
            to = to.cwiseMin(Point2(domainU[su + 1], domainV[sv + 1]));
            if (!(from.x() < to.x() && from.y() < to.y())) continue;
            const BezierPatch piece = patches_->piece(su, sv, from.x(), to.x(), from.y(), to.y());
            std::array<Point2, 3> local;
            for (int k = 0; k < 3; ++k)
                local[k] = Point2((uv[k].x() - from.x()) / (to.x() - from.x()),
                                  (uv[k].y() - from.y()) / (to.y() - from.y()));
            bound =
                std::max(bound, affineDeviation(piece, affineAt(from), affineAt({to.x(), from.y()}),
                                                affineAt({from.x(), to.y()}), target, local));
            if (!(bound <= target)) return bound;
        }
    return bound;
}

double FaceTessellator::boundAcrossSpans(const std::array<cInt, 4>& cell,
                                         const std::vector<cInt>& breaksX,
                                         const std::vector<cInt>& breaksY, double target,
                                         bool trimmedCell, double pieceFraction) const {
    const std::size_t count = (breaksX.size() + 1) * (breaksY.size() + 1);
    constexpr double kUnsettled = std::numeric_limits<double>::infinity();
    if (count > kMostSpansInCell) return kUnsettled;
    const Rect r{cell[0], cell[1], cell[2], cell[3]};
    std::vector<cInt> xs{r.x0}, ys{r.y0};
    xs.insert(xs.end(), breaksX.begin(), breaksX.end());
    ys.insert(ys.end(), breaksY.begin(), breaksY.end());
    xs.push_back(r.x1);
    ys.push_back(r.y1);
    // Most such cells are far from settling (cells smaller than spans at a fine tolerance): a
    // surface point off the bilinear patch of the corners by more than the target less the
    // twist term rules the cell out before any piece is made (twistTerm), here at the centre,
    // at the span corners inside the cell and at the middle of each span's piece.
    auto surfaceAt = [&](cInt x, cInt y) {
        const Point2 uv = frame_->toParameter(x, y);
        return patches_->point(uv.x(), uv.y());
    };
    const Point3 c00 = surfaceAt(r.x0, r.y0), c10 = surfaceAt(r.x1, r.y0);
    const Point3 c01 = surfaceAt(r.x0, r.y1), c11 = surfaceAt(r.x1, r.y1);
    const double beyondAt = target - twistTerm(c00, c10, c01, c11, mode_, trimmedCell,
                                               choices_.flatCellsByDistance, pieceFraction);
    auto beyond = [&](cInt x, cInt y) {
        const double s = double(x - r.x0) / double(r.x1 - r.x0);
        const double t = double(y - r.y0) / double(r.y1 - r.y0);
        return (surfaceAt(x, y) - bilinearAt(c00, c10, c01, c11, s, t)).norm() > beyondAt;
    };
    if (beyond(r.x0 + (r.x1 - r.x0) / 2, r.y0 + (r.y1 - r.y0) / 2)) return kUnsettled;
    for (std::size_t a = 0; a + 1 < xs.size(); ++a)
        for (std::size_t b = 0; b + 1 < ys.size(); ++b)
            if ((a > 0 && b > 0 && beyond(xs[a], ys[b])) ||
                beyond(xs[a] + (xs[a + 1] - xs[a]) / 2, ys[b] + (ys[b + 1] - ys[b]) / 2))
                return kUnsettled;
    std::vector<SpanPiece> pieces;
    pieces.reserve(count);
    for (std::size_t a = 0; a + 1 < xs.size(); ++a)
        for (std::size_t b = 0; b + 1 < ys.size(); ++b) {
            const Point2 low = frame_->toParameter(xs[a], ys[b]);
            const Point2 high = frame_->toParameter(xs[a + 1], ys[b + 1]);
            const Point2 middle = 0.5 * (low + high);
            const int su = patches_->spanIndexU(middle.x()), sv = patches_->spanIndexV(middle.y());
            SpanPiece piece{patches_->piece(su, sv, low.x(), high.x(), low.y(), high.y())};
            // exactly 0 and 1 at the cell's sides, which the bound takes for its border
            piece.s0 = double(xs[a] - r.x0) / double(r.x1 - r.x0);
            piece.s1 = double(xs[a + 1] - r.x0) / double(r.x1 - r.x0);
            piece.t0 = double(ys[b] - r.y0) / double(r.y1 - r.y0);
            piece.t1 = double(ys[b + 1] - r.y0) / double(r.y1 - r.y0);
            pieces.push_back(std::move(piece));
        }
    return cellErrorBoundAcrossSpans(pieces, mode_, target, trimmedCell,
                                     choices_.flatCellsByDistance, pieceFraction)
        .measure(mode_, trimmedCell);
}

void FaceTessellator::setFreeChords(const std::vector<BoundaryLoop>& loops) {
    freeChords_.clear();
    if (choices_.freeEdges.empty() || mode_ != ErrorMode::Guaranteed) return;
    const auto integer = integerBoundary(loops);
    for (std::size_t l = 0; l < loops.size(); ++l)
        for (std::size_t i = 0; i < loops[l].points.size(); ++i) {
            const int edge = loops[l].origins[i].edge;
            if (std::binary_search(choices_.freeEdges.begin(), choices_.freeEdges.end(), edge))
                freeChords_.push_back({integer[l][i], integer[l][(i + 1) % integer[l].size()]});
        }
}

bool FaceTessellator::touchesFreeChord(const std::array<cInt, 4>& cell) const {
    for (const auto& [a, b] : freeChords_) {
        if (std::max(a.X, b.X) < cell[0] || std::min(a.X, b.X) > cell[2] ||
            std::max(a.Y, b.Y) < cell[1] || std::min(a.Y, b.Y) > cell[3])
            continue;
        // the boxes meet: the segment meets the cell unless all four corners lie strictly on
        // one side of its line
        const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
        int above = 0, below = 0;
        for (const cInt x : {cell[0], cell[2]})
            for (const cInt y : {cell[1], cell[3]}) {
                const double side = dx * double(y - a.Y) - dy * double(x - a.X);
                above += side > 0;
                below += side < 0;
            }
        if (above < 4 && below < 4) return true;
    }
    return false;
}

void FaceTessellator::buildKdTree(const Paths& region, bool oneSimpleRing,
                                  CellDecisions& decisions) {
    leaves_.clear();
    struct Node {
        Rect rect;
        bool full;
        // the parent's piece of the region, shared by both children (each reads it only)
        std::shared_ptr<const Paths> region;
        int depth;
        int index;  // in leaves_
        // The parent's Bezier piece over its cell (none across span borders): a child's piece
        // is one de Casteljau pass of it along the split, where restricting the span's patch
        // to the cell took four (BezierPatchGrid::piece, 9% of trj7_b1-ec-214.stp's time).
        std::shared_ptr<const BezierPatch> parentPiece = nullptr;
        Rect parentRect{};
        bool simpleRing = false;  // the region's piece is known to be one simple ring
        // The bound of this cell as a half of its parent (settlingSplitDirection measured it),
        // with the target, trimmed-ness and piece fraction it was measured for: taken where the
        // cell has the same, the piece being the same de Casteljau pass of the same parent.
        std::optional<CellErrorBound> halfBound = std::nullopt;
        double halfTarget = 0;
        bool halfTrimmed = false;
        double halfFraction = 0;
    };
    std::vector<Node> stack;
    // the split through iso-run points below, for the faces that take it
    const bool throughIsoRuns = choices_.splitThroughBoundaryPoints && choices_.filledCellsBySides;
    const IsoRunLines isoRuns(throughIsoRuns ? region : Paths{});
    leaves_.push_back({{0, 0, kScale, kScale}});
    stack.push_back({{0, 0, kScale, kScale},
                     false,
                     std::make_shared<const Paths>(region),
                     0,
                     0,
                     nullptr,
                     Rect{},
                     oneSimpleRing});
    // A region that is a rectangle answers every cell's questions without clipping: the cells
    // along its sides were clipped twice at every depth, a seventh of bottle.brep's time. The
    // answers are those of the clips; a cell's piece is not needed either, as the boundary
    // points a split goes through are looked up inside the cell only (throughBoundaryPoint).
    const std::optional<Rect> rectangle = regionRectangle(region);
    while (!stack.empty()) {
        Node node = std::move(stack.back());
        stack.pop_back();
        const Rect& r = node.rect;
        // A cell the region fills exactly, its boundary running along the cell's sides (a
        // cylinder's circles on its columns): every triangle corner is on a side, as in a full
        // cell, so the bound for corners on the sides holds (CellErrorBound::untrimmed), with
        // the surface share as the target: its boundary triangles spend the other shares.
        bool sidesOnly = false;
        // how much of the cell the box around the region's piece covers (fractionOfCell)
        double pieceFraction = 1;
        if (!node.full) {
            // Most cells are wholly inside or outside: told apart without clipping. The others
            // are clipped to the cell grown by the margin, not to the cell: a child shares sides
            // with its parent, and its margin beyond them must still be there to be covered.
            const Rect grown{r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1};
            bool covered = false;
            if (rectangle) {
                // covered with the margin, else a piece with area, the whole cell where the cell
                // lies in the rectangle
                covered = contains(*rectangle, grown);
                if (!covered) {
                    if (!(grown.x0 < rectangle->x1 && rectangle->x0 < grown.x1 &&
                          grown.y0 < rectangle->y1 && rectangle->y0 < grown.y1))
                        continue;
                    sidesOnly = choices_.filledCellsBySides && contains(*rectangle, r);
                    pieceFraction = fractionOfCell(*rectangle, r);
                }
            } else {
                const RectangleInRegion where =
                    rectangleInRegion(*node.region, grown.x0, grown.y0, grown.x1, grown.y1);
                if (where == RectangleInRegion::Outside) continue;  // as the clip would find
                covered = where == RectangleInRegion::Inside;
            }
            if (!covered && !rectangle) {
                bool simplePiece = false;
                Paths piece = clip(*node.region, grown, true, node.simpleRing, &simplePiece);
                // A piece with less area than the grown cell does not cover it; only one with
                // (about) all of it needs the exact test (the rounding of doubles at 2^60).
                double area = 0;
                bool any = false;
                for (const auto& p : piece) {
                    const double pathArea = ClipperLib::Area(p);
                    area += pathArea;
                    any |= pathArea != 0;
                }
                const double grownArea = double(grown.x1 - grown.x0) * double(grown.y1 - grown.y0);
                covered =
                    std::abs(area) >= (1 - 1e-9) * grownArea && coversWithMargin(*node.region, r);
                if (!covered) {
                    if (!any) continue;  // outside the trimmed region: neither leaf nor parent
                    const double cellArea = double(r.x1 - r.x0) * double(r.y1 - r.y0);
                    sidesOnly = choices_.filledCellsBySides &&
                                std::abs(area) >= (1 - 1e-9) * cellArea &&
                                isWholeCell(piece, r, simplePiece);
                    pieceFraction = fractionOfCell(boundsOf(piece), r);
                    // The clipper's piece of a region of several rings (a face with holes)
                    // is one simple ring in most cells, away from the holes: the cells below
                    // then take the one-pass clip too (trj7_b1-ec-214.stp at relative 1e-4:
                    // 2,733 M -> 2,579 M instructions).
                    if (!simplePiece) simplePiece = isOneRingWithoutTouch(piece);
                    node.region = std::make_shared<const Paths>(std::move(piece));
                    node.simpleRing = simplePiece;
                }
            }
            if (covered) {
                node.full = true;
                node.region.reset();
            }
        }
        leaves_[node.index].full = node.full;
        // this cell's piece once bounded, handed to its children where it is the surface over
        // the whole cell
        std::shared_ptr<const BezierPatch> ownPiece, childrenPiece;
        // the halves' bounds that settlingSplitDirection measured, for its direction
        HalfBounds halves;
        int halvesDirection = -1;
        auto split = [&](int direction, cInt at) {
            Rect a = r, b = r;
            if (direction == 0)
                a.x1 = b.x0 = at;
            else
                a.y1 = b.y0 = at;
            const int ia = static_cast<int>(leaves_.size());
            leaves_.push_back({a});
            leaves_.push_back({b});
            leaves_[node.index].children[0] = ia;
            leaves_[node.index].children[1] = ia + 1;
            stack.push_back({b, node.full, node.region, node.depth + 1, ia + 1, childrenPiece, r,
                             node.simpleRing});
            stack.push_back(
                {a, node.full, node.region, node.depth + 1, ia, childrenPiece, r, node.simpleRing});
        };
        // first cut at Bezier span borders, nearest the middle, in the direction with more
        auto inside = [](const std::vector<cInt>& breaks, cInt lo, cInt hi) {
            std::vector<cInt> out;
            for (cInt b : breaks)
                if (b > lo && b < hi) out.push_back(b);
            return out;
        };
        const auto spanBreaksX = inside(frame_->breaksX, r.x0, r.x1);
        const auto spanBreaksY = inside(frame_->breaksY, r.y0, r.y1);
        // a cell at a free chord, on a face asked to refine there, takes a smaller target
        // (kFreeChordTarget)
        const double target = node.full ? wholeCellTarget(budget_, mode_)
                              : choices_.finerCellsAtFreeChords &&
                                      touchesFreeChord({r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1})
                                  ? kFreeChordTarget * budget_.surface
                                  : budget_.surface;
        const bool trimmedCell = !node.full && !sidesOnly;
        // what the bounds said of this cell in the first build, if it had it, as filled or as
        // trimmed as now
        const std::array<cInt, 4> key{r.x0, r.y0, r.x1, r.y1};
        auto known = decisions.byRect.find(key);
        if (known != decisions.byRect.end() && known->second.full != node.full)
            known = decisions.byRect.end();
        // kept as a flag: the decisions recorded below may rehash the map, and `known` with it
        const bool decided = known != decisions.byRect.end();
        // this cell's decision, recorded in the first build, and kept at hand for what the
        // checks below add to it (a rehash moves no element of the map)
        CellDecisions::Decision* recorded = nullptr;
        auto record = [&](bool settles, int direction, double bound = 0) {
            if (decisions.record)
                recorded = &(decisions.byRect[key] = {node.full, settles, direction, bound});
        };
        // a leaf, within `bound` of the surface where its bound was measured
        auto settle = [&](double bound) {
            Leaf& leaf = leaves_[node.index];
            leaf.leaf = true;
            if (mode_ == ErrorMode::Guaranteed && choices_.openPointsSpendCellSlack && !node.full &&
                bound <= target)
                leaf.slack = budget_.surface - bound;
        };
        constexpr double kUnmeasured = std::numeric_limits<double>::infinity();
        if (!spanBreaksX.empty() || !spanBreaksY.empty()) {
            const double bound = decided ? known->second.bound
                                         : boundAcrossSpans(key, spanBreaksX, spanBreaksY, target,
                                                            trimmedCell, pieceFraction);
            const bool settles = decided ? known->second.settles : bound <= target;
            if (!decided) record(settles, 0, bound);
            if (settles) {
                settle(bound);
                continue;
            }
            const bool alongU = spanBreaksX.size() >= spanBreaksY.size();
            const auto& breaks = alongU ? spanBreaksX : spanBreaksY;
            const cInt middle = alongU ? (r.x0 + r.x1) / 2 : (r.y0 + r.y1) / 2;
            cInt best = breaks.front();
            for (cInt b : breaks)
                if (std::abs(b - middle) < std::abs(best - middle)) best = b;
            split(alongU ? 0 : 1, best);
            continue;
        }
        // one Bezier patch: bound the error of its piece over the cell (section 5.2)
        if (node.parentPiece) {
            const Rect& p = node.parentRect;
            auto local = [](cInt x, cInt lo, cInt hi) { return double(x - lo) / double(hi - lo); };
            ownPiece = std::make_shared<const BezierPatch>(
                node.parentPiece->restricted(local(r.x0, p.x0, p.x1), local(r.x1, p.x0, p.x1),
                                             local(r.y0, p.y0, p.y1), local(r.y1, p.y0, p.y1)));
            childrenPiece = ownPiece;
        } else {
            const Point2 low = frame_->toParameter(r.x0, r.y0);
            const Point2 high = frame_->toParameter(r.x1, r.y1);
            const Point2 middle = 0.5 * (low + high);
            const int su = patches_->spanIndexU(middle.x()), sv = patches_->spanIndexV(middle.y());
            ownPiece = std::make_shared<const BezierPatch>(
                patches_->piece(su, sv, low.x(), high.x(), low.y(), high.y()));
            // not where the cell reaches past its span (a frame past the surface's domain): the
            // piece is then the span's part within it, clamped, and no longer maps the cell
            // linearly. A side on a span border rounded to the frame's step is on it.
            const auto& breaksU = patches_->breakpointsU();
            const auto& breaksV = patches_->breakpointsV();
            const double stepU = 1 / frame_->scaleU, stepV = 1 / frame_->scaleV;
            if (low.x() >= breaksU[su] - stepU && high.x() <= breaksU[su + 1] + stepU &&
                low.y() >= breaksV[sv] - stepV && high.y() <= breaksV[sv + 1] + stepV)
                childrenPiece = ownPiece;
        }
        const BezierPatch& piece = *ownPiece;
        // a cell whose centre is off by more than the target is split whatever its bound
        int preferredDirection = 0;
        // a trimmed cell whose bound for corners on its sides would do (bandSplit), and the
        // widest band it may cut off
        bool sidesWouldDo = false;
        double widestBand = kWidestBand;
        // the cell's bound where it was measured
        double measured = kUnmeasured;
        // whether centreBeyond found the centre within the target
        bool centreWithinTarget = false;
        if (decided) {
            if (known->second.settles) {
                settle(known->second.bound);
                continue;
            }
            preferredDirection = known->second.preferredDirection;
            sidesWouldDo = known->second.sidesWouldDo;
            widestBand = known->second.widestBand;
        } else if (mode_ == ErrorMode::Guaranteed && centreBeyond(piece, target)) {
            preferredDirection = preferredSplitDirection(piece);
            record(false, preferredDirection);
        } else {
            centreWithinTarget = mode_ == ErrorMode::Guaranteed;
            const CellErrorBound bound =
                node.halfBound && node.halfTarget == target && node.halfTrimmed == trimmedCell &&
                        node.halfFraction == pieceFraction
                    ? *node.halfBound
                    : cellErrorBound(piece, mode_, target, trimmedCell,
                                     choices_.flatCellsByDistance, pieceFraction);
            // a trimmed cell's bound for corners on its sides, measured (not the plain sum
            // interior + boundary that `bound` takes), once for the checks below that need it
            std::optional<CellErrorBound> sides;
            auto measuredSides = [&]() -> const CellErrorBound& {
                if (!sides)
                    sides =
                        cellErrorBound(piece, mode_, target, false, choices_.flatCellsByDistance);
                return *sides;
            };
            measured = bound.measure(mode_, trimmedCell);
            const bool settles = measured <= target;
            record(settles, bound.splitDirection, measured);
            if (settles) {
                settle(bound.measure(mode_, trimmedCell));
                continue;
            }
            // a boundary a hair inside the cell's sides, on a face whose filled cells take the
            // bound for corners on their sides: the bound for corners near them
            if (trimmedCell && mode_ == ErrorMode::Guaranteed && choices_.filledCellsBySides &&
                pieceFraction > 0.5)
                if (const auto near = nearSideOffsets(*node.region, r, node.simpleRing)) {
                    // the bound for corners on the sides, measured for them (not the trimmed
                    // cell's plain sum)
                    const double nearBound =
                        measuredSides().nearSides(parameterSpeed(piece), (*near)[0], (*near)[1]);
                    if (nearBound <= target) {
                        record(true, 0, nearBound);
                        settle(nearBound);
                        continue;
                    }
                }
            preferredDirection = bound.splitDirection;
            sidesWouldDo = trimmedCell && bound.untrimmed() <= target;
            if (trimmedCell && !sidesWouldDo && mode_ == ErrorMode::Guaranteed &&
                choices_.filledCellsBySides && choices_.splitThroughBoundaryPoints &&
                bound.untrimmed() <= kMeasuredSidesWithin * target &&
                measuredSides().untrimmed() <= target) {
                sidesWouldDo = true;
                widestBand = bound.measure(mode_, trimmedCell) > kFarAboveTarget * target
                                 ? kWidestBand
                                 : kThinBand;
            }
            if (recorded) {
                recorded->sidesWouldDo = sidesWouldDo;
                recorded->widestBand = widestBand;
            }
        }
        const bool canU = r.x1 - r.x0 >= 2, canV = r.y1 - r.y0 >= 2;
        if (node.depth >= kMaxDepth || (!canU && !canV)) {
            toleranceReached_ = false;
            leaves_[node.index].leaf = true;
            continue;
        }
        // the other halving where it settles both halves and the bound's does not (the
        // command line's meshes; the display's keep the paper's cut). The second build (even
        // columns) reads the direction from the decisions.
        if (choices_.middleSplits && canU && canV && !decided) {
            preferredDirection = settlingSplitDirection(
                piece, preferredDirection, target, trimmedCell, choices_.flatCellsByDistance,
                pieceFraction, mode_, &halves, centreWithinTarget);
            halvesDirection = preferredDirection;
            if (recorded) recorded->preferredDirection = preferredDirection;
        }
        // A middle cut that meets a free chord leaves a point on it: an open edge, which stays
        // where the removal cannot drop it (removeOpenBoundaryPoints), and always where the
        // chord is on the surface. Where the other halving meets none and lowers the bound by
        // kAlongFreeChordGain, the cell is cut that way: a twisted cell at its free edge (a
        // ruled face's rim) becomes a thin row along the chord, whose width its curvature
        // alone sets.
        if (choices_.cutsAlongFreeChords && choices_.middleSplits && !freeChords_.empty() && canU &&
            canV && measured < kUnmeasured && !decided) {
            const cInt middle[2] = {r.x0 + (r.x1 - r.x0 + 1) / 2, r.y0 + (r.y1 - r.y0 + 1) / 2};
            const int other = 1 - preferredDirection;
            // the middle cut in `direction` as a cell of no width: its ends on the cell's sides,
            // or its crossing inside, become points of the chords it meets
            auto cutMeetsFreeChord = [&](int direction) {
                const cInt at = middle[direction];
                return touchesFreeChord(direction == 0 ? std::array<cInt, 4>{at, r.y0, at, r.y1}
                                                       : std::array<cInt, 4>{r.x0, at, r.x1, at});
            };
            if (cutMeetsFreeChord(preferredDirection) && !cutMeetsFreeChord(other)) {
                const double half = double(middle[other] - (other == 0 ? r.x0 : r.y0)) /
                                    double(other == 0 ? r.x1 - r.x0 : r.y1 - r.y0);
                double worst = 0;
                for (const auto& [t0, t1] : {std::pair{0.0, half}, std::pair{half, 1.0}}) {
                    const BezierPatch h = other == 0 ? piece.restricted(t0, t1, 0, 1)
                                                     : piece.restricted(0, 1, t0, t1);
                    worst = std::max(worst, cellErrorBound(h, mode_, target, trimmedCell,
                                                           choices_.flatCellsByDistance)
                                                .measure(mode_, trimmedCell));
                }
                if (worst <= kAlongFreeChordGain * measured) preferredDirection = other;
                if (recorded) recorded->preferredDirection = preferredDirection;
            }
        }
        // each axis's even columns' middle line where the cell holds two or more (the lines its
        // edges' points were put on)
        std::optional<std::int64_t> evenSplits[2];
        for (int axis = 0; axis < 2; ++axis)
            if (frame_->even[axis])
                evenSplits[axis] = (*choices_.evenColumns)[axis].evenSplit(axis == 0 ? r.x0 : r.y0,
                                                                           axis == 0 ? r.x1 : r.y1);
        int direction = preferredDirection;
        // a cell the bound would cut across its even columns, where it holds two or more of
        // them: cut along them instead on the second build (findCrossings)
        if (!evenSplits[direction] && evenSplits[1 - direction]) {
            evenOrderMatters_ = true;
            if (evenLinesFirst_) direction = 1 - direction;
        }
        if ((direction == 0 && !canU) || (direction == 1 && !canV)) direction = 1 - direction;
        const cInt lo = direction == 0 ? r.x0 : r.y0, hi = direction == 0 ? r.x1 : r.y1;
        // on that even line, else in the middle (splitDirectionOfNet) or through the farthest net
        // point
        const std::optional<std::int64_t>& even = evenSplits[direction];
        const cInt at =
            even ? static_cast<cInt>(*even)
            : choices_.middleSplits
                ? lo + (hi - lo + 1) / 2
                : std::clamp<cInt>(lo + std::llround(farthestNetPointAt(piece, preferredDirection) *
                                                     double(hi - lo)),
                                   lo + 1, hi - 1);
        if (sidesWouldDo && choices_.filledCellsBySides && choices_.splitThroughBoundaryPoints)
            if (const auto band = bandSplit(*node.region, r, widestBand)) {
                split(band->first, band->second);
                continue;
            }
        cInt where = node.full || !choices_.splitThroughBoundaryPoints
                         ? at
                         : throughBoundaryPoint(*node.region, r, direction, at);
        // An edge along an iso-line of this face may carry another face's points (a torus
        // fillet's circle that the cylinder beside it discretised). throughBoundaryPoint takes
        // a point on a cell's side only where both ends of the line are on the boundary, and a
        // full cell keeps its middle; so every split across such an edge goes through the
        // edge's point nearest it instead (IsoRunLines), full cells included, and the cells of
        // one column keep one line while the edge gains no point there (trj7_b1-ec-214.stp at
        // relative 1e-4: 30,663 -> 29,421 triangles, bug33398.step 32,370 -> 32,070,
        // hammer.iges 9,564 -> 9,408). Not on a face with a free edge, which bounds its cells
        // at the boundary as trimmed ones (filledCellsBySides): off-centre cells cost it more
        // than the points saved (wing.brep at 1e-4: 6,529 -> 7,536 triangles).
        if (where == at && !even && throughIsoRuns) where = isoRuns.nearest(direction, lo, hi, at);
        split(direction, where);
        // a cut through the middle of a cell whose children's pieces are its own halves
        if (direction == halvesDirection && 2 * where == lo + hi && childrenPiece)
            for (int k = 0; k < 2; ++k) {
                Node& child = stack[stack.size() - 1 - k];  // the lower half on top
                child.halfBound = std::move(halves[k]);
                child.halfTarget = target;
                child.halfTrimmed = trimmedCell;
                child.halfFraction = pieceFraction;
            }
    }
}

namespace {

// Cell corners by the line they lie on, to put a neighbour's corners (hanging points) into
// the sides of a bigger cell so that neighbouring cells share every point of a common side.
// Each axis is one sorted array of (line, value) entries: a line's values are a run of it. A map
// of vectors per line allocated every line and grew every vector one point at a time (2% of
// trj7's instructions in malloc and free alone). An entry is one word, the line in its high
// half and the value in its low half, each offset by 2^31: words sort as the pairs would, by
// Boost's spreadsort (radix buckets) rather than comparisons. Sorting pairs of 64-bit integers
// with std::sort was 5% of bottle.brep's tessellation time at relative 1e-4; words with it
// about 3.5%. Frame steps lie in [0, 2^30] and a few steps beyond (cells grown by one step),
// far inside the 32 bits each half holds.
struct CornerLines {
    using Entry = std::uint64_t;
    std::vector<Entry> onVertical;    // (x, y)
    std::vector<Entry> onHorizontal;  // (y, x)

    static constexpr cInt kOffset = cInt(1) << 31;
    static Entry entry(cInt line, cInt value) {
        if (line < -kOffset || line >= kOffset || value < -kOffset || value >= kOffset)
            throw std::runtime_error("a trimming point lies outside the face's parameter frame");
        return (static_cast<Entry>(line + kOffset) << 32) | static_cast<Entry>(value + kOffset);
    }
    static cInt lineOf(Entry e) { return static_cast<cInt>(e >> 32) - kOffset; }
    static cInt valueOf(Entry e) { return static_cast<cInt>(e & 0xffffffffu) - kOffset; }

    void add(const IntPoint& p) {
        onVertical.push_back(entry(p.X, p.Y));
        onHorizontal.push_back(entry(p.Y, p.X));
    }
    void finish() {
        for (auto* lines : {&onVertical, &onHorizontal}) {
            boost::sort::spreadsort::integer_sort(lines->begin(), lines->end());
            lines->erase(std::unique(lines->begin(), lines->end()), lines->end());
        }
    }
    bool isCorner(const IntPoint& p) const {
        return std::binary_search(onVertical.begin(), onVertical.end(), entry(p.X, p.Y));
    }
    // Points strictly between a and b on a common vertical or horizontal line, in order a -> b.
    void between(const IntPoint& a, const IntPoint& b, Path& out) const {
        if (a.X == b.X)
            valuesBetween(onVertical, a.X, a.Y, b.Y, [&](cInt y) { out.push_back({a.X, y}); });
        else if (a.Y == b.Y)
            valuesBetween(onHorizontal, a.Y, a.X, b.X, [&](cInt x) { out.push_back({x, a.Y}); });
    }
    // The values that `lines` holds on `line` strictly between from and to, in the order
    // from -> to: one routine for both directions of both axes.
    template <class Emit>
    static void valuesBetween(const std::vector<Entry>& lines, cInt line, cInt from, cInt to,
                              Emit emit) {
        if (from < to) {
            for (auto v = std::upper_bound(lines.begin(), lines.end(), entry(line, from));
                 v != lines.end() && lineOf(*v) == line && valueOf(*v) < to; ++v)
                emit(valueOf(*v));
        } else {
            auto v = std::lower_bound(lines.begin(), lines.end(), entry(line, from));
            while (v != lines.begin()) {
                --v;
                if (lineOf(*v) != line || valueOf(*v) <= to) break;
                emit(valueOf(*v));
            }
        }
    }
    // Adds the hanging points to the sides of a path that run along the cell's border.
    Path withHangingPoints(const Path& path, const Rect& r) const {
        Path out;
        for (size_t i = 0; i < path.size(); ++i) {
            const IntPoint& a = path[i];
            const IntPoint& b = path[(i + 1) % path.size()];
            out.push_back(a);
            const bool vertical = a.X == b.X && (a.X == r.x0 || a.X == r.x1);
            const bool horizontal = a.Y == b.Y && (a.Y == r.y0 || a.Y == r.y1);
            if (vertical || horizontal) between(a, b, out);
        }
        return out;
    }
};

// The polygons with holes of a leaf: each entry is rings[0] = outer, rings[1..] = holes.
std::vector<Paths> polygonsOfLeaf(const Paths& region, const Rect& r, bool full,
                                  const CornerLines& lines, bool oneSimpleRing) {
    std::vector<Paths> out;
    if (full) {
        out.push_back({lines.withHangingPoints(r.path(), r)});
        return out;
    }
    // one simple ring's piece in one pass, as the kd-tree's cells (clip above): the clipper
    // was a seventh of bottle.brep's instructions here
    if (const auto piece = simpleRingPiece(region, oneSimpleRing, r)) {
        if (!piece->empty()) out.push_back({lines.withHangingPoints(piece->front(), r)});
        return out;
    }
    ClipperLib::Clipper& clipper = threadClipper();
    clipper.PreserveCollinear(true);
    clipper.AddPaths(region, ClipperLib::ptSubject, true);
    clipper.AddPath(r.path(), ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    std::vector<const ClipperLib::PolyNode*> outers;
    for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext())
        if (!node->IsHole()) outers.push_back(node);
    for (const auto* outer : outers) {
        Paths rings{lines.withHangingPoints(outer->Contour, r)};
        for (const auto* hole : outer->Childs)
            rings.push_back(lines.withHangingPoints(hole->Contour, r));
        out.push_back(std::move(rings));
    }
    return out;
}

}  // namespace

void FaceTessellator::forEachLeaf(
    const ClipperLib::Paths& region, bool oneSimpleRing,
    const std::function<void(const Leaf&, const Paths&, bool)>& visit) const {
    // The region cut down the tree node by node: each cut sees only its parent's piece, so the
    // whole walk costs about the boundary's size times the tree's depth. A leaf gets its
    // parent's piece, which its polygons are cut from (polygonsOfLeaf): cut here too, every
    // leaf was clipped twice.
    // A region of one simple ring (oneSimpleRing) stays one down the tree as long as each cut
    // is clipSimpleRing's; the first cut that is not leaves paths that run back and forth along
    // the cell's sides, and the leaves below it go to the clipper.
    const Paths none;  // a full leaf's: its polygon is its rectangle
    struct Entry {
        int index;
        std::shared_ptr<const Paths> parentRegion;
        bool oneSimpleRing;
    };
    std::vector<Entry> stack;
    stack.push_back({0, std::make_shared<const Paths>(region), oneSimpleRing});
    while (!stack.empty()) {
        auto [index, parentRegion, parentSimple] = std::move(stack.back());
        stack.pop_back();
        const Leaf& node = leaves_[index];
        if (node.leaf) {
            visit(node, node.full ? none : *parentRegion, parentSimple);
            continue;
        }
        Paths piece;
        bool simplePiece = false;
        if (!node.full) {
            const Rect& r = node.rect;
            if (auto simple = simpleRingPiece(*parentRegion, parentSimple, r)) {
                simplePiece = true;
                piece = std::move(*simple);
            } else {
                piece = clipKeepingWinding(*parentRegion, r.x0, r.y0, r.x1, r.y1);
            }
        }
        if (node.children[0] >= 0) {
            // both children read the piece: shared, not copied
            auto shared = std::make_shared<const Paths>(std::move(piece));
            stack.push_back({node.children[1], shared, simplePiece});
            stack.push_back({node.children[0], std::move(shared), simplePiece});
        }
    }
}

// Points that must stay in a cell's sides: the corners of all leaves (a neighbour's corners
// are hanging points of a bigger cell), and the boundary's own points, which the clipper drops
// where the boundary runs along a cell side.
namespace {
CornerLines cornerLinesOf(const std::vector<Rect>& cells,
                          const std::vector<std::vector<IntPoint>>& loopPoints) {
    CornerLines lines;
    std::size_t count = 4 * cells.size();
    for (const auto& loop : loopPoints) count += loop.size();
    lines.onVertical.reserve(count);
    lines.onHorizontal.reserve(count);
    for (const auto& cell : cells)
        for (const IntPoint& c : {IntPoint{cell.x0, cell.y0}, IntPoint{cell.x1, cell.y0},
                                  IntPoint{cell.x1, cell.y1}, IntPoint{cell.x0, cell.y1}})
            lines.add(c);
    for (const auto& loop : loopPoints)
        for (const IntPoint& p : loop) lines.add(p);
    lines.finish();
    return lines;
}

// The boundary as both passes look it up: the points that must stay in cell sides, and the
// segment under a point the clipper made.
struct BoundaryLookup {
    CornerLines lines;
    BoundaryIndex index;
    BoundaryLookup(const std::vector<std::vector<IntPoint>>& loops, const std::vector<Rect>& cells)
        : lines(cornerLinesOf(cells, loops)) {
        index.build(loops);
    }
};
}  // namespace

void FaceTessellator::buildLeaves(const Paths& region, bool simpleRegion) {
    // The bound cuts a cell across its even columns where that is the larger error, and the
    // rows cut so run over all the columns in the cell: each column then takes the rows its
    // neediest neighbour needs. Where a column's rows settle sooner in some columns than in
    // others, cutting the columns first lets each take its own; where the columns' need differs
    // from row to row instead (a sphere's, fewer near its poles), cutting across first does.
    // Where the order matters, the kd-tree is built both ways and the one with fewer cells
    // kept; the second build takes the first's bounds of the cells both have (CellDecisions).
    // The 32 models at relative 1e-3 and 1e-4: the helical sweep of
    // tests/bench/generated_shapes.py at 1e-3 7,012 -> 4,764 triangles (its side, degree 6
    // around and 10 along, built twice at about twice the instructions), trj7_b1-ec-214.stp at
    // 1e-4 39,239 -> 39,213, the others unchanged. (Before the split weighed the net's bends by
    // the degrees, splitOfNet, the loft's side, degree 12 around and 2 along, was the one that
    // gained: 4,502 -> 2,894 triangles at 1e-3.)
    CellDecisions decisions;
    decisions.record = frame_->even[0] || frame_->even[1];
    buildKdTree(region, simpleRegion, decisions);
    if (evenOrderMatters_) {
        auto leafCount = [](const std::vector<Leaf>& leaves) {
            return std::count_if(leaves.begin(), leaves.end(),
                                 [](const Leaf& leaf) { return leaf.leaf; });
        };
        std::vector<Leaf> rowsFirst = std::move(leaves_);
        const bool rowsFirstReached = toleranceReached_;
        evenLinesFirst_ = true;
        toleranceReached_ = true;
        decisions.record = false;
        buildKdTree(region, simpleRegion, decisions);
        if (leafCount(leaves_) >= leafCount(rowsFirst)) {
            leaves_ = std::move(rowsFirst);
            toleranceReached_ = rowsFirstReached;
        }
    }
}

std::vector<BoundaryCrossing> FaceTessellator::findCrossings(
    const std::vector<BoundaryLoop>& loops) {
    if (auto problem = face_.surface.problem()) throw std::runtime_error(*problem);
    setFrame(loops);
    setFreeChords(loops);
    const Paths region = regionOf(loops);
    double area = 0;
    for (const auto& p : region) area += ClipperLib::Area(p);
    if (!(std::abs(area) > 0)) throw FaceWithoutArea("the trimming loops enclose no area");
    const bool simpleRegion = isOneRingWithoutTouch(region);
    // A face in a plane whose loops make one polygon there takes no kd-tree: triangulate makes
    // its triangles in the plane, and no cell side cuts its chords (the loops' points are its
    // surface's at their (u, v) here, within the share gap of the points it gets).
    std::vector<std::vector<Point3>> onSurface;
    if (plane_ || cylinder_)
        onSurface = ringsInSpace(loops, [&](const BoundaryPoint& bp) {
            return face_.surface.point(bp.uv.x(), bp.uv.y());
        });
    if (plane_ && developedTriangles(onSurface)) {
        leaves_.clear();
        return {};
    }
    // A face on a cylinder whose unrolled triangles keep the bound over its loops' points takes
    // them. One that needs points on its chords for that asks for them where they are fewer
    // than the kd-tree's, below.
    std::optional<UnrolledTriangles> firstTry;
    if (cylinder_) {
        firstTry = triangulateUnrolled(*cylinder_, onSurface);
        if (firstTry && keepsBound(*firstTry, unrolledShare())) {
            leaves_.clear();
            return {};
        }
    }
    buildLeaves(region, simpleRegion);

    std::vector<Rect> cells;
    for (const auto& leaf : leaves_)
        if (leaf.leaf) cells.push_back(leaf.rect);
    const BoundaryLookup lookup(integerBoundary(loops), cells);
    const CornerLines& lines = lookup.lines;
    const BoundaryIndex& index = lookup.index;

    std::vector<BoundaryCrossing> crossings;
    std::unordered_map<std::int64_t, bool> seen;
    forEachLeaf(
        region, simpleRegion, [&](const Leaf& leaf, const Paths& leafRegion, bool oneSimpleRing) {
            if (leaf.full) return;
            for (const Paths& rings :
                 polygonsOfLeaf(leafRegion, leaf.rect, false, lines, oneSimpleRing))
                for (const Path& ring : rings)
                    for (const IntPoint& p : ring) {
                        const auto key = keyOf(p.X, p.Y);
                        if (index.corners.count(key) || seen.count(key)) continue;
                        seen[key] = true;
                        auto [segment, t] = index.segmentAt(p, 1.5);
                        if (segment < 0) continue;  // a surface point inside the region
                        const auto& s = index.segments[segment];
                        const BoundarySegmentOrigin& origin = loops[s.loop].origins[s.index];
                        if (origin.edge < 0) continue;
                        // t runs along the loop; the edge may run the other way
                        crossings.push_back({origin.edge, origin.segment, origin.use,
                                             origin.forward ? t : 1 - t, p.X, p.Y});
                    }
        });
    if (firstTry) {
        // Triangles over a polygon of b points on its boundary and i inside: b + 2 i - 2. The
        // unrolled ones have the loops' points and the added ones; the kd-tree's the loops'
        // points, its crossings, and at least the corners of its cells inside the region
        // (those of cells the boundary does not touch).
        std::unordered_set<std::int64_t> inside;
        for (const auto& leaf : leaves_)
            if (leaf.leaf && leaf.full)
                for (const IntPoint& corner : leaf.rect.path())
                    if (!index.corners.count(keyOf(corner.X, corner.Y)))
                        inside.insert(keyOf(corner.X, corner.Y));
        // (the first try's rounds go no farther than that: a face whose cylinder loses to its
        // kd-tree, the bolt's half cylinders, takes none)
        if (auto unrolled = unrolledCrossings(loops, onSurface, *firstTry,
                                              crossings.size() + 2 * inside.size())) {
            leaves_.clear();
            return std::move(*unrolled);
        }
    }
    return crossings;
}

FaceMesh FaceTessellator::triangulate(const std::vector<BoundaryLoop>& loops,
                                      const std::vector<Point3>& sharedPositions,
                                      const std::vector<double>& sharedOffsets) {
    FaceMesh mesh;
    const Paths region = regionOf(loops);
    // A face in a plane (FacePlane) is one polygon of its loops' points, triangulated by their
    // coordinates in the plane: every triangle lies in the plane (within the flatness, and the
    // shared points' offsets, which its unspent surface share covers), and together they tile
    // the polygon of its chords exactly, as the kd-tree's triangles, mapped from (u, v), do
    // within their bound.
    std::optional<std::vector<std::array<std::uint32_t, 3>>> inPlane;
    // (a face on a cylinder whose first pass took a kd-tree keeps it: its unrolled triangles
    // over more points would rarely be narrower, and they cost an ear clipping of the face)
    if (plane_ || (cylinder_ && leaves_.empty())) {
        inPlane = developedTriangles(ringsInSpace(
            loops, [&](const BoundaryPoint& bp) { return sharedPositions[bp.vertex]; }));
    }
    // One that findCrossings left without a kd-tree, whose loops with their final points make
    // no polygon in the plane, takes its kd-tree now: the points its cells cut on shared chords
    // reach the other faces as open cuts (ModelTessellator, step 5b).
    if (!inPlane && leaves_.empty()) {
        setFreeChords(loops);
        buildLeaves(region, isOneRingWithoutTouch(region));
    }

    std::vector<Rect> cells;
    for (const auto& leaf : leaves_)
        if (leaf.leaf) cells.push_back(leaf.rect);
    const BoundaryLookup lookup(integerBoundary(loops), cells);
    const CornerLines& lines = lookup.lines;
    const BoundaryIndex& index = lookup.index;

    // face vertices: shared ones by shared id, the face's own by integer point
    std::unordered_map<std::uint32_t, std::uint32_t> sharedToFace;
    std::unordered_map<std::int64_t, std::uint32_t> pointToFace;
    // the cuts of cell sides with boundary segments no other face knows: by integer point, the
    // segment and the vertex
    std::unordered_map<std::int64_t, std::pair<int, std::uint32_t>> cutsOnSegments;
    std::vector<Point2> uvOfVertex;
    std::vector<char> needsPosition;
    auto sharedVertex = [&](std::uint32_t id, const Point2& uv) {
        auto [it, inserted] =
            sharedToFace.emplace(id, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (inserted) {
            FaceMesh::Vertex v;
            v.shared = true;
            v.sharedId = id;
            v.position = sharedPositions[id];
            mesh.vertices.push_back(v);
            uvOfVertex.push_back(uv);
            needsPosition.push_back(0);
        }
        return it->second;
    };
    auto ownVertex = [&](const IntPoint& p, const Point2& uv, const Point3* position) {
        auto [it, inserted] =
            pointToFace.emplace(keyOf(p.X, p.Y), static_cast<std::uint32_t>(mesh.vertices.size()));
        if (inserted) {
            FaceMesh::Vertex v;
            if (position) v.position = *position;
            mesh.vertices.push_back(v);
            uvOfVertex.push_back(uv);
            needsPosition.push_back(position ? 0 : 1);
        }
        return it->second;
    };
    auto resolve = [&](const IntPoint& p) -> std::uint32_t {
        const auto key = keyOf(p.X, p.Y);
        if (auto it = index.corners.find(key); it != index.corners.end()) {
            const auto& bp = loops[it->second.first].points[it->second.second];
            return sharedVertex(bp.vertex, bp.uv);
        }
        if (lines.isCorner(p) && index.segmentAt(p, 0.5).first < 0)
            return ownVertex(p, frame_->toParameter(p.X, p.Y), nullptr);
        if (auto [loop, i] = index.cornerNear(p, 3); loop >= 0) {
            const auto& bp = loops[loop].points[i];
            return sharedVertex(bp.vertex, bp.uv);
        }
        if (auto [segment, t] = index.segmentAt(p, 1.5); segment >= 0) {
            // a cut no other face knows: a point on this face's chord (an open edge). The two
            // cells on either side of the cut may each round it to its own integer point, a
            // step apart: one vertex for both, or the chord's point is two vertices, each with
            // half its fan, which removeOpenBoundaryPoints takes for corners and keeps
            // (OpenCASCADE's shell1.brep at relative 1e-3: 67 open edges, 50 with one vertex;
            // BRepMesh 49).
            for (cInt dx = -1; dx <= 1; ++dx)
                for (cInt dy = -1; dy <= 1; ++dy)
                    if (const auto it = cutsOnSegments.find(keyOf(p.X + dx, p.Y + dy));
                        it != cutsOnSegments.end() && it->second.first == segment)
                        return it->second.second;
            const auto& s = index.segments[segment];
            const auto& loop = loops[s.loop];
            const auto& a = loop.points[s.index];
            const auto& b = loop.points[(s.index + 1) % loop.points.size()];
            const Point3 position =
                (1 - t) * sharedPositions[a.vertex] + t * sharedPositions[b.vertex];
            if (const auto& origin = loop.origins[s.index]; origin.edge >= 0)
                mesh.openCuts.push_back(
                    {origin.edge, origin.segment, origin.use, position, p.X, p.Y});
            const std::uint32_t id = choices_.freeEdgesOnSurface
                                         ? ownVertex(p, (1 - t) * a.uv + t * b.uv, nullptr)
                                         : ownVertex(p, (1 - t) * a.uv + t * b.uv, &position);
            cutsOnSegments.emplace(keyOf(p.X, p.Y), std::pair{segment, id});
            return id;
        }
        return ownVertex(p, frame_->toParameter(p.X, p.Y), nullptr);
    };

    // The ring's points on a side of the cell whose points are all one point in space (a pole:
    // a degenerated edge, each of whose points the boundary gives its own vertex at the same
    // position), or empty where no side is. Only a true pole: points equal but for rounding
    // (1e-9 of the cell's coordinates). A side that is merely short in space, or a pole row
    // a sloppy file spreads, keeps the plain triangulation: a triangle with two of its points
    // has area there, and may be all the face has (a thin spike).
    auto pointsAtPole = [&](const std::vector<IntegerPoint2>& ring,
                            const std::vector<std::uint32_t>& ringIds, const Rect& r) {
        std::vector<char> atPole(ring.size(), 0);
        double magnitude = 0;
        for (std::uint32_t id : ringIds)
            if (!needsPosition[id])
                magnitude = std::max(magnitude, mesh.vertices[id].position.cwiseAbs().maxCoeff());
        const double samePoint = 1e-9 * magnitude;
        bool any = false;
        for (int side = 0; side < 4; ++side) {
            std::vector<std::size_t> on;
            for (std::size_t i = 0; i < ring.size(); ++i) {
                const IntegerPoint2& p = ring[i];
                if (side == 0   ? p.x == r.x0
                    : side == 1 ? p.x == r.x1
                    : side == 2 ? p.y == r.y0
                                : p.y == r.y1)
                    on.push_back(i);
            }
            if (on.size() < 2) continue;
            bool collapsed = true;
            const Point3& first = mesh.vertices[ringIds[on[0]]].position;
            for (std::size_t i : on)
                collapsed &= !needsPosition[ringIds[i]] &&
                             (mesh.vertices[ringIds[i]].position - first).norm() <= samePoint;
            if (!collapsed) continue;
            for (std::size_t i : on) atPole[i] = 1;
            any = true;
        }
        if (!any) atPole.clear();
        return atPole;
    };

    // a triangle on three distinct vertices; one that names a vertex twice has no area
    auto addTriangle = [&mesh](const std::array<std::uint32_t, 3>& tri) {
        if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) mesh.triangles.push_back(tri);
    };
    if (inPlane) {
        std::vector<std::uint32_t> vertexOf;
        for (const auto& loop : loops)
            for (const auto& bp : loop.points) vertexOf.push_back(sharedVertex(bp.vertex, bp.uv));
        for (const auto& t : *inPlane)
            addTriangle({vertexOf[t[0]], vertexOf[t[1]], vertexOf[t[2]]});
    }

    // each triangle's leaf's slack (Leaf::slack; 0 for the triangles of no leaf)
    std::vector<double> triangleSlack;
    // one polygon's vertex ids and rings, their capacity kept from leaf to leaf
    std::vector<std::uint32_t> ids;
    std::vector<std::vector<IntegerPoint2>> integerRings;
    if (!inPlane)
        forEachLeaf(
            region, isOneRingWithoutTouch(region),
            [&](const Leaf& leaf, const Paths& leafRegion, bool oneSimpleRing) {
                ++mesh.cells;
                for (const Paths& rings :
                     polygonsOfLeaf(leafRegion, leaf.rect, leaf.full, lines, oneSimpleRing)) {
                    ids.clear();
                    integerRings.resize(rings.size());
                    for (std::size_t r = 0; r < rings.size(); ++r) {
                        const Path& ring = rings[r];
                        std::vector<IntegerPoint2>& integerRing = integerRings[r];
                        integerRing.clear();
                        for (std::size_t i = 0; i < ring.size(); ++i) {
                            const IntPoint& p = ring[i];
                            if (ring.size() > 3 && !lines.isCorner(p) &&
                                index.isCollinearOnChord(ring, i))
                                continue;
                            integerRing.push_back({p.X, p.Y});
                            ids.push_back(resolve(p));
                        }
                    }
                    if (leaf.full && integerRings.size() == 1 && integerRings[0].size() == 4) {
                        // a whole cell without neighbours' points: its two triangles (section 7)
                        mesh.triangles.push_back({ids[0], ids[1], ids[2]});
                        mesh.triangles.push_back({ids[0], ids[2], ids[3]});
                        continue;
                    }
                    if (leaf.full && integerRings.size() == 1) {
                        // a whole cell with hanging points: no cap that could fold in space
                        for (const auto& t : triangulateCellWithoutCaps(integerRings[0]))
                            mesh.triangles.push_back({ids[t[0]], ids[t[1]], ids[t[2]]});
                        continue;
                    }
                    if (integerRings.size() == 1) {
                        // a cell with one side at a pole: no triangle flat against the surface
                        // there
                        const auto atPole = pointsAtPole(integerRings[0], ids, leaf.rect);
                        const auto triangles = atPole.empty()
                                                   ? std::vector<std::array<std::uint32_t, 3>>{}
                                                   : triangulateCellAtPole(integerRings[0], atPole);
                        // the pole's one vertex twice: no triangle (a spike of a face is then
                        // left without any, and fanned over its boundary like other faces too
                        // thin)
                        for (const auto& t : triangles)
                            addTriangle({ids[t[0]], ids[t[1]], ids[t[2]]});
                        if (!triangles.empty()) continue;
                    }
                    const Triangulation triangulation = triangulatePolygon(integerRings);
                    // points the boundary shares (a pole, a snapped cut) make zero-area
                    // triangles
                    for (const auto& t : triangulation.triangles)
                        addTriangle({ids[t[0]], ids[t[1]], ids[t[2]]});
                }
                triangleSlack.resize(mesh.triangles.size(), leaf.slack);
            });
    triangleSlack.resize(mesh.triangles.size(), 0.0);

    // positions and exact normals at every vertex (section 8), in one pass that shares the
    // basis functions of equal u and v values; a shared vertex keeps its edge's position (the
    // surface point comes with its normal at no extra cost, and is dropped)
    std::vector<Point3> positions(mesh.vertices.size());
    std::vector<Vector3> normals(mesh.vertices.size());
    PointSetEvaluator(face_.surface).evaluate(uvOfVertex, positions.data(), normals.data());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (needsPosition[i]) mesh.vertices[i].position = positions[i];
        mesh.vertices[i].positionFromSurface = needsPosition[i] != 0;
        mesh.vertices[i].normal = face_.reversed ? Vector3(-normals[i]) : normals[i];
        mesh.vertices[i].uv = uvOfVertex[i];
    }
    const double allowance = 0.5 * budget_.shareGap + budget_.openChords;
    // where the new triangles change the old ones more than the allowance, bounded against the
    // surface: within the surface share and the allowance, as a trimmed cell's triangles
    TriangleBound boundedBySurface;
    if (mode_ == ErrorMode::Guaranteed && choices_.openPointsBoundedBySurface)
        boundedBySurface = [&](const std::array<std::uint32_t, 3>& t) {
            const auto& v = mesh.vertices;
            return triangleBound({v[t[0]].uv, v[t[1]].uv, v[t[2]].uv},
                                 {v[t[0]].position, v[t[1]].position, v[t[2]].position},
                                 budget_.surface + allowance);
        };
    removeOpenBoundaryPoints(mesh, sharedOffsets, triangleSlack, allowance, boundedBySurface,
                             budget_.surface);
    if (mode_ == ErrorMode::Guaranteed && choices_.compact) {
        // An inner triangle has only the surface between it and the face: it may take what a
        // full cell takes (the whole sum of the shares), bounded on its own instead of by the
        // cell's bound for any triangles over it.
        const double inner = wholeCellTarget(budget_, mode_);
        const auto& v = mesh.vertices;
        // The surface's distance from a triangle at its centre and its sides' middles (as
        // triangleBound samples it), each side's kept: a ring's triangulations and the rings
        // of neighbouring points share most sides.
        std::unordered_map<std::uint64_t, double> sideDistance;
        auto distanceAtMiddle = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
            const auto [at, fresh] = sideDistance.try_emplace(key, 0.0);
            if (fresh) {
                const Point2 q = 0.5 * (v[a].uv + v[b].uv);
                at->second =
                    (patches_->point(q.x(), q.y()) - 0.5 * (v[a].position + v[b].position)).norm();
            }
            return at->second;
        };
        auto sampled = [&](const RingTriangle& t) {
            const Point2 q = (v[t[0]].uv + v[t[1]].uv + v[t[2]].uv) / 3;
            const Point3 centre = (v[t[0]].position + v[t[1]].position + v[t[2]].position) / 3;
            return std::max({(patches_->point(q.x(), q.y()) - centre).norm(),
                             distanceAtMiddle(t[0], t[1]), distanceAtMiddle(t[1], t[2]),
                             distanceAtMiddle(t[2], t[0])});
        };
        auto bounded = [&](const RingTriangle& t) {
            return triangleBound({v[t[0]].uv, v[t[1]].uv, v[t[2]].uv},
                                 {v[t[0]].position, v[t[1]].position, v[t[2]].position}, inner,
                                 /*sampleFirst=*/false);
        };
        removeInteriorPoints(mesh, sampled, bounded, inner);
    }
    splitNeedles(mesh.triangles,
                 [&](std::uint32_t i) -> const Point3& { return mesh.vertices[i].position; });
    if (face_.reversed)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    mesh.toleranceReached = toleranceReached_;
    return mesh;
}

}  // namespace nurbslod
