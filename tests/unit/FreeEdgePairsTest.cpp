#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <array>
#include <map>
#include <vector>

#include "occ/FreeEdgePairs.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// A box of six faces each built on its own (loose faces, as an IGES file without topology
// writes them), every face outward: each edge is two copies, and the two faces of a box edge
// run along it in opposite directions. `skip` leaves a face out (-1: none).
TopoDS_Compound looseBox(int skip = -1) {
    const std::array<std::array<gp_Pnt, 4>, 6> faces{{
        {gp_Pnt(0, 0, 0), gp_Pnt(0, 20, 0), gp_Pnt(10, 20, 0), gp_Pnt(10, 0, 0)},
        {gp_Pnt(0, 0, 30), gp_Pnt(10, 0, 30), gp_Pnt(10, 20, 30), gp_Pnt(0, 20, 30)},
        {gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 0, 30), gp_Pnt(0, 0, 30)},
        {gp_Pnt(0, 20, 0), gp_Pnt(0, 20, 30), gp_Pnt(10, 20, 30), gp_Pnt(10, 20, 0)},
        {gp_Pnt(0, 0, 0), gp_Pnt(0, 0, 30), gp_Pnt(0, 20, 30), gp_Pnt(0, 20, 0)},
        {gp_Pnt(10, 0, 0), gp_Pnt(10, 20, 0), gp_Pnt(10, 20, 30), gp_Pnt(10, 0, 30)},
    }};
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    for (int f = 0; f < 6; ++f) {
        if (f == skip) continue;
        const auto& p = faces[f];
        builder.Add(compound,
                    BRepBuilderAPI_MakeFace(
                        BRepBuilderAPI_MakePolygon(p[0], p[1], p[2], p[3], Standard_True).Wire(),
                        Standard_True)
                        .Face());
    }
    return compound;
}

TEST(FreeEdgePairs, LooseFacesOfABoxPairUpWhole) {
    const TopoDS_Compound box = looseBox();
    EXPECT_EQ(occ::freeEdges(box).size(), 24u);
    EXPECT_EQ(occ::pairFreeEdges(box, 1e-6).size(), 12u);
    // a box without its top: the top's four neighbours keep an edge with no pair, and the
    // pairs are left to the sewing
    EXPECT_TRUE(occ::pairFreeEdges(looseBox(1), 1e-6).empty());
    EXPECT_TRUE(occ::pairFreeEdges(box, 0).empty());
    EXPECT_TRUE(occ::pairFreeEdges(box, std::nan("")).empty());
}

// The copies become one edge on import: every edge of the model is used by two faces (the
// copies running against each other take the kept one's parameter the other way round), and
// the mesh is closed and within the tolerance.
TEST(FreeEdgePairs, JoinedCopiesMeshClosed) {
    const TopoDS_Compound box = looseBox();
    const Model model = occ::importModel(box);
    std::map<int, int> uses;
    for (const auto& face : model.faces) {
        ASSERT_TRUE(face.error.empty()) << face.error;
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves) ++uses[curve.edge];
    }
    EXPECT_EQ(uses.size(), 12u);
    for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << "edge " << edge;
    // joined, not sewn: the other copies stay in the edge list, unused (OpenCASCADE's sewing
    // would have merged them into 12)
    EXPECT_EQ(model.edges.size(), 24u);
    TessellationOptions options;
    options.tolerance = 0.01;
    const auto result = tessellateModel(model, options);
    ASSERT_TRUE(result.failures.empty());
    const auto report = occ::verifyMesh(box, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass);
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(result.mesh.triangles.size(), 12u);
}

}  // namespace
}  // namespace nurbslod
