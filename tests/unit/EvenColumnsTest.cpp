// Even columns (KdTreeGrid::setEvenColumns, evenColumnLines): a span cut into the fewest equal
// columns that meet the bound, not a power of two, with the edges' points on the same lines as
// the kd-tree's cuts.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "CorpusMesh.hpp"
#include "VerifiedLargestFace.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/EvenColumns.hpp"
#include "tessellate/KdTreeAlignedHalving.hpp"
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
// them: 5,096 triangles against 6,130 with halvings (until rows were counted, the two kept
// their halvings). 4,548 while the torus's boundary rounded off its columns' frame and it kept
// halvings around its axis (KdTreeGrid::framesWithinAStep): its rows near the axis need fewer
// columns than its rim, which equal columns cannot follow.
TEST(EvenColumns, CylinderSharingACircleWithATorusTakesColumnsCutAcross) {
    const TopoDS_Shape plain = BRepPrimAPI_MakeCylinder(7.5, 3.0).Shape();
    BRepFilletAPI_MakeFillet fillet(plain);
    fillet.Add(1.0, topCircle(plain));
    const auto [even, halved] = trianglesWithAndWithout(fillet.Shape());
    EXPECT_LT(double(even), 0.85 * double(halved)) << even << " vs " << halved;
}

// A sphere as FreeCAD's Part.makeSphere(7) makes it (tests/data/freecad_sphere.brep, the
// generated shapes' sphere), at relative 1e-3: every column is cut across into rows, which
// need fewer columns near the poles. The neediest rows' count is well under its power of two:
// 2,814 triangles against 3,312 with halvings (3,024 while columns were tested on halved rows
// whatever lines the other axis took: RowsAreCutOnTheOtherAxisLines).
TEST(EvenColumns, SphereTakesColumnsCutAcross) {
    const auto [even, halved] = trianglesWithAndWithout(
        occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_sphere.brep"), 0.024249);
    EXPECT_LT(double(even), 0.9 * double(halved)) << even << " vs " << halved;
}

// A sphere cut to latitudes -30 to 60 degrees and 270 degrees of longitude, as FreeCAD's
// Part.makeSphere(7, ..., -30, 60, 270) makes it (tests/bench/generated_shapes.py's sphere
// segment), at relative 1e-4: its rows near the equator need 128 halved columns a span of
// longitude, where 65 and 77 equal ones meet every row. Over one span across, equal columns are
// taken beyond kMostColumnsCutAcross, up to a lower share of the power of two: 14,994
// triangles, against 16,750 with halvings alone (16,994 before, its columns halved).
TEST(EvenColumns, SphereSegmentTakesMoreThan64ColumnsCutAcross) {
    const TopoDS_Shape segment =
        BRepPrimAPI_MakeSphere(gp_Ax2(), 7.0, -M_PI / 6, M_PI / 3, 1.5 * M_PI).Shape();
    const auto [even, halved] = trianglesWithAndWithout(segment, 0.0021987);
    EXPECT_LT(even, 15500u) << even << " vs " << halved;
    EXPECT_LT(double(even), 0.9 * double(halved)) << even << " vs " << halved;
}

// A column's rows are cut as the kd-tree cuts them: on the other axis's even lines while a cell
// holds two of them or more, then in halves. A column of the sphere (the first 1/64 of a span,
// at the fixed surface share of relative 1e-4: 128 rows on halvings) is counted the same rows on 8
// equal lines a span across, which are the halvings themselves, as on halvings; on 3 a span, other
// rows. (Before, a column was always counted on halvings, whatever lines the other axis took: a
// sphere's longitudes, tested against halved latitudes of 1.4 degrees, met latitudes of 2 degrees
// in its kd-tree, which halved them again.)
TEST(EvenColumns, RowsAreCutOnTheOtherAxisLines) {
    const Model model =
        occ::importModel(occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_sphere.brep"));
    ASSERT_EQ(model.faces.size(), 1u);
    const auto grids = kdTreeLinesBeforeDiscretisation(model.faces[0]).both();
    ASSERT_TRUE(grids);
    const double target = 0.6 * 0.0024249;
    auto rowsOfColumn = [&](const std::array<KdTreeGrid, 2>& withLines) {
        const ColumnTest test(model.faces[0], withLines, 0, target, ErrorMode::Guaranteed, true);
        const std::vector<std::int64_t> spans = withLines[0].intervals();
        return test.rowCount(spans[0], KdTreeGrid::columnLine(spans[0], spans[1], 64, 1));
    };
    auto withEqualLinesAcross = [&](int count) {
        std::array<KdTreeGrid, 2> lined = *grids;
        lined[1].setEvenColumns(std::vector<int>(lined[1].intervals().size() - 1, count));
        EXPECT_TRUE(lined[1].hasEvenColumns());
        return lined;
    };
    const int halved = rowsOfColumn(*grids);
    ASSERT_GT(halved, 0);
    EXPECT_EQ(rowsOfColumn(withEqualLinesAcross(8)), halved);
    const int onThree = rowsOfColumn(withEqualLinesAcross(3));
    EXPECT_GT(onThree, 0);
    EXPECT_NE(onThree, halved) << onThree;
}

// A loft through a circle, an ellipse and a tilted circle as FreeCAD's Part.makeLoft makes it
// (tests/bench/generated_shapes.py's loft), at relative 1e-3: its faces are single spans of
// degree 12 around and 2 along. Even columns: 1,734 triangles against 1,914 with halvings. Its
// smaller side (surface share 0.03335) takes the fewest equal columns whose middle one the
// kd-tree cuts across only: 13, of 16 rows; with 12 its bound would cut a cell of it along.
TEST(EvenColumns, LoftTakesEvenColumns) {
    const TopoDS_Shape shape = occ::readShape(NURBSLOD_TEST_DATA_DIR "/freecad_loft.brep");
    const auto [even, halved] = trianglesWithAndWithout(shape, 0.035202);
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
    const Model model = occ::importModel(shape);
    ASSERT_GE(model.faces.size(), 1u);
    const auto grids = kdTreeLinesBeforeDiscretisation(model.faces[0]).both();
    ASSERT_TRUE(grids);
    const double target = 0.03335;
    const auto lines =
        evenColumnLines(model.faces[0], *grids, 0, target, ErrorMode::Guaranteed, true, true);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_GE(lines[0].size(), 3u);
    const int count = static_cast<int>(lines[0].size()) - 1;
    EXPECT_EQ(lines[0], KdTreeGrid::equalColumnLines(0, kKdTreeFrameScale, count));
    const ColumnTest test(model.faces[0], *grids, 0, target, ErrorMode::Guaranteed, true);
    auto middleRows = [&](int k) {
        return test.rowCount(KdTreeGrid::columnLine(0, kKdTreeFrameScale, k, k / 2),
                             KdTreeGrid::columnLine(0, kKdTreeFrameScale, k, k / 2 + 1));
    };
    EXPECT_GT(middleRows(count), 1);
    EXPECT_EQ(middleRows(count - 1), -1);
}

// Two cylinders fused at right angles, as tests/bench/generated_shapes.py's crossed cylinders.
TopoDS_Shape crossedCylinders() {
    const TopoDS_Shape upright =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -15), gp_Dir(0, 0, 1)), 5, 30).Shape();
    const TopoDS_Shape across =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-15, 0, 0), gp_Dir(1, 0, 0)), 4, 30).Shape();
    BRepAlgoAPI_Fuse fuse(upright, across);
    EXPECT_TRUE(fuse.IsDone());
    return fuse.Shape();
}

