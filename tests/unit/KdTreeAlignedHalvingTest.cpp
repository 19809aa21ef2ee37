// An edge halved on a face's kd-tree lines (KdTreeAlignedHalving): its points fall where that
// face's kd-tree cuts, so two curves of one face that are parameterised unlike each other (a
// cylinder's circle as an arc, and as the B-spline another system wrote it) get points at the
// same u, and the cells cut neither between its points (bug3883_xr2-ct-214_bolt.stp at relative
// 1e-3: 548 triangles, 380 with the points on the lines).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "tessellate/KdTreeAlignedHalving.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "trim/EdgeDiscretizer.hpp"
#include "trim/TrimmedSurface.hpp"

namespace nurbslod {
namespace {

TEST(KdTreeGrid, GivesTheCoarsestLineInTheMiddleHalf) {
    const KdTreeGrid grid(0, 8, {});
    EXPECT_EQ(grid.lineWithin(0, 8).value(), 4);
    EXPECT_EQ(grid.lineWithin(8, 0).value(), 4);  // either order
    EXPECT_EQ(grid.lineWithin(0, 4).value(), 2);
    // middle half [1.625, 2.875]: 2 is a line of the second halving, 2.5 only of the fourth
    EXPECT_EQ(grid.lineWithin(1, 3.5).value(), 2);
    // middle half [0.125, 0.175]: the sixth halving's 0.125
    EXPECT_EQ(grid.lineWithin(0.1, 0.2).value(), 0.125);
    EXPECT_FALSE(grid.lineWithin(-5, -4).has_value());       // outside the frame
    EXPECT_FALSE(grid.lineWithin(1, 1 + 1e-9).has_value());  // below a frame step
}

TEST(KdTreeGrid, CutsAtSpanBordersFirst) {
    const KdTreeGrid grid(0, 8, {0, 3, 8});
    EXPECT_EQ(grid.lineWithin(0, 8).value(), 3);
    // within the span [3, 8] the halvings start from its borders: 5.5, then 4.25 and 6.75
    EXPECT_EQ(grid.lineWithin(3, 8).value(), 5.5);
    EXPECT_EQ(grid.lineWithin(3, 5.5).value(), 4.25);
    // [4, 7]'s middle half [4.75, 6.25] holds 5.5 (not the plain middle 5.5 by chance: 3.5 off)
    EXPECT_EQ(grid.lineWithin(3.6, 7.4).value(), 5.5);
}

// A straight line in (u, v), u from 0 to 1, run unevenly: u(s) is rational in s
BSplineCurve2d unevenLine(double v, double weight) {
    return BSplineCurve2d(
        KnotVector(2, {0, 0, 0, 1, 1, 1}),
        {HomogeneousPoint2(0, v, 1), HomogeneousPoint2(0.5 * weight, v * weight, weight),
         HomogeneousPoint2(1, v, 1)});
}

BSplineCurve2d evenLine(double v) {
    return BSplineCurve2d(KnotVector(1, {0, 0, 1, 1}),
                          {HomogeneousPoint2(0, v, 1), HomogeneousPoint2(1, v, 1)});
}

TEST(CurveOnSurface, FindsWhereACoordinateTakesAValue) {
    const BSplineSurface plane(KnotVector(1, {0, 0, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 2, 2,
                               {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 1, 0, 1),
                                HomogeneousPoint3(1, 0, 0, 1), HomogeneousPoint3(1, 1, 0, 1)});
    const BSplineCurve2d line = unevenLine(0.5, 0.2);
    const CurveOnSurface curve(plane, line, 0, 1);
    for (double value : {0.01, 0.3, 0.5, 0.77, 0.999}) {
        const double s = curve.parameterWhere(0, value, 0, 1);
        EXPECT_NEAR(curve.uv(s).x(), value, 1e-14);
    }
    // within a piece, and the nearer end where the piece does not reach the value
    const double s = curve.parameterWhere(0, 0.3, 0.1, 0.9);
    EXPECT_NEAR(curve.uv(s).x(), 0.3, 1e-14);
    EXPECT_EQ(curve.parameterWhere(0, 0.999, 0.1, 0.2), 0.2);
}

// A quarter cylinder of radius 1 (rational quadratic in u, straight in v): its bottom circle
// runs evenly in u, its top circle (the same circle, shifted up) unevenly.
class QuarterCylinder : public ::testing::Test {
protected:
    static constexpr double w = 0.70710678118654752;
    const BSplineSurface surface{KnotVector(2, {0, 0, 0, 1, 1, 1}),
                                 KnotVector(1, {0, 0, 1, 1}),
                                 3,
                                 2,
                                 {HomogeneousPoint3(1, 0, 0, 1), HomogeneousPoint3(1, 0, 1, 1),
                                  HomogeneousPoint3(w, w, 0, w), HomogeneousPoint3(w, w, w, w),
                                  HomogeneousPoint3(0, 1, 0, 1), HomogeneousPoint3(0, 1, 1, 1)}};
    const BSplineCurve2d bottom = evenLine(0);
    const BSplineCurve2d top = unevenLine(1, 0.3);

    // the face over the whole quarter, with `bottomSide` along v = 0 and the top circle
    TrimmedSurface faceWithBottom(BSplineCurve2d bottomSide) const {
        TrimmedSurface face;
        face.surface = surface;
        TrimLoop loop;
        auto add = [&](BSplineCurve2d pcurve) {
            TrimCurve curve;
            curve.pcurve = std::move(pcurve);
            loop.curves.push_back(std::move(curve));
        };
        add(std::move(bottomSide));
        add(BSplineCurve2d(KnotVector(1, {0, 0, 1, 1}),
                           {HomogeneousPoint2(1, 0, 1), HomogeneousPoint2(1, 1, 1)}));
        add(top);
        add(BSplineCurve2d(KnotVector(1, {0, 0, 1, 1}),
                           {HomogeneousPoint2(0, 1, 1), HomogeneousPoint2(0, 0, 1)}));
        face.loops.push_back(loop);
        return face;
    }

    // the frame steps of an edge's points in u, discretised alone with or without the grids
    std::set<long long> stepsOf(const BSplineCurve2d& pcurve,
                                const std::optional<std::array<KdTreeGrid, 2>>& grids,
                                bool onLines = true) {
        const std::vector<CurveOnSurface> curve{CurveOnSurface(surface, pcurve, 0, 1)};
        const std::optional<FaceKdTreeLines> lines =
            grids ? std::optional(FaceKdTreeLines{{(*grids)[0], (*grids)[1]}, {1, 1}, {}})
                  : std::nullopt;
        const std::vector<double> params =
            onLines
                ? discretizeEdgeOnKdTreeLines(curve, 0, lines ? &*lines : nullptr, 1e-4, 0).value()
                : discretizeEdge(curve, 1e-4, 0);
        std::set<long long> steps;
        for (double s : params)
            steps.insert(std::llround(curve[0].uv(s).x() * double(kKdTreeFrameScale)));
        return steps;
    }
};

TEST_F(QuarterCylinder, CirclesHalvedOnTheKdTreeLinesShareTheirPoints) {
    const std::array<KdTreeGrid, 2> grids{KdTreeGrid(0, 1, {0, 1}), KdTreeGrid(0, 1, {0, 1})};
    const auto bottomSteps = stepsOf(bottom, grids), topSteps = stepsOf(top, grids);
    EXPECT_GT(bottomSteps.size(), 16u);
    EXPECT_EQ(bottomSteps, topSteps);
    // so does the kd-tree over the curves' own range, where the face's frame is not known
    EXPECT_EQ(stepsOf(bottom, std::nullopt), stepsOf(top, std::nullopt));
    // halved in their own parameter, the two circles' points differ
    EXPECT_NE(stepsOf(bottom, {}, false), stepsOf(top, {}, false));
}

// Span borders cut first, then each span's halvings, as the kd-tree cuts: the border is one of
// the points, and the two circles, parameterised unlike each other, share every point of the
// one with fewer; the frame's halvings, which know no border, do not put a point on it.
TEST_F(QuarterCylinder, UnevenSpansPutTheBorderAmongThePoints) {
    const std::array<KdTreeGrid, 2> grids{KdTreeGrid(0, 1, {0, 0.37, 1}), KdTreeGrid(0, 1, {})};
    const auto border = std::llround(0.37 * double(kKdTreeFrameScale));
    const auto bottomSteps = stepsOf(bottom, grids);
    EXPECT_GT(bottomSteps.size(), 16u);
    EXPECT_EQ(bottomSteps.count(border), 1u);
    const auto topSteps = stepsOf(top, grids);
    std::vector<long long> shared;
    std::set_intersection(bottomSteps.begin(), bottomSteps.end(), topSteps.begin(), topSteps.end(),
                          std::back_inserter(shared));
    EXPECT_EQ(shared.size(), bottomSteps.size()) << topSteps.size();
    EXPECT_EQ(stepsOf(bottom, std::nullopt).count(border), 0u);
}

TEST_F(QuarterCylinder, GridsAreKnownWhereEveryCurveStaysInTheEndsBox) {
    TrimmedSurface face = faceWithBottom(bottom);
    const auto grids = kdTreeLinesBeforeDiscretisation(face).both();
    ASSERT_TRUE(grids.has_value());
    EXPECT_EQ((*grids)[0].lineWithin(0, 1).value(), 0.5);
    // a left side that bulges past u = 0: the frame waits for the boundary's points
    face.loops[0].curves[3].pcurve = BSplineCurve2d(
        KnotVector(2, {0, 0, 0, 1, 1, 1}),
        {HomogeneousPoint2(0, 1, 1), HomogeneousPoint2(-0.2, 0.5, 1), HomogeneousPoint2(0, 0, 1)});
    EXPECT_FALSE(kdTreeLinesBeforeDiscretisation(face).both().has_value());
}

// A bottom side that bulges a hair below v = 0 (a sloppy band's side off its iso-line): a
// quadratic in (u, v), running one way along u, unevenly.
BSplineCurve2d bulgingLine(double depth) {
    return BSplineCurve2d(KnotVector(2, {0, 0, 0, 1, 1, 1}),
                          {HomogeneousPoint2(0, 0, 1), HomogeneousPoint2(0.3, -depth, 1),
                           HomogeneousPoint2(1, 0, 1)});
}

TEST_F(QuarterCylinder, ASideAHairOffItsIsoLineIsHalvedOnTheColumnsLines) {
    const TrimmedSurface face = faceWithBottom(bulgingLine(0.004));
    // the columns are known, the rows wait for the boundary's points
    const FaceKdTreeLines lines = kdTreeLinesBeforeDiscretisation(face);
    ASSERT_TRUE(lines.axes[0].has_value());
    EXPECT_FALSE(lines.axes[1].has_value());
    EXPECT_FALSE(lines.both().has_value());
    EXPECT_EQ(lines.extent[1], 1);

    auto steps = [&](const BSplineCurve2d& pcurve, bool onLines) {
        const std::vector<CurveOnSurface> curve{CurveOnSurface(surface, pcurve, 0, 1)};
        const std::vector<double> params =
            onLines ? discretizeEdgeOnKdTreeLines(curve, 0, &lines, 1e-4, 0).value()
                    : discretizeEdge(curve, 1e-4, 0);
        std::set<long long> out;
        for (double s : params)
            out.insert(std::llround(curve[0].uv(s).x() * double(kKdTreeFrameScale)));
        return out;
    };
    // both long sides get their points on the same columns: the kd-tree's columns through the
    // one side's points meet the other's points too
    const auto bottomSteps = steps(bulgingLine(0.004), true), topSteps = steps(top, true);
    EXPECT_GT(bottomSteps.size(), 16u);
    EXPECT_EQ(bottomSteps, topSteps);
    // halved in its own parameter the side's points are elsewhere
    EXPECT_NE(steps(bulgingLine(0.004), false), topSteps);

    // a curve that leaves the band, or turns back along it, is not halved on the lines; one
    // that leaves the band runs along u on a cylinder, straight in v, where that is allowed
    const BSplineCurve2d narrowLine = bulgingLine(0.004), wideLine = bulgingLine(0.3);
    const CurveOnSurface narrowCurve(surface, narrowLine, 0, 1);
    const CurveOnSurface wideCurve(surface, wideLine, 0, 1);
    EXPECT_EQ(axisAlong(narrowCurve, {1, 1}, BentCurves::narrowBand), 0);
    EXPECT_EQ(axisAlong(wideCurve, {1, 1}, BentCurves::narrowBand), -1);
    EXPECT_EQ(axisAlong(wideCurve, {1, 1}, BentCurves::onRuledSurface), 0);
    const BSplineCurve2d turning(
        KnotVector(2, {0, 0, 0, 1, 1, 1}),
        {HomogeneousPoint2(0, 0, 1), HomogeneousPoint2(1.2, -0.01, 1), HomogeneousPoint2(1, 0, 1)});
    EXPECT_EQ(axisAlong(CurveOnSurface(surface, turning, 0, 1), {1, 1}, BentCurves::onRuledSurface),
              -1);
    // the same wide curve on a plane (straight both ways): no axis is clear
    const BSplineSurface plane(KnotVector(1, {0, 0, 1, 1}), KnotVector(1, {0, 0, 1, 1}), 2, 2,
                               {HomogeneousPoint3(0, 0, 0, 1), HomogeneousPoint3(0, 1, 0, 1),
                                HomogeneousPoint3(1, 0, 0, 1), HomogeneousPoint3(1, 1, 0, 1)});
    EXPECT_EQ(axisAlong(CurveOnSurface(plane, wideLine, 0, 1), {1, 1}, BentCurves::onRuledSurface),
              -1);
    const std::vector<CurveOnSurface> wide{wideCurve};
    // allowed, its points are on the columns' lines (the 4,096 coarsest); halved in its own
    // parameter they are not
    const auto wideParams =
        discretizeEdgeOnKdTreeLines(wide, 0, &lines, 1e-4, 0, nullptr, BentCurves::onRuledSurface);
    ASSERT_TRUE(wideParams.has_value());
    auto offLines = [&](const std::vector<double>& params) {
        int off = 0;
        for (double s : params)
            off += std::llround(wideCurve.uv(s).x() * double(kKdTreeFrameScale)) % (1 << 18) != 0;
        return off;
    };
    EXPECT_GT(wideParams->size(), 16u);
    EXPECT_EQ(offLines(*wideParams), 0);
    EXPECT_GT(offLines(discretizeEdge(wide, 1e-4, 0)), 0);
    EXPECT_FALSE(discretizeEdgeOnKdTreeLines(wide, 0, &lines, 1e-4, 0).has_value());
}

}  // namespace
}  // namespace nurbslod
