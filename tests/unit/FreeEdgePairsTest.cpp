#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <array>
#include <cmath>
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

// The loose box whose top face (z = 30) has its front edge (y = 0) in two pieces, split at
// x = 5: the front face's copy of that edge has no pair, nor have the top's two pieces.
TopoDS_Compound looseBoxWithASplitEdge() {
    const TopoDS_Compound whole = looseBox();
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    int f = 0;
    for (TopExp_Explorer it(whole, TopAbs_FACE); it.More(); it.Next(), ++f) {
        if (f != 1) {
            builder.Add(compound, it.Current());
            continue;
        }
        BRepBuilderAPI_MakePolygon top;
        for (const gp_Pnt& p : {gp_Pnt(0, 0, 30), gp_Pnt(5, 0, 30), gp_Pnt(10, 0, 30),
                                gp_Pnt(10, 20, 30), gp_Pnt(0, 20, 30)})
            top.Add(p);
        top.Close();
        builder.Add(compound, BRepBuilderAPI_MakeFace(top.Wire(), Standard_True).Face());
    }
    return compound;
}

// How many loop curves use each edge (seams and poles left out).
std::map<int, int> edgeUses(const Model& model) {
    std::map<int, int> uses;
    for (const auto& face : model.faces)
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves)
                if (!curve.seam && !curve.degenerated) ++uses[curve.edge];
    return uses;
}

// The model's mesh at `tolerance` passes the verifier with no open edge; its triangle count.
std::size_t closedMeshTriangles(const TopoDS_Shape& shape, const Model& model, double tolerance) {
    TessellationOptions options;
    options.tolerance = tolerance;
    const auto result = tessellateModel(model, options);
    EXPECT_TRUE(result.failures.empty());
    const auto report = occ::verifyMesh(shape, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass);
    EXPECT_EQ(report.openEdges, 0u);
    return result.mesh.triangles.size();
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

// Where some free edges have no pair, only the faces near them are left to the sewing: the
// top and front faces of the split edge, and the sides, whose edges end where it ends. The
// bottom and back pair up whole. Imported, the pairs are joined and those faces sewn, and the
// mesh is closed.
TEST(FreeEdgePairs, OnlyTheFacesNearAnEdgeWithoutAPairAreLeftToTheSewing) {
    const TopoDS_Compound box = looseBoxWithASplitEdge();
    EXPECT_EQ(occ::freeEdges(box).size(), 25u);
    EXPECT_TRUE(occ::pairFreeEdges(box, 1e-6).empty());
    const occ::FreeEdgeMatch match = occ::matchFreeEdges(box, 1e-6);
    EXPECT_EQ(match.pairs.size(), 11u);
    EXPECT_EQ(match.facesLeft, (std::vector<int>{2, 3, 5, 6}));
    // a tolerance that is no number compares nothing: every face with a free edge is left
    EXPECT_EQ(occ::matchFreeEdges(box, std::nan("")).facesLeft.size(), 6u);
    const Model model = occ::importModel(box);
    for (const auto& face : model.faces) ASSERT_TRUE(face.error.empty()) << face.error;
    for (const auto& [edge, count] : edgeUses(model)) EXPECT_EQ(count, 2) << "edge " << edge;
    EXPECT_GT(closedMeshTriangles(box, model, 0.01), 0u);
}

// The copies become one edge on import: every edge of the model is used by two faces (the
// copies running against each other take the kept one's parameter the other way round), and
// the mesh is closed and within the tolerance.
TEST(FreeEdgePairs, JoinedCopiesMeshClosed) {
    const TopoDS_Compound box = looseBox();
    const Model model = occ::importModel(box);
    for (const auto& face : model.faces) ASSERT_TRUE(face.error.empty()) << face.error;
    const std::map<int, int> uses = edgeUses(model);
    EXPECT_EQ(uses.size(), 12u);
    for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << "edge " << edge;
    // joined, not sewn: the other copies stay in the edge list, unused (OpenCASCADE's sewing
    // would have merged them into 12)
    EXPECT_EQ(model.edges.size(), 24u);
    EXPECT_EQ(closedMeshTriangles(box, model, 0.01), 12u);
}

// Each face of a plate with a round hole and of a cylinder copied on its own: loose faces on
// planes and cylinders, whose copies meet along lines and circles.
TopoDS_Compound looseFacesOfParts() {
    TopoDS_Compound parts;
    BRep_Builder builder;
    builder.MakeCompound(parts);
    builder.Add(
        parts, BRepAlgoAPI_Cut(
                   BRepPrimAPI_MakeBox(40.0, 30.0, 5.0).Shape(),
                   BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -1), gp::DZ()), 6.0, 7.0).Shape())
                   .Shape());
    builder.Add(parts,
                BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(70, 0, 0), gp::DZ()), 8.0, 12.0).Shape());
    TopoDS_Compound loose;
    builder.MakeCompound(loose);
    for (TopExp_Explorer it(parts, TopAbs_FACE); it.More(); it.Next())
        builder.Add(loose, BRepBuilderAPI_Copy(it.Current()).Shape());
    return loose;
}

