#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <map>
#include <mutex>
#include <numeric>
#include <vector>

#include "occ/ModelImporter.hpp"
#include "trim/CurveOnSurface.hpp"

namespace nurbslod {
namespace {

// A plate with a round hole (planes and a cylinder that meet at circles) beside a sphere, a
// cone and a torus: every elementary surface, each with circles and seams.
TopoDS_Shape analyticParts() {
    const TopoDS_Shape plate =
        BRepAlgoAPI_Cut(
            BRepPrimAPI_MakeBox(40.0, 30.0, 5.0).Shape(),
            BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -1), gp::DZ()), 6.0, 7.0).Shape())
            .Shape();
    TopoDS_Compound parts;
    BRep_Builder builder;
    builder.MakeCompound(parts);
    builder.Add(parts, plate);
    builder.Add(parts, BRepPrimAPI_MakeSphere(gp_Pnt(60, 0, 0), 8.0).Shape());
    builder.Add(parts,
                BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 60, 0), gp::DZ()), 7.0, 2.0, 9.0).Shape());
    builder.Add(parts,
                BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(60, 60, 0), gp::DZ()), 10.0, 3.0).Shape());
    return parts;
}

struct Use {
    const TrimmedSurface* face;
    const TrimCurve* curve;
};

std::map<int, std::vector<Use>> usesByEdge(const Model& model) {
    std::map<int, std::vector<Use>> uses;
    for (const auto& face : model.faces)
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves)
                if (curve.edge >= 0 && !curve.degenerated)
                    uses[curve.edge].push_back({&face, &curve});
    return uses;
}

// The importer converts analytic surfaces to B-splines itself, with another parameter than
// the file's, and carries the pcurves over; a circle edge moves to its rational parameter on
// every face. Whatever the faces, at one parameter of an edge every face must give the same
// point, on the edge: that is what lets a mesh share the edge's points and close.
TEST(ModelImporter, AnalyticFacesAgreeOnEveryEdgeParameter) {
    const TopoDS_Shape shape = analyticParts();
    const Model model = occ::importModel(shape);
    for (const auto& face : model.faces) ASSERT_TRUE(face.error.empty()) << face.error;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    TopoDS_Compound allEdges;
    BRep_Builder builder;
    builder.MakeCompound(allEdges);
    for (int k = 1; k <= edges.Extent(); ++k) builder.Add(allEdges, edges(k));

    const double accuracy = 1e-6 * model.boundingBoxDiagonal;
    int shared = 0;
    for (const auto& [edge, uses] : usesByEdge(model)) {
        const TrimCurve& first = *uses.front().curve;
        for (const Use& use : uses) {
            EXPECT_DOUBLE_EQ(use.curve->first, first.first) << "edge " << edge;
            EXPECT_DOUBLE_EQ(use.curve->last, first.last) << "edge " << edge;
        }
        shared += uses.size() >= 2;
        for (int k = 0; k <= 8; ++k) {
            const double s = double(k) / 8;
            const Point3 reference =
                CurveOnSurface(uses.front().face->surface, first.pcurve, first.first, first.last)
                    .point(s);
            for (const Use& use : uses) {
                const Point3 p = CurveOnSurface(use.face->surface, use.curve->pcurve,
                                                use.curve->first, use.curve->last)
                                     .point(s);
                EXPECT_LE((p - reference).norm(), accuracy) << "edge " << edge << " at " << s;
            }
            BRepExtrema_DistShapeShape distance(
                BRepBuilderAPI_MakeVertex(gp_Pnt(reference.x(), reference.y(), reference.z())),
                allEdges);
            ASSERT_TRUE(distance.IsDone());
            EXPECT_LE(distance.Value(), accuracy) << "edge " << edge << " at " << s;
        }
    }
    // the plate's two circles and its seam, the cylinder's, and each solid's seam at least
    EXPECT_GE(shared, 8);
}