// The crossed cylinders: the larger one has two holes where the other meets it, so its region is
// not its frame's box, but it covers 0.88 of it (kEvenColumnsRegionShare): it takes even columns
// too, and its circles carry fewer points: 1,808 triangles against 1,988 with halvings (1,772 since
// the smaller one takes columns too: CylinderCutByAnotherTakesColumnsAroundItsAxis).
TEST(EvenColumns, CylinderWithHolesTakesFewerColumns) {
    const auto [even, halved] = trianglesWithAndWithout(crossedCylinders());
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
}

// The same crossed cylinders at relative 1e-3 (T = 0.04359): the smaller one is two faces, each
// between its end circle and the curve where the larger meets it, which bulges past its ends
// along the axis. Its columns around are known from the circle, its rows wait for the boundary's
// points; the columns are tested over the box of its curves' control points along the axis
// (FaceKdTreeLines::hull) and are no longer halvings: 560 triangles against 632 (its end discs,
// which take the circles' points, 28 each against 46; BRepMesh_IncrementalMesh 416, discs 29).
TEST(EvenColumns, CylinderCutByAnotherTakesColumnsAroundItsAxis) {
    const TopoDS_Shape shape = crossedCylinders();
    const Model model = occ::importModel(shape);
    int hullFramed = 0;
    for (const TrimmedSurface& face : model.faces) {
        const FaceKdTreeLines lines = kdTreeLinesBeforeDiscretisation(face);
        if (lines.both() || !lines.forColumns()) continue;
        ++hullFramed;
        // the known axis runs around (the circle's), the hull's along the axis
        const int known = lines.axes[0] ? 0 : 1;
        ASSERT_TRUE(lines.hull[1 - known]);
        const auto columns = evenColumnLines(face, *lines.forColumns(), known, 0.6 * 0.04359,
                                             ErrorMode::Guaranteed, true, true);
        // three 120-degree spans of the circle's rational form, each cut into columns
        ASSERT_EQ(columns.size(), 3u);
        for (const auto& span : columns) EXPECT_GE(span.size(), 3u);
    }
    EXPECT_EQ(hullFramed, 2);
    TessellationOptions options;
    options.tolerance = 0.04359;
    const auto result = tessellateModel(model, options);
    EXPECT_TRUE(result.failures.empty());
    const auto report = occ::verifyMesh(shape, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass) << "max dev " << report.maxDev << " cover " << report.maxCover;
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_LT(result.mesh.triangles.size(), 600u);
}