// Closed copies (circles) join too: each has both ends nearest to its partner's ends, and a
// guess that took the wrong one slid the projection around the whole circle, which left the
// pair open (188 open edges at relative 1e-3 before).
TEST(FreeEdgePairs, ClosedCopiesJoinToo) {
    const TopoDS_Compound loose = looseFacesOfParts();
    ASSERT_EQ(occ::pairFreeEdges(loose, 1e-6).size(), 16u);
    const Model model = occ::importModel(loose);
    const std::map<int, int> uses = edgeUses(model);
    EXPECT_EQ(uses.size(), 16u);
    for (const auto& [edge, count] : uses) EXPECT_EQ(count, 2) << "edge " << edge;
    EXPECT_GT(closedMeshTriangles(loose, model, 0.05), 0u);
}

// The two faces of a joined edge give the same point at every edge parameter: copies written
// with one parameter keep their own curve carried onto the kept one's parameter (lines and
// circles of loose faces, each way round), and it must be the same point, not the copy's
// point at another parameter.
TEST(FreeEdgePairs, JoinedCurvesAgreeAtEveryParameter) {
    for (const TopoDS_Compound& loose : {looseBox(), looseFacesOfParts()}) {
        const Model model = occ::importModel(loose);
        std::map<int, std::vector<std::pair<const TrimmedSurface*, const TrimCurve*>>> uses;
        for (const auto& face : model.faces)
            for (const auto& loop : face.loops)
                for (const auto& curve : loop.curves)
                    if (!curve.seam && !curve.degenerated)
                        uses[curve.edge].push_back({&face, &curve});
        int compared = 0;
        for (const auto& [edge, faces] : uses) {
            ASSERT_EQ(faces.size(), 2u) << "edge " << edge;
            const auto& [faceA, curveA] = faces[0];
            const auto& [faceB, curveB] = faces[1];
            EXPECT_DOUBLE_EQ(curveA->first, curveB->first);
            EXPECT_DOUBLE_EQ(curveA->last, curveB->last);
            for (int k = 0; k <= 16; ++k) {
                const double t = curveA->first + (curveA->last - curveA->first) * k / 16;
                const Point2 a = curveA->pcurve.point(t), b = curveB->pcurve.point(t);
                EXPECT_LT((faceA->surface.point(a.x(), a.y()) - faceB->surface.point(b.x(), b.y()))
                              .norm(),
                          1e-7)
                    << "edge " << edge << " at " << t;
                ++compared;
            }
        }
        EXPECT_GT(compared, 100);
    }
}

// The pairs are joined in parallel where threads allow: the model is the same, bit for bit,
// with any thread count.
TEST(FreeEdgePairs, JoinsTheSameWithAnyThreadCount) {
    const TopoDS_Compound loose = looseFacesOfParts();
    const Model one = occ::importModel(loose, 1);
    const Model two = occ::importModel(loose, 2);
    ASSERT_EQ(two.faces.size(), one.faces.size());
    for (size_t f = 0; f < one.faces.size(); ++f) {
        ASSERT_EQ(two.faces[f].loops.size(), one.faces[f].loops.size());
        for (size_t l = 0; l < one.faces[f].loops.size(); ++l) {
            const auto &a = one.faces[f].loops[l].curves, &b = two.faces[f].loops[l].curves;
            ASSERT_EQ(a.size(), b.size());
            for (size_t c = 0; c < a.size(); ++c) {
                EXPECT_EQ(a[c].edge, b[c].edge);
                EXPECT_EQ(a[c].reversed, b[c].reversed);
                EXPECT_EQ(a[c].pcurve.poles(), b[c].pcurve.poles());
            }
        }
    }
    ASSERT_EQ(two.edges.size(), one.edges.size());
    for (size_t e = 0; e < one.edges.size(); ++e) {
        EXPECT_EQ(two.edges[e].tolerance, one.edges[e].tolerance);
        EXPECT_EQ(two.edges[e].firstVertex, one.edges[e].firstVertex);
        EXPECT_EQ(two.edges[e].lastVertex, one.edges[e].lastVertex);
    }
}

}  // namespace
}  // namespace nurbslod
