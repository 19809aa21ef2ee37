// Even columns (KdTreeGrid::setEvenColumns, chooseEvenColumns): a span cut into the fewest equal
// columns that meet the bound, not a power of two, with the edges' points on the same lines as
// the kd-tree's cuts.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cstdint>
#include <filesystem>
#include <gp_Ax2.hxx>
#include <set>
#include <vector>

#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/KdTreeGrid.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

// The lines the kd-tree cuts a cell [x0, x1] on while it holds two columns or more.
void collectSplits(const KdTreeGrid& grid, std::int64_t x0, std::int64_t x1,
                   std::set<std::int64_t>& lines) {
    const auto at = grid.evenSplit(x0, x1);
    if (!at) return;
    EXPECT_GT(*at, x0);
    EXPECT_LT(*at, x1);
    lines.insert(*at);
    collectSplits(grid, x0, *at, lines);
    collectSplits(grid, *at, x1, lines);
}

// The circle at z = 3 of a cylinder of height 3.
TopoDS_Edge topCircle(const TopoDS_Shape& cylinder) {
    TopoDS_Edge top;
    for (TopExp_Explorer it(cylinder, TopAbs_EDGE); it.More(); it.Next()) {
        const BRepAdaptor_Curve curve(TopoDS::Edge(it.Current()));
        if (curve.GetType() == GeomAbs_Circle && curve.Value(curve.FirstParameter()).Z() > 2.9)
            top = TopoDS::Edge(it.Current());
    }
    EXPECT_FALSE(top.IsNull());
    return top;
}

// 47 columns in the first of two spans: the kd-tree's splits are exactly the 46 inner column
// lines, and an edge's pieces are halved on them (lineWithin) wherever a piece's middle half
// holds one; the second span keeps its halvings.
TEST(KdTreeGrid, EvenColumnsAreWhereTheKdTreeSplits) {
    KdTreeGrid grid(0, 2, {1});
    grid.setEvenColumns({47, 0});
    ASSERT_TRUE(grid.hasEvenColumns());
    const std::vector<std::int64_t> intervals = grid.intervals();
    ASSERT_EQ(intervals.size(), 3u);
    const std::int64_t a = intervals[0], b = intervals[1];
    std::set<std::int64_t> columns;
    for (int c = 1; c < 47; ++c) columns.insert(KdTreeGrid::columnLine(a, b, 47, c));
    std::set<std::int64_t> splits;
    collectSplits(grid, a, b, splits);
    EXPECT_EQ(splits, columns);
    // an edge over the whole span, halved on the lines: every piece ends on a column line until
    // pieces are single columns
    auto stepOf = [&](double parameter) { return std::llround(parameter * double(b - a)); };
    std::vector<std::pair<double, double>> pieces{{0.0, 1.0}};
    std::set<std::int64_t> halved;
    while (!pieces.empty()) {
        const auto [p0, p1] = pieces.back();
        pieces.pop_back();
        const auto line = grid.lineWithin(p0, p1);
        if (!line || !columns.count(stepOf(*line))) continue;
        halved.insert(stepOf(*line));
        pieces.push_back({p0, *line});
        pieces.push_back({*line, p1});
    }
    EXPECT_EQ(halved, columns);
    // within one column, and in the second span, the halvings as before
    const double column = 1.0 / 47;
    EXPECT_FALSE(
        grid.evenSplit(KdTreeGrid::columnLine(a, b, 47, 3), KdTreeGrid::columnLine(a, b, 47, 4)));
    EXPECT_NEAR(grid.lineWithin(3 * column, 4 * column).value(), 3.5 * column, 1e-9);
    EXPECT_FALSE(grid.evenSplit(b, intervals[2]));
    EXPECT_EQ(grid.lineWithin(1, 2).value(), 1.5);
    // counts that do not fit the intervals are dropped
    KdTreeGrid wrong(0, 2, {1});
    wrong.setEvenColumns({47});
    EXPECT_FALSE(wrong.hasEvenColumns());
}

// The triangles of `shape` at `tolerance` (by default 0.0043: about bug3883_xr2-ct-214_bolt.stp
// at relative 1e-4)
// with even columns and without; both meshes within the tolerance and closed.
std::pair<std::size_t, std::size_t> trianglesWithAndWithout(const TopoDS_Shape& shape,
                                                            double tolerance = 0.0043) {
    const Model model = occ::importModel(shape);
    TessellationOptions options;
    options.tolerance = tolerance;
    const auto even = tessellateModel(model, options);
    options.evenColumns = false;
    const auto halved = tessellateModel(model, options);
    for (const auto* result : {&even, &halved}) {
        EXPECT_TRUE(result->failures.empty());
        const auto report = occ::verifyMesh(shape, result->mesh, options.tolerance);
        EXPECT_TRUE(report.pass) << "max dev " << report.maxDev << " cover " << report.maxCover;
        EXPECT_EQ(report.openEdges, 0u);
    }
    return {even.mesh.triangles.size(), halved.mesh.triangles.size()};
}

// A cylinder between two discs: its circles are not straight in the discs' (u, v), so its side
// takes the fewest equal columns (a power of two gives 64 a half turn where 47 do), and the
// discs follow its points: 428 triangles against 516.
TEST(EvenColumns, CylinderBetweenTwoDiscsTakesFewerColumns) {
    const auto [even, halved] = trianglesWithAndWithout(BRepPrimAPI_MakeCylinder(7.5, 3.0).Shape());
    EXPECT_LT(double(even), 0.9 * double(halved)) << even << " vs " << halved;
}

