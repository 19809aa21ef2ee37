// A cone frustum cut at both ends by planes tilted 2e-5 rad: each cut runs a hair inside one of
// the cone's circles in (u, v), so every kd-tree column (from the bottom circle to the top one)
// has its boundary near both of its v sides. (Much farther, 2e-4 rad, and the derivative term of
// the bound is above the tolerance: such columns are split as before.) A band split takes one side
// at a time and leaves thin trimmed cells along each; the bound for corners near the sides
// (CellErrorBound::nearSides) takes the column as it is, as wide as its bulge allows. The mesh
// is within the tolerance as `nurbslod verify` measures it, both ways.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>
#include <random>

#include "VerifiedLargestFace.hpp"
#include "geometry/BezierPatch.hpp"
#include "tessellate/CellErrorBound.hpp"

namespace nurbslod {
namespace {

// The cone (radius 10.5 at z = -1, 6 at z = 8) between the planes through z = 0 and z = 7,
// each tilted by `tilt` about the y axis (the two in opposite senses): three faces.
TopoDS_Shape cutAtBothEnds(double tilt) {
    const TopoDS_Shape cone =
        BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, -1), gp::DZ()), 10.5, 6, 9).Shape();
    gp_Trsf up, down;
    up.SetRotation(gp_Ax1(gp::Origin(), gp::DY()), tilt);
    down.SetRotation(gp_Ax1(gp_Pnt(0, 0, 7), gp::DY()), -tilt);
    const TopoDS_Shape above = BRepBuilderAPI_Transform(
        BRepPrimAPI_MakeBox(gp_Pnt(-50, -50, 0), 100, 100, 100).Shape(), up);
    const TopoDS_Shape below = BRepBuilderAPI_Transform(
        BRepPrimAPI_MakeBox(gp_Pnt(-50, -50, -93), 100, 100, 100).Shape(), down);
    return BRepAlgoAPI_Common(BRepAlgoAPI_Common(cone, above).Shape(), below).Shape();
}

TEST(NearSides, BoundaryAHairInsideTwoSidesCostsNoSplit) {
    const double tolerance = 0.01;
    const std::size_t untilted = test::verifiedLargestFaceTriangles(cutAtBothEnds(0), tolerance, 3);
    const std::size_t tilted =
        test::verifiedLargestFaceTriangles(cutAtBothEnds(2e-5), tolerance, 3);
    EXPECT_GT(untilted, 100u);
    // Measured: 162 untilted (even columns); tilted 444, and 2,101 where the columns were
    // halved until their trimmed bound held.
    EXPECT_LE(double(tilted), 3.0 * double(untilted)) << tilted << " against " << untilted;
}

// The largest finite-difference derivatives of a patch over a 201 x 201 grid.
CellErrorBound::Speed measuredSpeed(const BezierPatch& patch) {
    CellErrorBound::Speed largest;
    const int steps = 200;
    const double h = 1e-6;
    for (int a = 0; a <= steps; ++a)
        for (int b = 0; b <= steps; ++b) {
            const double s = std::clamp(double(a) / steps, h, 1 - h);
            const double t = std::clamp(double(b) / steps, h, 1 - h);
            largest.s = std::max(largest.s,
                                 (patch.point(s + h, t) - patch.point(s - h, t)).norm() / (2 * h));
            largest.t = std::max(largest.t,
                                 (patch.point(s, t + h) - patch.point(s, t - h)).norm() / (2 * h));
        }
    return largest;
}

// parameterSpeed bounds the patch's derivatives: finite differences over a grid of a rational
// biquadratic-by-cubic patch with uneven weights stay under it, and it is not far above them.
TEST(NearSides, ParameterSpeedBoundsTheDerivatives) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1, 1), weight(0.4, 2.5);
    BezierPatch patch(2, 3);
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 3; ++j) {
            const double w = weight(random);
            patch.pole(i, j) =
                HomogeneousPoint3(w * (i + 0.3 * coordinate(random)),
                                  w * (j + 0.3 * coordinate(random)), w * coordinate(random), w);
        }
    const CellErrorBound::Speed speed = parameterSpeed(patch);
    const CellErrorBound::Speed measured = measuredSpeed(patch);
    EXPECT_LE(measured.s, speed.s);
    EXPECT_LE(measured.t, speed.t);
    EXPECT_GE(measured.s, speed.s / 20);
    EXPECT_GE(measured.t, speed.t / 20);
}

// Two equal poles, the first of them weighted 100: along s the patch rushes from the heavy pole
// to the last one near s = 1, at about 200 times the poles' spacing, which only the weights'
// differences in the bound account for (degree times the largest weighted step gives 2).
TEST(NearSides, ParameterSpeedCountsTheWeights) {
    BezierPatch patch(2, 1);
    for (int j = 0; j <= 1; ++j) {
        patch.pole(0, j) = HomogeneousPoint3(0, j, 0, 1);
        patch.pole(1, j) = 100 * HomogeneousPoint3(0, j, 0, 1);
        patch.pole(2, j) = HomogeneousPoint3(1, j, 0, 1);
    }
    const CellErrorBound::Speed speed = parameterSpeed(patch);
    const CellErrorBound::Speed measured = measuredSpeed(patch);
    EXPECT_GT(measured.s, 100.0);
    EXPECT_LE(measured.s, speed.s);
    EXPECT_LE(measured.t, speed.t);
}

}  // namespace
}  // namespace nurbslod
