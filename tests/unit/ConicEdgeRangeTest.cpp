// Edges on circles whose range does not start in the circle's first period ([-pi, pi]: the
// tube circles of BRepPrimAPI's partial tori), and a shape whose bounding box OpenCASCADE
// cannot take: every face is meshed within the tolerance or listed with its reason.

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeTorus.hxx>
#include <GC_MakeCircle.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_Circle.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_Circle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <cmath>

#include "VerifiedLargestFace.hpp"
#include "occ/ClampedBSpline.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

TEST(ConicEdgeRange, CircleConvertedOverMinusPiToPiKeepsTheEdgeParameter) {
    const Handle(Geom2d_Circle) circle =
        new Geom2d_Circle(gp_Ax2d(gp_Pnt2d(10, 0), gp_Dir2d(1, 0)), 3);
    const Handle(Geom2d_BSplineCurve) converted = Geom2dConvert::CurveToBSplineCurve(
        new Geom2d_TrimmedCurve(circle, -M_PI, M_PI), Convert_TgtThetaOver2);
    // OpenCASCADE moves the range into the first period: the reason for onEdgeRange
    ASSERT_NEAR(converted->FirstParameter(), M_PI, 1e-12);
    const Handle(Geom2d_BSplineCurve) moved = occ::onEdgeRange(converted, -M_PI, M_PI);
    ASSERT_FALSE(moved.IsNull());
    EXPECT_NEAR(moved->FirstParameter(), -M_PI, 1e-12);
    EXPECT_NEAR(moved->LastParameter(), M_PI, 1e-12);
    for (int k = 0; k <= 16; ++k) {
        const double s = -M_PI + 2 * M_PI * k / 16;
        EXPECT_LT(moved->Value(s).Distance(converted->Value(s + 2 * M_PI)), 1e-12) << s;
    }
    // a range already right is the same curve; one that differs by other than whole periods
    // is refused
    EXPECT_EQ(occ::onEdgeRange(moved, -M_PI, M_PI), moved);
    EXPECT_TRUE(occ::onEdgeRange(moved, -1, 2 * M_PI - 1).IsNull());
}

TEST(ConicEdgeRange, SpaceCircleConvertedOverMinusPiToPi) {
    const Handle(Geom_Circle) circle = GC_MakeCircle(gp_Ax2(), 3).Value();
    const Handle(Geom_BSplineCurve) converted = GeomConvert::CurveToBSplineCurve(
        new Geom_TrimmedCurve(circle, -M_PI, M_PI), Convert_TgtThetaOver2);
    const Handle(Geom_BSplineCurve) moved = occ::onEdgeRange(converted, -M_PI, M_PI);
    ASSERT_FALSE(moved.IsNull());
    EXPECT_NEAR(moved->FirstParameter(), -M_PI, 1e-12);
    EXPECT_NEAR(moved->LastParameter(), M_PI, 1e-12);
    // the ends are the circle's at -pi and pi (the conversion meets the angle at its knots)
    EXPECT_LT(moved->Value(-M_PI).Distance(circle->Value(-M_PI)), 1e-12);
    EXPECT_LT(moved->Value(M_PI).Distance(circle->Value(M_PI)), 1e-12);
    for (int k = 0; k <= 16; ++k) {
        const double s = -M_PI + 2 * M_PI * k / 16;
        EXPECT_LT(moved->Value(s).Distance(converted->Value(s + 2 * M_PI)), 1e-12) << s;
        EXPECT_NEAR(moved->Value(s).Distance(gp_Pnt(0, 0, 0)), 3, 1e-12) << s;
    }
}

// An elbow: the whole tube swept a quarter turn. Its two end discs are bounded by the tube's
// circles over [-pi, pi]; they were silently left empty.
TEST(ConicEdgeRange, QuarterTorusElbowHasItsEndDiscs) {
    const TopoDS_Shape elbow =
        BRepPrimAPI_MakeTorus(gp_Ax2(), 10, 3, -M_PI, M_PI, M_PI / 2).Shape();
    test::verifiedLargestFaceTriangles(elbow, 0.02, 3);
}

// The tube's section cut to three quarters: planes bounded by the section's arc from -pi/2.
TEST(ConicEdgeRange, TorusWithThreeQuarterSection) {
    const TopoDS_Shape torus =
        BRepPrimAPI_MakeTorus(gp_Ax2(), 10, 3, -M_PI / 2, M_PI, 200 * M_PI / 180).Shape();
    test::verifiedLargestFaceTriangles(torus, 0.03, 5);
}

// tests/data/torus_without_end_faces.brep: FreeCAD's Part.makeTorus(10, 3, ..., 0, 270, 200),
// an invalid shape whose two end faces have edges without a range; OpenCASCADE throws on its
// bounding box. The three other faces are meshed, the two are listed.
TEST(ConicEdgeRange, BrokenFacesFailAloneWhereTheShapeHasNoBox) {
    const TopoDS_Shape shape =
        occ::readShape(NURBSLOD_TEST_DATA_DIR "/torus_without_end_faces.brep");
    const Model model = occ::importModel(shape);
    ASSERT_EQ(model.faces.size(), 5u);
    EXPECT_NEAR(model.boundingBoxDiagonal, 34.4, 0.1);
    TessellationOptions options;
    options.tolerance = 1e-3 * model.boundingBoxDiagonal;
    const TessellationResult result = tessellateModel(model, options);
    ASSERT_EQ(result.failures.size(), 2u);
    EXPECT_EQ(result.failures[0].face, 4);
    EXPECT_EQ(result.failures[1].face, 5);
    for (const auto& failure : result.failures) EXPECT_FALSE(failure.reason.empty());
    std::vector<int> perFace(6, 0);
    for (const int face : result.mesh.triangleFaces) ++perFace.at(face);
    EXPECT_GT(perFace[1], 0);
    EXPECT_GT(perFace[2], 0);
    EXPECT_GT(perFace[3], 0);
}

}  // namespace
}  // namespace nurbslod
