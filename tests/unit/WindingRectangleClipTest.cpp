#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <polyclipping/clipper.hpp>
#include <random>

#include "tessellate/WindingRectangleClip.hpp"

using namespace nurbslod;
using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

struct Box {
    cInt x0, y0, x1, y1;
    Path path() const { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
};

// The winding number of the paths around (x, y), a point on no segment.
int windingNumber(const Paths& paths, double x, double y) {
    int winding = 0;
    for (const Path& path : paths)
        for (size_t i = 0; i < path.size(); ++i) {
            const IntPoint& a = path[i];
            const IntPoint& b = path[(i + 1) % path.size()];
            const double left = (double(b.X) - a.X) * (y - a.Y) - (x - a.X) * (double(b.Y) - a.Y);
            if (a.Y <= y && y < b.Y && left > 0) ++winding;
            if (b.Y <= y && y < a.Y && left < 0) --winding;
        }
    return winding;
}

double distanceToSegments(const Paths& paths, double x, double y) {
    double nearest = INFINITY;
    for (const Path& path : paths)
        for (size_t i = 0; i < path.size(); ++i) {
            const IntPoint& a = path[i];
            const IntPoint& b = path[(i + 1) % path.size()];
            const double dx = double(b.X) - a.X, dy = double(b.Y) - a.Y;
            const double length2 = dx * dx + dy * dy;
            double t = length2 > 0 ? ((x - a.X) * dx + (y - a.Y) * dy) / length2 : 0;
            t = std::clamp(t, 0.0, 1.0);
            nearest = std::min(nearest, std::hypot(a.X + t * dx - x, a.Y + t * dy - y));
        }
    return nearest;
}

Paths clipperIntersection(const Paths& region, const Box& box) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(region, ClipperLib::ptSubject, true);
    clipper.AddPath(box.path(), ClipperLib::ptClip, true);
    Paths out;
    clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    return out;
}

double areaOf(const Paths& paths) {
    double area = 0;
    for (const Path& p : paths) area += ClipperLib::Area(p);
    return std::abs(area);
}

// Random paths that cross themselves and each other, over 0..1000 squared.
Paths randomPaths(std::mt19937& random) {
    std::uniform_int_distribution<cInt> coordinate(0, 1000);
    std::uniform_int_distribution<int> count(3, 12), paths(1, 3);
    Paths out(paths(random));
    for (Path& path : out) {
        path.resize(count(random));
        for (IntPoint& p : path) p = {coordinate(random), coordinate(random)};
    }
    return out;
}

Box randomBox(std::mt19937& random, cInt low, cInt high) {
    std::uniform_int_distribution<cInt> coordinate(low, high);
    cInt x0 = coordinate(random), x1 = coordinate(random);
    cInt y0 = coordinate(random), y1 = coordinate(random);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    return {x0, y0, x1 + 2, y1 + 2};
}

}  // namespace

// Every point strictly inside the rectangle keeps its winding number; the cut points are
// rounded, so points within a step and a half of the paths are left out.
TEST(WindingRectangleClip, KeepsEveryWindingNumberInsideTheRectangle) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int compared = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Paths region = randomPaths(random);
        const Box box = randomBox(random, -100, 1100);
        const Paths clipped = clipKeepingWinding(region, box.x0, box.y0, box.x1, box.y1);
        for (const Path& path : clipped) {
            EXPECT_GE(path.size(), 3u);
            for (const IntPoint& p : path) {
                EXPECT_TRUE(p.X >= box.x0 && p.X <= box.x1 && p.Y >= box.y0 && p.Y <= box.y1)
                    << "trial " << trial << ": a point outside the rectangle";
            }
        }
        for (int k = 0; k < 200; ++k) {
            const double x = box.x0 + unit(random) * (box.x1 - box.x0);
            const double y = box.y0 + unit(random) * (box.y1 - box.y0);
            if (x <= box.x0 || x >= box.x1 || y <= box.y0 || y >= box.y1) continue;
            if (distanceToSegments(region, x, y) < 1.5) continue;
            ASSERT_EQ(windingNumber(clipped, x, y), windingNumber(region, x, y))
                << "trial " << trial << " at " << x << ", " << y;
            ++compared;
        }
    }
    EXPECT_GT(compared, 20000);
}