// A face's boundary box may differ from the frame of its pcurves' ends, on which its columns
// were chosen, in the last bits (its points evaluated otherwise, or moved onto their edges'
// shared points): within a frame step at each end, the face takes that frame (framesWithinAStep)
// and keeps its columns; beyond, it keeps its own.
TEST(KdTreeGrid, FramesABoxWithinAStepOfIt) {
    const double turn = 2 * M_PI;
    const KdTreeGrid grid(0, turn, {0, M_PI, turn});
    const double step = 1 / grid.scale();
    EXPECT_TRUE(grid.framesWithinAStep(0, turn));
    EXPECT_TRUE(grid.framesWithinAStep(0, std::nextafter(turn, 0.0)));
    EXPECT_TRUE(grid.framesWithinAStep(1e-30, std::nextafter(turn, 7.0)));
    EXPECT_TRUE(grid.framesWithinAStep(-0.9 * step, turn + 0.9 * step));
    EXPECT_FALSE(grid.framesWithinAStep(0, turn - 2 * step));
    EXPECT_FALSE(grid.framesWithinAStep(2 * step, turn));
    EXPECT_FALSE(grid.framesWithinAStep(0, 0.5 * turn));
    // the same origin, scale and span borders are the same frame
    EXPECT_TRUE(
        grid.hasFrame(0, grid.scale(), spanBordersInFrame(0, grid.scale(), {0, M_PI, turn})));
    EXPECT_FALSE(
        grid.hasFrame(0, grid.scale(), spanBordersInFrame(0, grid.scale(), {0, 3.0, turn})));
    EXPECT_FALSE(
        grid.hasFrame(1e-12, grid.scale(), spanBordersInFrame(0, grid.scale(), {0, M_PI, turn})));
}

// Two faces of one edge frame it from their own pcurves' ends, which may differ in the last
// bits: such frames are near (nearlySameFrame), and ModelTessellator makes them one. A frame a
// step off at either end, or with other span borders, is not near.
TEST(KdTreeGrid, FramesOfOneEdgeDifferingInTheLastBitsAreNear) {
    const double low = 0.0194257807917055, high = 0.8249475520990;
    const KdTreeGrid grid(low, high, {0, M_PI / 2});
    const KdTreeGrid lastBits(std::nextafter(low, 1.0), std::nextafter(high, 0.0), {0, M_PI / 2});
    EXPECT_FALSE(grid.sameFrame(lastBits));
    EXPECT_TRUE(grid.nearlySameFrame(lastBits));
    EXPECT_TRUE(lastBits.nearlySameFrame(grid));
    const double step = 1 / grid.scale();
    EXPECT_FALSE(grid.nearlySameFrame(KdTreeGrid(low + 2 * step, high, {0, M_PI / 2})));
    EXPECT_FALSE(grid.nearlySameFrame(KdTreeGrid(low, high - 2 * step, {0, M_PI / 2})));
    EXPECT_FALSE(grid.nearlySameFrame(KdTreeGrid(low, high, {0, 0.5, M_PI / 2})));
}

