// The points of a boundary's runs along an axis, through which FaceTessellator splits a cell
// across such a run (an edge along an iso-line whose points another face placed).

#include <gtest/gtest.h>

#include "tessellate/IsoRunLines.hpp"

namespace nurbslod {
namespace {

using ClipperLib::IntPoint;
using ClipperLib::Paths;

// A square whose top side carries three points between its corners, as an edge discretised by
// the face beyond it.
Paths squareWithPointsOnTop() {
    return {{IntPoint(0, 0), IntPoint(100, 0), IntPoint(100, 100), IntPoint(80, 100),
             IntPoint(55, 100), IntPoint(30, 100), IntPoint(0, 100)}};
}

TEST(IsoRunLines, SplitGoesThroughTheRunPointNearestTheMiddle) {
    const IsoRunLines runs(squareWithPointsOnTop());
    EXPECT_EQ(runs.nearest(0, 0, 100, 50), 55);
    EXPECT_EQ(runs.nearest(0, 40, 100, 70), 80);  // 80 is nearer than 55
    EXPECT_EQ(runs.nearest(0, 60, 100, 80), 80);  // on a point already
}

TEST(IsoRunLines, OnlyPointsWithinAQuarterOfTheCellCount) {
    const IsoRunLines runs(squareWithPointsOnTop());
    EXPECT_EQ(runs.nearest(0, 0, 40, 20), 30);  // 10 away, the window 11
    EXPECT_EQ(runs.nearest(0, 0, 36, 18), 18);  // 12 away, the window 10
    EXPECT_EQ(runs.nearest(0, 0, 20, 10), 10);  // none inside the cell
}

TEST(IsoRunLines, TheCellsOwnSidesAreNoSplit) {
    const IsoRunLines runs(squareWithPointsOnTop());
    // 55 and 80 are the cell's sides: a split there would make a cell without width
    EXPECT_EQ(runs.nearest(0, 55, 80, 67), 67);
}

TEST(IsoRunLines, EachAxisTakesTheRunsAlongIt) {
    const IsoRunLines runs(squareWithPointsOnTop());
    // the vertical sides have no point between their ends: a split across them stays
    EXPECT_EQ(runs.nearest(1, 0, 100, 50), 50);
    // a slanted segment is no run: its ends are not lines
    const IsoRunLines triangle(Paths{{IntPoint(0, 0), IntPoint(100, 0), IntPoint(45, 60)}});
    EXPECT_EQ(triangle.nearest(0, 0, 100, 50), 50);
    EXPECT_EQ(triangle.nearest(1, 0, 100, 50), 50);
}

}  // namespace
}  // namespace nurbslod