// As the kd-tree's walk uses it: a node's piece cut this way and then clipped to a cell inside
// the node by the clipper gives the cell's piece of the region, up to the rounding of cut
// points (a step per cut along the cell's border).
TEST(WindingRectangleClip, ACellClippedFromTheNodesPieceHasTheSameArea) {
    std::mt19937 random(11);
    for (int trial = 0; trial < 300; ++trial) {
        Paths region;
        ClipperLib::SimplifyPolygons(randomPaths(random), region, ClipperLib::pftNonZero);
        const Box node = randomBox(random, 0, 900);
        std::uniform_int_distribution<cInt> x(node.x0, node.x1), y(node.y0, node.y1);
        cInt cx0 = x(random), cx1 = x(random), cy0 = y(random), cy1 = y(random);
        if (cx0 > cx1) std::swap(cx0, cx1);
        if (cy0 > cy1) std::swap(cy0, cy1);
        if (cx0 == cx1 || cy0 == cy1) continue;
        const Box cell{cx0, cy0, cx1, cy1};
        const Paths piece = clipKeepingWinding(region, node.x0, node.y0, node.x1, node.y1);
        const Paths direct = clipperIntersection(region, cell);
        const Paths throughPiece = clipperIntersection(piece, cell);
        double perimeter = 0;
        for (const Path& p : region) perimeter += p.size();
        EXPECT_NEAR(areaOf(throughPiece), areaOf(direct), 2.0 * (cx1 - cx0 + cy1 - cy0) + perimeter)
            << "trial " << trial;
    }
}

TEST(WindingRectangleClip, KeepsPathsInsideDropsPathsOutsideAndWrapsARectangleItSurrounds) {
    const Path inside{{20, 20}, {40, 20}, {40, 40}};
    const Path outside{{200, 200}, {300, 200}, {300, 300}};
    const Path touchingFromOutside{{100, 0}, {150, 0}, {150, 100}};  // on the side x = 100 only
    const Path around{{-50, -50}, {500, -50}, {500, 500}, {-50, 500}};
    const Paths out =
        clipKeepingWinding({inside, outside, touchingFromOutside, around}, 0, 0, 100, 100);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0], inside);
    Path square = out[1];
    std::sort(square.begin(), square.end(), [](const IntPoint& a, const IntPoint& b) {
        return a.X != b.X ? a.X < b.X : a.Y < b.Y;
    });
    EXPECT_EQ(square, (Path{{0, 0}, {0, 100}, {100, 0}, {100, 100}}));
}

// Cut points are exact where the line meets a segment at an integer, and rounded to the
// nearest integer elsewhere.
TEST(WindingRectangleClip, RoundsCutPointsToTheNearestStep) {
    // from (0, 0) to (30, 10) the segment meets x = 10 at y = 3.33 and x = 20 at 6.67
    const Paths out = clipKeepingWinding({{{0, 0}, {30, 10}, {0, 10}}}, 10, 0, 20, 10);
    ASSERT_EQ(out.size(), 1u);
    bool low = false, high = false;
    for (const IntPoint& p : out[0]) {
        low |= p == IntPoint{10, 3};
        high |= p == IntPoint{20, 7};
    }
    EXPECT_TRUE(low);
    EXPECT_TRUE(high);
}

namespace {

// A random ring: points at increasing angles around a centre, at random distances, counter-
// clockwise or clockwise. Simple but where two neighbours are more than a half turn apart.
Path randomStar(std::mt19937& random) {
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), radius(50, 500);
    std::uniform_int_distribution<int> count(3, 16), centre(300, 700), turn(0, 1);
    std::vector<double> angles(count(random));
    for (double& a : angles) a = angle(random);
    std::sort(angles.begin(), angles.end());
    const cInt cx = centre(random), cy = centre(random);
    Path ring;
    for (const double a : angles) {
        const double r = radius(random);
        const IntPoint p{cx + std::llround(r * std::cos(a)), cy + std::llround(r * std::sin(a))};
        if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
    }
    if (turn(random)) std::reverse(ring.begin(), ring.end());
    return ring;
}

// Whether two segments that share no end point meet (touching counts).
bool segmentsMeet(const IntPoint& a, const IntPoint& b, const IntPoint& c, const IntPoint& d) {
    auto side = [](const IntPoint& p, const IntPoint& q, const IntPoint& r) {
        const double cross =
            double(q.X - p.X) * double(r.Y - p.Y) - double(q.Y - p.Y) * double(r.X - p.X);
        return (cross > 0) - (cross < 0);
    };
    auto within = [](const IntPoint& p, const IntPoint& q, const IntPoint& r) {
        return std::min(p.X, q.X) <= r.X && r.X <= std::max(p.X, q.X) &&
               std::min(p.Y, q.Y) <= r.Y && r.Y <= std::max(p.Y, q.Y);
    };
    const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
    if (s1 * s2 < 0 && s3 * s4 < 0) return true;
    return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) ||
           (s3 == 0 && within(c, d, a)) || (s4 == 0 && within(c, d, b));
}