// A corpus model's triangles per face in guaranteed mode at relative 1e-4, its mesh within T
// both ways with no open edge (test::verifiedTrianglesPerFace); none where the corpus is absent.
std::optional<std::vector<std::size_t>> corpusTrianglesPerFaceAt1e4(const std::string& name) {
    const auto corpus = test::corpusModel(name);
    if (!corpus) return std::nullopt;
    return test::verifiedTrianglesPerFace(corpus->shape, corpus->model,
                                          1e-4 * corpus->model.boundingBoxDiagonal);
}

// bottle.brep's tori are mirror images in pairs (faces 8 and 11, 42 and 45), each sharing its
// circles with a cylinder; one of each pair framed the circle a few bits off its cylinder's
// frame, so the two were not tied and took halvings: 1,672 triangles against its image's 1,120
// at relative 1e-4, 1,236 against 1,056. Now both take the same, and the mesh is within T.
TEST(EvenColumns, MirrorImageToriTakeTheSameColumns) {
    const auto perFace = corpusTrianglesPerFaceAt1e4("bottle.brep");
    if (!perFace) GTEST_SKIP() << "corpus not found at " << NURBSLOD_CORPUS_DIR;
    EXPECT_EQ((*perFace)[11], (*perFace)[8]);
    EXPECT_EQ((*perFace)[32], (*perFace)[27]);
    EXPECT_EQ((*perFace)[45], (*perFace)[42]);
    EXPECT_EQ((*perFace)[64], (*perFace)[59]);
    EXPECT_LT((*perFace)[11], 1300u);
}

// hammer.iges's rational fillets (faces 10 and 16, 12 and 18) have their whole boxes as regions,
// and share iso-line edges with faces that take no columns. Those no longer rule the fillets'
// columns out: 615 and 423 triangles each at relative 1e-4 instead of 712 and 544 with halvings,
// the mesh within T with no open edge.
TEST(EvenColumns, FaceBesideOneWithoutColumnsKeepsItsOwn) {
    const auto perFace = corpusTrianglesPerFaceAt1e4("hammer.iges");
    if (!perFace) GTEST_SKIP() << "corpus not found at " << NURBSLOD_CORPUS_DIR;
    for (const int face : {10, 16}) EXPECT_LT((*perFace)[face], 660u) << "face " << face;
    for (const int face : {12, 18}) EXPECT_LT((*perFace)[face], 480u) << "face " << face;
}

// A whole torus (as Part.makeTorus(10, 3), the generated shapes' torus) at relative 1e-3: its
// boundary's points span a box a bit narrower than its pcurves' ends, and its columns were
// dropped for that: 4,612 triangles, more than the 4,440 of halvings; now 3,906.
TEST(EvenColumns, TorusKeepsItsColumnsWhereItsBoundaryRoundsOtherwise) {
    const TopoDS_Shape torus = BRepPrimAPI_MakeTorus(10, 3).Shape();
    const auto [even, halved] = trianglesWithAndWithout(torus, 0.037256);
    EXPECT_LT(double(even), 0.95 * double(halved)) << even << " vs " << halved;
}

// wing.brep at relative 1e-3 and 1e-4, tessellated with `option` on and off: on, the mesh is
// within the tolerance, has no more open edges (but for `openEdgesAt1e4` more at 1e-4), and
// takes at most `share` of the triangles.
void expectWingTakesFewerWith(bool TessellationOptions::*option, double share,
                              std::size_t openEdgesAt1e4 = 0) {
    const auto path = std::filesystem::path(NURBSLOD_CORPUS_DIR) / "wing.brep";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus not found at " << path;
    const TopoDS_Shape shape = occ::readShape(path.string());
    const Model model = occ::importModel(shape);
    for (const double relative : {1e-3, 1e-4}) {
        TessellationOptions options;
        options.tolerance = relative * model.boundingBoxDiagonal;
        const auto on = tessellateModel(model, options);
        options.*option = false;
        const auto off = tessellateModel(model, options);
        const auto onReport = occ::verifyMesh(shape, on.mesh, options.tolerance);
        const auto offReport = occ::verifyMesh(shape, off.mesh, options.tolerance);
        EXPECT_TRUE(onReport.pass) << relative << ": max dev " << onReport.maxDev;
        EXPECT_LE(onReport.openEdges, offReport.openEdges + (relative < 5e-4 ? openEdgesAt1e4 : 0))
            << relative;
        EXPECT_LE(double(on.mesh.triangles.size()), share * double(off.mesh.triangles.size()))
            << relative << ": " << on.mesh.triangles.size() << " vs " << off.mesh.triangles.size();
    }
}

