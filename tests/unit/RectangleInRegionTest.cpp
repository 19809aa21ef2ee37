#include <gtest/gtest.h>

#include <cmath>
#include <polyclipping/clipper.hpp>
#include <random>

#include "tessellate/RectangleInRegion.hpp"

using namespace nurbslod;
using ClipperLib::cInt;
using ClipperLib::Path;
using ClipperLib::Paths;

namespace {

// What clipping says: the area of the region inside the closed rectangle.
double clippedArea(const Paths& region, cInt x0, cInt y0, cInt x1, cInt y1) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(region, ClipperLib::ptSubject, true);
    clipper.AddPath({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, ClipperLib::ptClip, true);
    Paths out;
    clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    double area = 0;
    for (const Path& p : out) area += ClipperLib::Area(p);
    return std::abs(area);
}

// A square 0..100 with a square hole 40..60 (clockwise, as Clipper's union gives holes).
Paths squareWithHole() {
    return {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{40, 40}, {40, 60}, {60, 60}, {60, 40}}};
}

}  // namespace

TEST(RectangleInRegion, InsideOutsideAndInTheHole) {
    const Paths region = squareWithHole();
    EXPECT_EQ(rectangleInRegion(region, 10, 10, 30, 30), RectangleInRegion::Inside);
    EXPECT_EQ(rectangleInRegion(region, 62, 10, 98, 98), RectangleInRegion::Inside);
    EXPECT_EQ(rectangleInRegion(region, 45, 45, 55, 55), RectangleInRegion::Outside);
    EXPECT_EQ(rectangleInRegion(region, 101, 10, 120, 30), RectangleInRegion::Outside);
    EXPECT_EQ(rectangleInRegion(region, -50, -50, -10, 200), RectangleInRegion::Outside);
    EXPECT_EQ(rectangleInRegion({}, 0, 0, 10, 10), RectangleInRegion::Outside);
}

TEST(RectangleInRegion, TouchingOrCrossingIsNear) {
    const Paths region = squareWithHole();
    EXPECT_EQ(rectangleInRegion(region, 100, 10, 120, 30), RectangleInRegion::Near);  // a side
    EXPECT_EQ(rectangleInRegion(region, 30, 30, 40, 40), RectangleInRegion::Near);    // a corner
    EXPECT_EQ(rectangleInRegion(region, 50, 50, 70, 55), RectangleInRegion::Near);
    EXPECT_EQ(rectangleInRegion(region, -10, -10, 110, 110), RectangleInRegion::Near);
}

TEST(RectangleInRegion, TheRayThroughAVertexCountsItOnce) {
    // a diamond whose left and right vertices lie on the centre line of the rectangle
    const Paths diamond{{{50, 0}, {100, 50}, {50, 100}, {0, 50}}};
    EXPECT_EQ(rectangleInRegion(diamond, 45, 45, 55, 55), RectangleInRegion::Inside);
    EXPECT_EQ(rectangleInRegion(diamond, -30, 40, -10, 60), RectangleInRegion::Outside);
    // the same diamond the other way round (non-zero fill: orientation does not matter)
    const Paths reversed{{{0, 50}, {50, 100}, {100, 50}, {50, 0}}};
    EXPECT_EQ(rectangleInRegion(reversed, 45, 45, 55, 55), RectangleInRegion::Inside);
}

TEST(RectangleInRegion, AgreesWithClippingOnRandomPolygons) {
    std::mt19937 random(7);
    std::uniform_int_distribution<cInt> coordinate(0, 1 << 20);
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 300; ++trial) {
        // a star-shaped loop around a random centre, and a random loop that crosses itself
        Paths region(2);
        const double cx = double(coordinate(random)), cy = double(coordinate(random));
        for (int k = 0; k < 24; ++k) {
            const double angle = 2 * M_PI * k / 24;
            const double radius = 1000 + double(coordinate(random) % 300000);
            region[0].push_back(
                {cInt(cx + radius * std::cos(angle)), cInt(cy + radius * std::sin(angle))});
        }
        for (int k = 0; k < 6; ++k) region[1].push_back({coordinate(random), coordinate(random)});
        for (int query = 0; query < 50; ++query) {
            const cInt x0 = coordinate(random), y0 = coordinate(random);
            const cInt size = 1 + coordinate(random) % 20000;
            const cInt x1 = x0 + size, y1 = y0 + 1 + coordinate(random) % 20000;
            const double rectangleArea = double(x1 - x0) * double(y1 - y0);
            switch (rectangleInRegion(region, x0, y0, x1, y1)) {
                case RectangleInRegion::Inside:
                    ++inside;
                    EXPECT_DOUBLE_EQ(clippedArea(region, x0, y0, x1, y1), rectangleArea);
                    break;
                case RectangleInRegion::Outside:
                    ++outside;
                    EXPECT_EQ(clippedArea(region, x0, y0, x1, y1), 0.0);
                    break;
                case RectangleInRegion::Near:
                    break;
            }
        }
    }
    // the random cases reach both answers, so the comparison is not empty
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 100);
}
