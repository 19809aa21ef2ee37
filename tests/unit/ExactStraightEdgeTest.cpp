// An exact edge that is straight in (u, v) on each of its faces does not take the trimming share
// of a face that has other, bent curves: that face's cells bound the triangles along it, as the
// curve use's do (ModelTessellator's edgeBudget).

#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <cmath>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ErrorBudget.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

constexpr double kRadius = 5;
constexpr double kJointHeight = 4;

// A cone from radius 8 at z = 0 to radius 5 at z = 4, a cylinder of radius 5 on it, cut at the
// top by the plane z = 10 + 0.3 x. The circle where cone and cylinder meet is an iso-line of
// both (exact: the revolution makes it one edge), and the cylinder's other boundary, the
// ellipse of the cut, bends in its (u, v): the cylinder has a trimming share to keep, the
// circle need not keep it.
TopoDS_Shape coneCylinderCutSlanted() {
    BRepBuilderAPI_MakePolygon profile;
    for (const gp_Pnt& p : {gp_Pnt(0, 0, 0), gp_Pnt(8, 0, 0), gp_Pnt(kRadius, 0, kJointHeight),
                            gp_Pnt(kRadius, 0, 14), gp_Pnt(0, 0, 14)})
        profile.Add(p);
    profile.Close();
    const TopoDS_Face section = BRepBuilderAPI_MakeFace(profile.Wire(), true).Face();
    const TopoDS_Shape solid = BRepPrimAPI_MakeRevol(section, gp_Ax1(gp::Origin(), gp::DZ()));
    // the half-space above the plane: a large box whose base lies in it
    const gp_Dir normal(-0.3, 0, 1), along(1, 0, 0.3);
    const gp_Pnt base = gp_Pnt(0, 0, 10)
                            .Translated(-50 * gp_Vec(along))
                            .Translated(-50 * gp_Vec(normal.Crossed(along)));
    const TopoDS_Shape above = BRepPrimAPI_MakeBox(gp_Ax2(base, normal, along), 100, 100, 100);
    BRepAlgoAPI_Cut cut(solid, above);
    EXPECT_TRUE(cut.IsDone());
    return cut.Shape();
}

TEST(ExactStraightEdge, TakesTheChordsTheCellsNeedNotTheTrimmingShare) {
    const TopoDS_Shape shape = coneCylinderCutSlanted();
    const Model model = occ::importModel(shape);
    for (const double relative : {1e-3, 1e-4}) {
        const double tolerance = relative * model.boundingBoxDiagonal;
        TessellationOptions options;
        options.tolerance = tolerance;
        const auto result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty());
        const auto report = occ::verifyMesh(shape, result.mesh, tolerance);
        EXPECT_TRUE(report.pass) << relative << ": max dev " << report.maxDev;
        EXPECT_EQ(report.openEdges, 0u) << relative;
        // the points on the joint circle
        int onCircle = 0;
        for (const auto& p : result.mesh.positions)
            onCircle += std::abs(p.z() - kJointHeight) < 1e-9 &&
                        std::abs(std::hypot(p.x(), p.y()) - kRadius) < 1e-6;
        // Chords within the cylinder's trimming share (the fixed split's chord part) would
        // need this many points around the circle; the cells need fewer.
        const ErrorBudget fixed = ErrorBudget::of(tolerance, ErrorMode::Guaranteed);
        const double chordAngle = 2 * std::acos(1 - fixed.lineApproximation / kRadius);
        const int withTrimmingShare = static_cast<int>(std::ceil(2 * M_PI / chordAngle));
        EXPECT_GT(onCircle, 0) << relative;
        EXPECT_LT(onCircle, withTrimmingShare) << relative;
    }
}

}  // namespace
}  // namespace nurbslod