// wing.brep's four faces each have a free edge: their cells at it are bounded as trimmed
// (CellChoices::filledCellsBySides) and split further within the columns, and the columns
// take no more triangles than halvings in guaranteed mode. At relative 1e-3: 647 triangles
// against 663, and no more open edges (35 each; BRepMesh 50). At 1e-4 each face, one long
// span, takes 65 to 108 columns (kMostColumns): 6,529 triangles against 6,688, and one open
// edge more (97 against 96; BRepMesh 100), since the wing's exact edges between its faces no
// longer take a face's trimming share (ModelTessellator's edgeBudget): halvings had 6,608
// triangles and 98 open edges before. Halvings took 857 and 7,792 while the kd-tree cut through
// the farthest control point (splitDirectionOfNet).
TEST(EvenColumns, FacesWithFreeEdgesTakeThemToo) {
    expectWingTakesFewerWith(&TessellationOptions::evenColumns, 1.0, 1);
}

// The generated freeform patch (tests/bench/generated_shapes.py): a B-spline interpolated
// through 6 x 6 heights, a round hole cut through it, every edge free. A face with a free edge
// takes no columns cut across into rows (their rows are tested as cells filled to their sides,
// which its cells at the boundary are not): its mesh is the same with or without them, and at
// relative 1e-3 it takes 1,484 triangles where it took 1,654 with them (BRepMesh at the same
// deflection: 974).
TEST(EvenColumns, FaceWithFreeEdgesTakesNoColumnsCutAcross) {
    TColgp_Array2OfPnt heights(1, 6, 1, 6);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            heights.SetValue(i + 1, j + 1,
                             gp_Pnt(5.0 * i, 5.0 * j, 3 * std::sin(0.9 * i) * std::cos(0.7 * j)));
    GeomAPI_PointsToBSplineSurface interpolation;
    interpolation.Interpolate(heights);
    ASSERT_TRUE(interpolation.IsDone());
    const TopoDS_Shape patch = BRepBuilderAPI_MakeFace(interpolation.Surface(), 1e-7).Face();
    const TopoDS_Shape shape =
        BRepAlgoAPI_Cut(
            patch, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(12, 12, -20), gp_Dir(0, 0, 1)), 4.0, 40.0)
                       .Shape())
            .Shape();
    const Model model = occ::importModel(shape);
    ASSERT_EQ(model.faces.size(), 1u);
    TessellationOptions options;
    options.tolerance = 1e-3 * model.boundingBoxDiagonal;
    const TessellationResult result = tessellateModel(model, options);
    ASSERT_TRUE(result.failures.empty());
    options.evenColumnsCutAcross = false;
    const TessellationResult without = tessellateModel(model, options);
    EXPECT_EQ(result.mesh.triangles.size(), without.mesh.triangles.size());
    EXPECT_LT(result.mesh.triangles.size(), 1600u);
    const occ::VerificationReport report = occ::verifyMesh(shape, result.mesh, options.tolerance);
    EXPECT_TRUE(report.pass) << "dev " << report.maxDev << " cover " << report.maxCover;
}

