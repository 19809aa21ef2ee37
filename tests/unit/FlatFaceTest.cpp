// Faces in a plane (FlatFace.hpp): found from their control points, and triangulated by their
// points' coordinates in the plane, whatever their parameter does there.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeFix_Face.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <gp_Circ.hxx>
#include <vector>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/FlatFace.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// A bicubic Bezier patch over a trapezoid of the plane z = lift * x y / 100, 10 long, 1 wide at
// x = 0 and 10 wide at x = 10, its control points crowded towards x = 0 (the parameter runs
// unevenly: a planar face exported as a B-spline) and its corner (3, 3) raised by `bump`.
BSplineSurface unevenPatch(double lift = 0, double bump = 0) {
    const KnotVector knots(3, {0, 0, 0, 0, 1, 1, 1, 1});
    std::vector<HomogeneousPoint3> poles;
    const double xs[] = {0, 0.2, 1, 10};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            // the rows converge towards x = 0 as well: a twist in the plane
            const double x = xs[i], y = 10.0 * j / 3 * (0.1 + 0.09 * x);
            double z = lift * x * y / 100;
            if (i == 3 && j == 3) z += bump;
            poles.push_back(HomogeneousPoint3(x, y, z, 1));
        }
    return BSplineSurface(knots, knots, 4, 4, poles);
}

TEST(FlatFace, APlaneIsFoundFromItsControlPointsAndFollowsTheSurfacesNormal) {
    const auto plane = facePlane(unevenPatch(), 1e-9);
    ASSERT_TRUE(plane);
    // du x dv of the patch points up z
    EXPECT_GT(plane->e1.cross(plane->e2).z(), 1 - 1e-12);
    EXPECT_NEAR(plane->e1.dot(plane->e2), 0, 1e-12);
    // a corner raised by 1e-3 is flat within 1e-2, not within 1e-4
    EXPECT_TRUE(facePlane(unevenPatch(0, 1e-3), 1e-2));
    EXPECT_FALSE(facePlane(unevenPatch(0, 1e-3), 1e-4));
    // a saddle is not flat
    EXPECT_FALSE(facePlane(unevenPatch(1), 1e-2));
    // nor a patch with a weight that is not positive (no hull to bound it)
    BSplineSurface weightless = unevenPatch();
    weightless.pole(1, 2) = HomogeneousPoint3::Zero();
    EXPECT_FALSE(facePlane(weightless, 1e-2));
}

TEST(FlatFace, RingsAreTriangulatedInThePlaneOrRefused) {
    FacePlane plane;  // z = 0, e1 x e2 = +z
    const std::vector<Point3> square{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    const std::vector<Point3> hole{{1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}};
    const auto triangles = triangulateInPlane(plane, {hole, square});  // the outer ring found
    ASSERT_TRUE(triangles);
    EXPECT_EQ(triangles->size(), 8u);
    const std::vector<Point3> all{hole[0],   hole[1],   hole[2],   hole[3],
                                  square[0], square[1], square[2], square[3]};
    double area = 0;
    for (const auto& t : *triangles) {
        const Vector3 normal = (all[t[1]] - all[t[0]]).cross(all[t[2]] - all[t[0]]);
        EXPECT_GT(normal.z(), 0);  // counter-clockwise about e1 x e2
        area += 0.5 * normal.z();
    }
    EXPECT_NEAR(area, 12, 1e-12);
    // a ring crossing itself (a bow tie) is no polygon, nor one with a point not a number
    EXPECT_FALSE(triangulateInPlane(plane, {{{0, 0, 0}, {4, 4, 0}, {4, 0, 0}, {0, 4, 0}}}));
    EXPECT_FALSE(
        triangulateInPlane(plane, {{{0, 0, 0}, {4, 0, 0}, {std::nan(""), 4, 0}, {0, 4, 0}}}));
}

// The uneven patch trimmed to a disk: the kd-tree's bounds of the cells the circle crosses,
// taken at equal parameters for corners anywhere in the cell, split them for the twist the
// parameter has in the plane (71 triangles at relative 1e-3 and 662 at 1e-4, with points inside
// the disk; OpenCASCADE's shell1.brep: 1,724 triangles at 1e-3 where BRepMesh makes 951, its
// planar bicubic faces 88 or 104 each). Triangulated in its plane it takes only its circle's
// points (33 and 107 triangles): as many triangles as points less two, within the tolerance.
TEST(FlatFace, APlanarPatchWithAnUnevenParameterHasNoInnerPoints) {
    const BSplineSurface patch = unevenPatch();
    TColgp_Array2OfPnt poles(1, 4, 1, 4);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const auto& p = patch.pole(i, j);
            poles(i + 1, j + 1) = gp_Pnt(p.x(), p.y(), p.z());
        }
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0, knots(2) = 1;
    TColStd_Array1OfInteger multiplicities(1, 2);
    multiplicities(1) = multiplicities(2) = 4;
    const Handle(Geom_BSplineSurface) surface =
        new Geom_BSplineSurface(poles, knots, knots, multiplicities, multiplicities, 3, 3);
    // trimmed to a disk of radius 1.5 about (6, 3) in it: cells the circle crosses are bounded
    // for corners anywhere in them, with the twist in full
    const TopoDS_Wire circle = BRepBuilderAPI_MakeWire(
        BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(6, 3, 0), gp_Dir(0, 0, 1)), 1.5)).Edge());
    ShapeFix_Face fix(
        BRepBuilderAPI_MakeFace(surface, TopoDS::Wire(circle.Reversed()), Standard_True).Face());
    fix.Perform();
    const TopoDS_Face face = fix.Face();
    const Model model = occ::importModel(face);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const auto result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty()) << result.failures.front().reason;
        EXPECT_EQ(result.mesh.triangles.size() + 2, result.mesh.positions.size())
            << "relative " << relative;
        const occ::VerificationReport report = occ::verifyMesh(face, result.mesh, result.tolerance);
        EXPECT_TRUE(report.pass) << "relative " << relative << ": dev " << report.maxDev
                                 << " cover " << report.maxCover;
    }
}

}  // namespace
}  // namespace nurbslod