// A plane's circle becomes its exact rational quadratic, and the circles of a cylinder, a cone
// and a torus lines in (u, v): the edge discretiser bounds both tightly (a circle approximated
// in its angle would take a high degree and many spans, a cylinder's circle that is not
// straight a trimming share).
TEST(ModelImporter, CirclesStayExactAndStraight) {
    const Model model = occ::importModel(analyticParts());
    int planeCircles = 0, straightCircles = 0;
    for (const auto& face : model.faces) {
        const bool plane =
            face.surface.knotsU().degree() == 1 && face.surface.knotsV().degree() == 1;
        for (const auto& loop : face.loops)
            for (const auto& curve : loop.curves) {
                if (curve.degenerated) continue;
                const CurveOnSurface onSurface(face.surface, curve.pcurve, curve.first, curve.last);
                const bool rational = std::any_of(
                    curve.pcurve.poles().begin(), curve.pcurve.poles().end(),
                    [](const HomogeneousPoint2& p) { return std::abs(p.z() - 1) > 1e-12; });
                if (plane && rational) {
                    ++planeCircles;
                    EXPECT_EQ(curve.pcurve.knots().degree(), 2);
                }
                if (!plane && onSurface.straightInParameterPlane()) ++straightCircles;
            }
    }
    EXPECT_EQ(planeCircles, 4);  // the hole on the plate's top and bottom, the cone's two caps
    // the cylinder's two circles and seam, the cone's two circles and seam, the torus's seams,
    // the sphere's seam
    EXPECT_GE(straightCircles, 8);
}

// The faces may be converted in parallel: each writes only its own slot, so the model comes
// out the same, bit for bit, whatever the thread count. Four copies of the parts give each
// thread faces of every kind.
TEST(ModelImporter, TheModelIsTheSameWithAnyThreadCount) {
    TopoDS_Compound parts;
    BRep_Builder builder;
    builder.MakeCompound(parts);
    for (int k = 0; k < 4; ++k) {
        TopoDS_Shape copy = analyticParts();
        gp_Trsf shift;
        shift.SetTranslation(gp_Vec(100.0 * k, 0, 0));
        copy.Move(TopLoc_Location(shift));
        builder.Add(parts, copy);
    }
    const Model one = occ::importModel(parts, 1);
    ASSERT_GE(one.faces.size(), 40u);
    for (const int threads : {2, 0}) {
        const Model many = occ::importModel(parts, threads);
        ASSERT_EQ(many.faces.size(), one.faces.size());
        ASSERT_EQ(many.edges.size(), one.edges.size());
        for (size_t f = 0; f < one.faces.size(); ++f) {
            const TrimmedSurface &a = one.faces[f], &b = many.faces[f];
            EXPECT_EQ(a.faceIndex, b.faceIndex);
            EXPECT_EQ(a.error, b.error);
            EXPECT_EQ(a.reversed, b.reversed);
            EXPECT_EQ(a.surface.poles(), b.surface.poles()) << "face " << f + 1;
            ASSERT_EQ(a.loops.size(), b.loops.size());
            for (size_t l = 0; l < a.loops.size(); ++l) {
                ASSERT_EQ(a.loops[l].curves.size(), b.loops[l].curves.size());
                for (size_t c = 0; c < a.loops[l].curves.size(); ++c) {
                    const TrimCurve &x = a.loops[l].curves[c], &y = b.loops[l].curves[c];
                    EXPECT_EQ(x.edge, y.edge);
                    EXPECT_EQ(x.first, y.first);
                    EXPECT_EQ(x.last, y.last);
                    EXPECT_EQ(x.pcurve.poles(), y.pcurve.poles())
                        << "face " << f + 1 << " loop " << l << " curve " << c;
                }
            }
        }
    }
}

// Progress comes after each face, from whichever thread converted it: every count from 1 to the
// number of faces once, each with that number as the total.
TEST(ModelImporter, ReportsProgressForEveryFace) {
    const TopoDS_Shape parts = analyticParts();
    for (const int threads : {1, 2}) {
        std::mutex mutex;
        std::vector<std::size_t> counts;
        std::size_t totals = 0;
        const Model model =
            occ::importModel(parts, threads, [&](std::size_t done, std::size_t total) {
                std::lock_guard lock(mutex);
                counts.push_back(done);
                totals = std::max(totals, total);
            });
        std::sort(counts.begin(), counts.end());
        std::vector<std::size_t> expected(model.faces.size());
        std::iota(expected.begin(), expected.end(), std::size_t(1));
        EXPECT_EQ(counts, expected) << threads << " threads";
        EXPECT_EQ(totals, model.faces.size());
    }
}

}  // namespace
}  // namespace nurbslod