// Graded column lines: the kd-tree splits a cell of several columns at its middle line by
// count, wherever that line lies, and an edge's pieces are halved on the same lines; lines
// that do not run from the interval's first border to its last, increasing, are refused.
TEST(KdTreeGrid, GradedColumnsAreWhereTheKdTreeSplits) {
    KdTreeGrid grid(0, 2, {1});
    const std::vector<std::int64_t> intervals = grid.intervals();
    ASSERT_EQ(intervals.size(), 3u);
    const std::int64_t a = intervals[0], b = intervals[1];
    // five columns, each 1.5 times as wide as the one before
    std::vector<std::int64_t> lines{a};
    double width = double(b - a) / (1 + 1.5 + 2.25 + 3.375 + 5.0625), at = double(a);
    for (int c = 0; c < 4; ++c, width *= 1.5) lines.push_back(std::llround(at += width));
    lines.push_back(b);
    grid.setColumnLines({lines, {}});
    ASSERT_TRUE(grid.hasEvenColumns());
    EXPECT_EQ(grid.columnLines(0), lines);
    EXPECT_TRUE(grid.columnLines(1).empty());
    EXPECT_EQ(grid.evenSplit(a, b), lines[2]);
    EXPECT_EQ(grid.evenSplit(a, lines[2]), lines[1]);
    EXPECT_EQ(grid.evenSplit(lines[2], b), lines[3]);
    EXPECT_FALSE(grid.evenSplit(lines[3], lines[4]));  // one column: halved
    EXPECT_FALSE(grid.evenSplit(a + 1, lines[3]));     // not on a line
    EXPECT_FALSE(grid.evenSplit(b, intervals[2]));     // the other interval halves
    std::set<std::int64_t> splits;
    collectSplits(grid, a, b, splits);
    EXPECT_EQ(splits, std::set<std::int64_t>(lines.begin() + 1, lines.end() - 1));
    // an edge piece over the interval's first half holds lines[2] (at 0.30 of the interval)
    // in its middle half: the coarsest line there is the kd-tree's first split
    const auto line = grid.lineWithin(grid.parameterAt(a), grid.parameterAt(a + (b - a) / 2));
    ASSERT_TRUE(line);
    EXPECT_DOUBLE_EQ(*line, grid.parameterAt(lines[2]));

    KdTreeGrid wrong(0, 2, {1});
    wrong.setColumnLines({{a + 1, lines[2], b}, {}});  // not from the border
    EXPECT_FALSE(wrong.hasEvenColumns());
    wrong.setColumnLines({{a, lines[2], lines[2], b}, {}});  // not increasing
    EXPECT_FALSE(wrong.hasEvenColumns());
    wrong.setColumnLines({lines});  // one interval of two
    EXPECT_FALSE(wrong.hasEvenColumns());
}

// Three eighths of a circle (135 degrees) swept along z, as one rational span (weights 1,
// cos 67.5 degrees, 1): its parameter turns the arc unevenly, about a third faster in the
// middle than at the ends, so equal columns are sized by the middle. Graded columns are each
// the widest that settles: fewer, each settling, and wider at the ends than in the middle.
TEST(EvenColumns, GradedColumnsFollowAnUnevenArc) {
    const double half = 67.5 * M_PI / 180, w = std::cos(half), r = 10;
    TColgp_Array2OfPnt poles(1, 3, 1, 2);
    TColStd_Array2OfReal weights(1, 3, 1, 2);
    const gp_Pnt arc[3] = {gp_Pnt(r, 0, 0), gp_Pnt(r, r * std::tan(half), 0),
                           gp_Pnt(r * std::cos(2 * half), r * std::sin(2 * half), 0)};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j) {
            poles(i + 1, j + 1) = arc[i].Translated(gp_Vec(0, 0, 10.0 * j));
            weights(i + 1, j + 1) = i == 1 ? w : 1.0;
        }
    TColStd_Array1OfReal knotsU(1, 2), knotsV(1, 2);
    TColStd_Array1OfInteger multsU(1, 2), multsV(1, 2);
    knotsU(1) = knotsV(1) = 0;
    knotsU(2) = knotsV(2) = 1;
    multsU(1) = multsU(2) = 3;
    multsV(1) = multsV(2) = 2;
    const Handle(Geom_BSplineSurface) surface =
        new Geom_BSplineSurface(poles, weights, knotsU, knotsV, multsU, multsV, 2, 1);
    const TopoDS_Shape face = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
    const Model model = occ::importModel(face);
    ASSERT_EQ(model.faces.size(), 1u);
    const auto grids = kdTreeLinesBeforeDiscretisation(model.faces[0]).both();
    ASSERT_TRUE(grids);
    const double target = 1e-3;
    const auto equal = evenColumnLines(model.faces[0], *grids, 0, target, ErrorMode::Guaranteed,
                                       true, false, false);
    const auto graded = evenColumnLines(model.faces[0], *grids, 0, target, ErrorMode::Guaranteed,
                                        true, false, true);
    ASSERT_EQ(equal.size(), 1u);
    ASSERT_EQ(graded.size(), 1u);
    const auto& lines = graded[0];
    ASSERT_GE(equal[0].size(), 4u);
    // 86 graded columns against 95 equal ones
    EXPECT_LE(double(lines.size() - 1), 0.95 * double(equal[0].size() - 1))
        << lines.size() - 1 << " graded, " << equal[0].size() - 1 << " equal";
    EXPECT_EQ(lines.front(), 0);
    EXPECT_EQ(lines.back(), kKdTreeFrameScale);
    const ColumnTest test(model.faces[0], *grids, 0, target, ErrorMode::Guaranteed, true);
    for (std::size_t c = 0; c + 1 < lines.size(); ++c) {
        EXPECT_LT(lines[c], lines[c + 1]);
        EXPECT_TRUE(test.settles(lines[c], lines[c + 1])) << "column " << c;
    }
    const std::size_t middle = (lines.size() - 1) / 2;
    EXPECT_GT(lines[1] - lines[0], lines[middle + 1] - lines[middle]);
}