// A cylinder with its top edge chamfered: the side and the cone share a circle that is straight
// in both their (u, v), on one frame. They take the same columns, the larger of their needs:
// 704 triangles against 776 (776 too without the two tied).
TEST(EvenColumns, ChamferedCylinderSharesItsColumnsWithTheCone) {
    const TopoDS_Shape plain = BRepPrimAPI_MakeCylinder(7.5, 3.0).Shape();
    BRepFilletAPI_MakeChamfer chamfer(plain);
    chamfer.Add(1.0, topCircle(plain));
    const auto [even, halved] = trianglesWithAndWithout(chamfer.Shape());
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
}

// The same cylinder with its top edge filleted: the side's top circle is straight in the
// torus's (u, v) too. The torus's columns need cuts across them, more near its rim than near its
// axis; equal columns meet the rows that need the most (kRowColumnsShare), and the side shares
// them: 4,548 triangles against 6,130 with halvings (until rows were counted, the two kept
// their halvings).
TEST(EvenColumns, CylinderSharingACircleWithATorusTakesColumnsCutAcross) {
    const TopoDS_Shape plain = BRepPrimAPI_MakeCylinder(7.5, 3.0).Shape();
    BRepFilletAPI_MakeFillet fillet(plain);
    fillet.Add(1.0, topCircle(plain));
    const auto [even, halved] = trianglesWithAndWithout(fillet.Shape());
    EXPECT_LT(double(even), 0.8 * double(halved)) << even << " vs " << halved;
}

// A sphere as FreeCAD's Part.makeSphere(7) makes it (tests/data/freecad_sphere.brep, the
// generated shapes' sphere), at relative 1e-3: every column is cut across into rows, which
// need fewer columns near the poles. The neediest rows' count is well under its power of two:
// 3,024 triangles against 3,312 with halvings.
TEST(EvenColumns, SphereTakesColumnsCutAcross) {
    const auto [even, halved] = trianglesWithAndWithout(
        occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_sphere.brep"), 0.024249);
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
}

// A loft through a circle, an ellipse and a tilted circle as FreeCAD's Part.makeLoft makes it
// (tests/data/freecad_loft.brep, the generated shapes' loft), at relative 1e-3: its side is one
// span of degree 12 around and 2 along, whose columns each need their own count of rows (16 to
// 59 of the 26 even columns). Cut across first, every column would take the rows the neediest
// one needs; cut into its columns first, each takes its own (FaceTessellator::findCrossings
// builds the kd-tree both ways where that order matters, and keeps the one with fewer cells):
// 2,894 triangles against 4,502 cut across first and 6,788 with halvings.
TEST(EvenColumns, LoftTakesItsColumnsBeforeTheirRows) {
    const auto [even, halved] = trianglesWithAndWithout(
        occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_loft.brep"), 0.035202);
    EXPECT_LT(double(even), 0.5 * double(halved)) << even << " vs " << halved;
}

// Two cylinders fused at right angles (tests/bench/generated_shapes.py's crossed cylinders):
// the larger one has two holes where the other meets it, so its region is not its frame's box,
// but it covers 0.88 of it (kEvenColumnsRegionShare): it takes even columns too, and its circles
// carry fewer points: 1,808 triangles against 1,988 with halvings.
TEST(EvenColumns, CylinderWithHolesTakesFewerColumns) {
    const TopoDS_Shape upright =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -15), gp_Dir(0, 0, 1)), 5, 30).Shape();
    const TopoDS_Shape across =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-15, 0, 0), gp_Dir(1, 0, 0)), 4, 30).Shape();
    BRepAlgoAPI_Fuse fuse(upright, across);
    ASSERT_TRUE(fuse.IsDone());
    const auto [even, halved] = trianglesWithAndWithout(fuse.Shape());
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
}

// wing.brep's four faces each have a free edge: their cells at it are bounded as trimmed
// (CellChoices::filledCellsBySides) and split further within the columns, but the columns
// still beat halvings in guaranteed mode. At relative 1e-3: 734 triangles against 857, and
// no more open edges (36 against 37; BRepMesh 50). At 1e-4 each face, one long span, takes 65
// to 108 columns (kMostColumns): 6,657 triangles against 7,792.
TEST(EvenColumns, FacesWithFreeEdgesTakeThemToo) {
    const auto path = std::filesystem::path(NURBSLOD_CORPUS_DIR) / "wing.brep";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus not found at " << path;
    const TopoDS_Shape shape = occ::readShape(path.string());
    const Model model = occ::importModel(shape);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const auto even = tessellateModel(model, options);
        options.evenColumns = false;
        const auto halved = tessellateModel(model, options);
        const auto evenReport = occ::verifyMesh(shape, even.mesh, options.tolerance);
        const auto halvedReport = occ::verifyMesh(shape, halved.mesh, options.tolerance);
        EXPECT_TRUE(evenReport.pass) << relative << ": max dev " << evenReport.maxDev;
        EXPECT_LE(evenReport.openEdges, halvedReport.openEdges) << relative;
        EXPECT_LT(double(even.mesh.triangles.size()), 0.9 * double(halved.mesh.triangles.size()))
            << relative << ": " << even.mesh.triangles.size() << " vs "
            << halved.mesh.triangles.size();
    }
}

}  // namespace
}  // namespace nurbslod
