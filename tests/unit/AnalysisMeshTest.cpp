#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <map>

#include "occ/ModelImporter.hpp"
#include "tessellate/AnalysisMesh.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// Two bicubic patches joined C1 (a double knot at u = 0) with a curvature jump: flat in u on
// the left, curved on the right, a bowl in v throughout.
Handle(Geom_BSplineSurface) twoPatchSurface() {
    const double xs[] = {-1.0, -2.0 / 3.0, -1.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
    const double zs[] = {0.0, 0.0, 0.0, 0.0, 8.0 / 3.0, 8.0};
    const double ys[] = {-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0};
    const double bowl[] = {4.0, -4.0 / 3.0, -4.0 / 3.0, 4.0};  // 4 y^2 as a cubic Bezier
    TColgp_Array2OfPnt poles(1, 6, 1, 4);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 4; ++j)
            poles(i + 1, j + 1) = gp_Pnt(20 * xs[i], 20 * ys[j], zs[i] + bowl[j]);
    TColStd_Array1OfReal knotsU(1, 3), knotsV(1, 2);
    TColStd_Array1OfInteger multsU(1, 3), multsV(1, 2);
    knotsU(1) = -1, knotsU(2) = 0, knotsU(3) = 1;
    multsU(1) = 4, multsU(2) = 2, multsU(3) = 4;
    knotsV(1) = -1, knotsV(2) = 1;
    multsV(1) = 4, multsV(2) = 4;
    return new Geom_BSplineSurface(poles, knotsU, knotsV, multsU, multsV, 3, 3);
}

TEST(AnalysisMesh, CurvatureIsExactAndOneSidedAtAJoint) {
    const Handle(Geom_BSplineSurface) surface = twoPatchSurface();
    const TopoDS_Shape face = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
    const Model model = occ::importModel(face);
    TessellationOptions options;
    options.tolerance = 1e-3 * model.boundingBoxDiagonal;
    const TessellationResult result = tessellateModel(model, options);
    ASSERT_TRUE(result.failures.empty());
    const AnalysisMesh mesh = analysisMesh(model, result.mesh);
    ASSERT_EQ(mesh.points.size(), mesh.mean.size());
    ASSERT_FALSE(mesh.triangles.empty());

    std::size_t onJoint = 0;
    std::map<std::pair<double, double>, std::vector<std::size_t>> copiesAt;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        const double u = mesh.parameters[v].x(), w = mesh.parameters[v].y();
        // edge points may sit on the boundary chord, within the mesh's tolerance
        const gp_Pnt exact = surface->Value(u, w);
        ASSERT_LE((mesh.points[v] - Vector3(exact.X(), exact.Y(), exact.Z())).norm(),
                  options.tolerance);
        // on the joint the value is the limit from the side of the vertex's triangles
        double side = 0;
        if (std::abs(u) < 1e-12) {
            ++onJoint;
            copiesAt[{mesh.points[v].y(), mesh.points[v].z()}].push_back(v);
            for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
                for (const auto corner : mesh.triangles[t])
                    if (corner == v)
                        for (const auto other : mesh.triangles[t])
                            side += mesh.parameters[other].x();
        }
        const double probe = side == 0 ? u : u + (side > 0 ? 1e-9 : -1e-9);
        GeomLProp_SLProps props(surface, probe, w, 2, 1e-12);
        ASSERT_TRUE(props.IsCurvatureDefined());
        const double scale =
            std::max({std::abs(props.MaxCurvature()), std::abs(props.MinCurvature()), 1e-3});
        // convex positive against OpenCASCADE's du x dv: the signs flip, min and max swap
        EXPECT_NEAR(mesh.mean[v], -props.MeanCurvature(), 1e-6 * scale) << u << ", " << w;
        EXPECT_NEAR(mesh.maximum[v], -props.MinCurvature(), 1e-6 * scale) << u << ", " << w;
        EXPECT_NEAR(mesh.minimum[v], -props.MaxCurvature(), 1e-6 * scale) << u << ", " << w;
        EXPECT_NEAR(mesh.gaussian[v], props.GaussianCurvature(), 1e-6 * scale * scale);
    }
    // the joint's vertices come in pairs, one per side, with the jump between them
    ASSERT_GT(onJoint, 4u);
    for (const auto& [where, copies] : copiesAt) {
        ASSERT_EQ(copies.size(), 2u) << "at y " << where.first;
        EXPECT_GT(std::abs(mesh.mean[copies[0]] - mesh.mean[copies[1]]), 1e-3);
    }
}

TEST(AnalysisMesh, RefusesAMeshThatDoesNotFitTheModel) {
    const Model model = occ::importModel(BRepBuilderAPI_MakeFace(twoPatchSurface(), 1e-7).Face());
    TessellationOptions options;
    options.tolerance = 1e-2 * model.boundingBoxDiagonal;
    TessellationResult result = tessellateModel(model, options);
    Mesh noParameters = result.mesh;
    noParameters.parameters.clear();
    EXPECT_THROW(analysisMesh(model, noParameters), std::invalid_argument);
    Mesh wrongFace = result.mesh;
    wrongFace.triangleFaces.front() = 7;
    EXPECT_THROW(analysisMesh(model, wrongFace), std::invalid_argument);
    Mesh badIndex = result.mesh;
    badIndex.triangles.front()[0] = 1u << 30;
    EXPECT_THROW(analysisMesh(model, badIndex), std::invalid_argument);
}

}  // namespace
}  // namespace nurbslod