bool isSimple(const Path& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share an end
            if (segmentsMeet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
        }
    return true;
}

}  // namespace

// Where it answers, the one-pass clip of a simple ring covers what the full clipper's
// intersection covers, as one simple counter-clockwise ring; it answers most random cases.
TEST(WindingRectangleClip, ASimpleRingsPieceIsTheClippersAsOneSimpleRing) {
    std::mt19937 random(11);
    int answered = 0, refused = 0, empty = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Path ring = randomStar(random);
        const Box box = randomBox(random, 0, 1000);
        if (!isSimple(ring)) continue;  // an angular gap over a half turn can fold it
        const auto piece = clipSimpleRing(ring, box.x0, box.y0, box.x1, box.y1);
        if (!piece) {
            ++refused;
            continue;
        }
        ++answered;
        const Paths reference = clipperIntersection({ring}, box);
        if (piece->empty()) {
            ++empty;
            EXPECT_EQ(areaOf(reference), 0) << "trial " << trial;
            continue;
        }
        EXPECT_GT(ClipperLib::Area(*piece), 0) << "trial " << trial;
        EXPECT_TRUE(isSimple(*piece)) << "trial " << trial;
        for (const IntPoint& p : *piece) {
            EXPECT_TRUE(box.x0 <= p.X && p.X <= box.x1 && box.y0 <= p.Y && p.Y <= box.y1);
        }
        // the same points covered, but within a step and a half of a cut (rounded either way)
        std::uniform_real_distribution<double> x(box.x0, box.x1), y(box.y0, box.y1);
        for (int sample = 0; sample < 50; ++sample) {
            const double px = x(random), py = y(random);
            if (distanceToSegments({*piece}, px, py) < 1.5 ||
                distanceToSegments(reference, px, py) < 1.5)
                continue;
            EXPECT_EQ(windingNumber({*piece}, px, py) != 0, windingNumber(reference, px, py) != 0)
                << "trial " << trial << " at " << px << ", " << py;
        }
    }
    EXPECT_GT(answered, 2 * refused);
    EXPECT_GT(answered - empty, 1000);
}

TEST(WindingRectangleClip, ASimpleRingThatCrossesALineFourTimesIsLeftToTheClipper) {
    // a U whose two arms reach up through y = 50
    const Path u{{0, 0}, {100, 0}, {100, 100}, {70, 100}, {70, 20}, {30, 20}, {30, 100}, {0, 100}};
    EXPECT_FALSE(clipSimpleRing(u, -10, -10, 110, 50).has_value());
    // the same U cut below its notch is one ring
    const auto low = clipSimpleRing(u, -10, -10, 110, 10);
    ASSERT_TRUE(low.has_value());
    EXPECT_EQ(ClipperLib::Area(*low), 100.0 * 10);
    // touching the line y = 20 from inside at the notch's floor: the closing piece of that line
    // would run along the floor
    const Path notch{{0, 0}, {100, 0}, {100, 40}, {60, 40}, {50, 20}, {40, 40}, {0, 40}};
    EXPECT_FALSE(clipSimpleRing(notch, -10, 20, 110, 50).has_value());
}

TEST(WindingRectangleClip, ASimpleRingInsideOutsideOrAroundTheRectangle) {
    const Path inside{{10, 10}, {20, 10}, {20, 20}};
    EXPECT_EQ(clipSimpleRing(inside, 0, 0, 100, 100), inside);
    EXPECT_EQ(clipSimpleRing(inside, 50, 50, 100, 100), Path{});
    const Path around{{-10, -10}, {200, -10}, {200, 200}, {-10, 200}};
    const auto box = clipSimpleRing(around, 0, 0, 100, 100);
    ASSERT_TRUE(box.has_value());
    EXPECT_EQ(box->size(), 4u);
    EXPECT_EQ(ClipperLib::Area(*box), 100.0 * 100);
    // clockwise in, counter-clockwise out
    const Path clockwise(around.rbegin(), around.rend());
    EXPECT_EQ(ClipperLib::Area(*clipSimpleRing(clockwise, 0, 0, 100, 100)), 100.0 * 100);
}