// A loft through four squares, each turned 30 degrees from the one below and 10 higher
// (FreeCAD's Part.makeLoft, solid, not ruled): each side is a ruled surface whose lines turn as
// it rises. Its cells' bound is mostly twist, which falls only linearly with the rows, so the
// rows along the loft, whole cells across its straight side, number well over a thousand.
TopoDS_Shape twistedLoft() {
    BRepOffsetAPI_ThruSections loft(Standard_True, Standard_False);
    for (int k = 0; k < 4; ++k) {
        BRepBuilderAPI_MakePolygon square(gp_Pnt(-5, -5, 0), gp_Pnt(5, -5, 0), gp_Pnt(5, 5, 0),
                                          gp_Pnt(-5, 5, 0), Standard_True);
        gp_Trsf turn, lift;
        turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), k * M_PI / 6);
        lift.SetTranslation(gp_Vec(0, 0, 10.0 * k));
        loft.AddWire(TopoDS::Wire(square.Wire().Moved(TopLoc_Location(lift * turn))));
    }
    loft.Build();
    EXPECT_TRUE(loft.IsDone());
    return loft.Shape();
}

// More than 256 equal columns a span (kMostColumns): the twisted loft's sides at relative 1e-4
// took halvings with 256, 2,048 rows and 4,096 triangles each at 0.53 T; with equal columns
// 2,280 each (9,124 in all; BRepMesh_IncrementalMesh at the same deflection 11,558).
TEST(EvenColumns, TwistedLoftTakesMoreThan256Columns) {
    const TopoDS_Shape shape = twistedLoft();
    const Model model = occ::importModel(shape);
    ASSERT_EQ(model.faces.size(), 6u);
    const double tolerance = 1e-4 * model.boundingBoxDiagonal;
    const std::vector<std::size_t> perFace =
        test::verifiedTrianglesPerFace(shape, model, tolerance);
    std::size_t sides = 0;
    for (std::size_t f = 1; f < perFace.size(); ++f)
        if (perFace[f] > 2) {
            ++sides;
            EXPECT_GT(perFace[f], 1000u);
            EXPECT_LT(perFace[f], 3000u) << "face " << f;
        }
    EXPECT_EQ(sides, 4u);
}

// wing.brep's faces are whole boxes whose one long span bends unevenly: graded columns take
// fewer triangles than equal ones (687 against 734 at relative 1e-3, 6,557 against 6,657 at
// 1e-4), within the tolerance and with no more open edges but one at 1e-4 (96 against 95,
// BRepMesh 100: the points on the free chords are dropped where the cells' bounds leave room,
// and the equal columns' cells leave a little more).
TEST(EvenColumns, WingTakesGradedColumns) {
    expectWingTakesFewerWith(&TessellationOptions::gradedColumns, 0.995, 1);
}

}  // namespace
}  // namespace nurbslod
