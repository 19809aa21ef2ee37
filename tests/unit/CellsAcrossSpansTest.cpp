// A kd-tree cell may reach across Bezier span borders where one bound over all its spans'
// pieces settles it (cellErrorBoundAcrossSpans): the bound must hold for the piecewise surface,
// kinks at the borders included, and a surface of many small spans must no longer take a cell
// (two triangles) per span.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <gp_Ax3.hxx>
#include <random>
#include <vector>

#include "CellSamples.hpp"
#include "occ/MeshVerifier.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/CellErrorBound.hpp"
#include "tessellate/ModelTessellator.hpp"

namespace nurbslod {
namespace {

using Parameter = std::array<double, 2>;
using Surface = std::function<Point3(double, double)>;

// A rational bicubic patch over [x0, x1] x [y0, y1] of a wavy sheet, with jittered control
// points and weights from 0.3 to 3.
BezierPatch wavyPatch(std::mt19937& random, double x0, double x1, double y0, double y1) {
    std::uniform_real_distribution<double> jitter(-0.03, 0.03), weight(0.3, 3.0);
    BezierPatch patch(3, 3);
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j) {
            const double x = x0 + (x1 - x0) * i / 3, y = y0 + (y1 - y0) * j / 3;
            const Point3 p(x + jitter(random), y + jitter(random),
                           0.2 * std::sin(3 * x) * std::cos(2 * y) + jitter(random));
            const double w = weight(random);
            patch.pole(i, j) = HomogeneousPoint3(w * p.x(), w * p.y(), w * p.z(), w);
        }
    return patch;
}

// Pieces of a 3 x 2 grid over the cell, breaks at uneven places, each its own patch (a kink at
// every border), neighbours sharing their border rows so that the surface is continuous.
struct KinkedCell {
    std::vector<SpanPiece> pieces;
    std::array<double, 4> breaksS{0, 0.2, 0.7, 1};
    std::array<double, 3> breaksT{0, 0.55, 1};

    explicit KinkedCell(std::mt19937& random) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 2; ++b) {
                SpanPiece piece{
                    wavyPatch(random, breaksS[a], breaksS[a + 1], breaksT[b], breaksT[b + 1]),
                    breaksS[a], breaksS[a + 1], breaksT[b], breaksT[b + 1]};
                // the shared rows of the pieces before it in s and in t
                if (a > 0)
                    for (int j = 0; j <= 3; ++j) piece.patch.pole(0, j) = at(a - 1, b).pole(3, j);
                if (b > 0)
                    for (int i = 0; i <= 3; ++i) piece.patch.pole(i, 0) = at(a, b - 1).pole(i, 3);
                pieces.push_back(std::move(piece));
            }
    }
    const BezierPatch& at(int a, int b) const { return pieces[a * 2 + b].patch; }
    Point3 operator()(double s, double t) const {
        const int a = s < breaksS[1] ? 0 : s < breaksS[2] ? 1 : 2;
        const int b = t < breaksT[1] ? 0 : 1;
        const SpanPiece& piece = pieces[a * 2 + b];
        return piece.patch.point((s - piece.s0) / (piece.s1 - piece.s0),
                                 (t - piece.t0) / (piece.t1 - piece.t0));
    }
};

TEST(CellsAcrossSpans, BoundIsNeverBelowAMeasuredDistanceOnAKinkedSurface) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> anywhere(0, 1);
    int checked = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const KinkedCell cell(random);
        const Surface surface = [&](double s, double t) { return cell(s, t); };
        for (bool trimmedCell : {false, true}) {
            // at equal parameters (byDistance false), as the sampled distance is measured; a
            // target of 0 and one that makes the bound cut each piece's difference in quarters
            const CellErrorBound coarse = cellErrorBoundAcrossSpans(
                cell.pieces, ErrorMode::Guaranteed, 0, trimmedCell, false, 1);
            const double coarseMeasure = trimmedCell ? coarse.trimmed() : coarse.untrimmed();
            for (double target : {0.0, 0.6 * coarseMeasure}) {
                const CellErrorBound bound = cellErrorBoundAcrossSpans(
                    cell.pieces, ErrorMode::Guaranteed, target, trimmedCell, false, 1);
                EXPECT_LE(bound.measure(ErrorMode::Guaranteed, trimmedCell), coarseMeasure + 1e-15);
                EXPECT_LE(
                    std::max(testing::sampledTriangleDistance(surface, {0, 0}, {1, 0}, {1, 1}),
                             testing::sampledTriangleDistance(surface, {0, 0}, {1, 1}, {0, 1})),
                    bound.untrimmed() * (1 + 1e-9) + 1e-12);
                for (int k = 0; k < 8; ++k) {
                    // corners on the sides: a neighbour's points
                    EXPECT_LE(
                        testing::sampledTriangleDistance(surface, testing::cellBorderPoint(random),
                                                         testing::cellBorderPoint(random),
                                                         testing::cellBorderPoint(random)),
                        bound.untrimmed() * (1 + 1e-9) + 1e-12);
                    // corners anywhere: trimming points
                    EXPECT_LE(testing::sampledTriangleDistance(
                                  surface, {anywhere(random), anywhere(random)},
                                  {anywhere(random), anywhere(random)},
                                  {anywhere(random), anywhere(random)}),
                              bound.trimmed() * (1 + 1e-9) + 1e-12);
                }
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 20 * 2 * 2);
}

// Pieces of one patch bound it no worse than the patch's own net does: the union of the
// pieces' hulls lies in the patch's hull.
TEST(CellsAcrossSpans, PiecesOfOnePatchBoundItNoWorseThanItsNet) {
    std::mt19937 random(5);
    for (int trial = 0; trial < 20; ++trial) {
        const BezierPatch patch = wavyPatch(random, 0, 1, 0, 1);
        std::vector<SpanPiece> pieces;
        const double breaksS[] = {0, 0.3, 1}, breaksT[] = {0, 0.45, 0.8, 1};
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 3; ++b)
                pieces.push_back(
                    {patch.restricted(breaksS[a], breaksS[a + 1], breaksT[b], breaksT[b + 1]),
                     breaksS[a], breaksS[a + 1], breaksT[b], breaksT[b + 1]});
        for (bool trimmedCell : {false, true}) {
            const CellErrorBound whole =
                cellErrorBound(patch, ErrorMode::Guaranteed, 0, trimmedCell, false);
            const CellErrorBound across =
                cellErrorBoundAcrossSpans(pieces, ErrorMode::Guaranteed, 0, trimmedCell, false, 1);
            EXPECT_NEAR(across.twist, whole.twist, 1e-12);
            EXPECT_LE(across.measure(ErrorMode::Guaranteed, trimmedCell),
                      whole.measure(ErrorMode::Guaranteed, trimmedCell) * (1 + 1e-9) + 1e-12);
        }
    }
}

// A gently curved sheet as a bicubic B-spline of 24 x 24 uniform spans, each span far within
// the tolerance: the kd-tree used to cut at every span border first (at least 2 triangles a
// span: 1,140 guaranteed, 1,108 approximate), and now keeps cells of many spans where their
// bound allows (280 and 254; a bowl of that curvature needs about 11 x 11 cells at 0.6 T).
TEST(CellsAcrossSpans, SurfaceOfManySmallSpansTakesFewerCellsThanSpans) {
    constexpr int kSpans = 24, kDegree = 3, kPoles = kSpans + kDegree;
    TColgp_Array2OfPnt poles(1, kPoles, 1, kPoles);
    // Greville abscissae of the uniform clamped knots, on [0, 10]: a smooth bowl
    auto greville = [&](int k) {
        double sum = 0;
        for (int i = k + 1; i <= k + kDegree; ++i)
            sum += std::clamp(double(i - kDegree), 0.0, double(kSpans));
        return 10.0 * sum / kDegree / kSpans;
    };
    for (int i = 1; i <= kPoles; ++i)
        for (int j = 1; j <= kPoles; ++j) {
            const double x = greville(i - 1), y = greville(j - 1);
            poles.SetValue(i, j, gp_Pnt(x, y, 0.02 * (x * x + y * y)));
        }
    TColStd_Array1OfReal knots(1, kSpans + 1);
    TColStd_Array1OfInteger multiplicities(1, kSpans + 1);
    for (int k = 1; k <= kSpans + 1; ++k) {
        knots.SetValue(k, double(k - 1) / kSpans);
        multiplicities.SetValue(k, k == 1 || k == kSpans + 1 ? kDegree + 1 : 1);
    }
    const Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(
        poles, knots, knots, multiplicities, multiplicities, kDegree, kDegree);
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, 1e-7);
    const Model model = occ::importModel(face);
    ASSERT_EQ(model.faces.size(), 1u);
    for (const ErrorMode mode : {ErrorMode::Guaranteed, ErrorMode::Approximate}) {
        TessellationOptions options;
        options.tolerance = 1e-3 * model.boundingBoxDiagonal;
        options.mode = mode;
        const TessellationResult result = tessellateModel(model, options);
        ASSERT_TRUE(result.failures.empty());
        EXPECT_LT(result.mesh.triangles.size(), std::size_t(kSpans * kSpans));
        if (mode == ErrorMode::Guaranteed) {
            const auto report = occ::verifyMesh(face, result.mesh, options.tolerance);
            EXPECT_TRUE(report.pass) << "max dev " << report.maxDev << " cover " << report.maxCover;
        }
    }
}

// `shape`, one face, tessellated in guaranteed mode at `relative` of its diagonal: no face
// failed, and the verifier's measure passes both ways. Returns the triangles and the report.
struct VerifiedFace {
    std::size_t triangles = 0;
    occ::VerificationReport report;
};
VerifiedFace verifiedOneFace(const TopoDS_Shape& shape, double relative) {
    const Model model = occ::importModel(shape);
    EXPECT_EQ(model.faces.size(), 1u);
    TessellationOptions options;
    options.tolerance = relative * model.boundingBoxDiagonal;
    const TessellationResult result = tessellateModel(model, options);
    EXPECT_TRUE(result.failures.empty())
        << (result.failures.empty() ? "" : result.failures.front().reason);
    VerifiedFace verified{result.mesh.triangles.size(),
                          occ::verifyMesh(shape, result.mesh, options.tolerance)};
    EXPECT_TRUE(verified.report.pass)
        << "max dev " << verified.report.maxDev << " cover " << verified.report.maxCover;
    return verified;
}

// A sphere approximated by a bicubic B-spline of 64 x 6 spans, its tips (where a span border
// row collapses to a point) inside cells that reach across spans: the corners of such a cell
// coincide in pairs, and its twist term is the collapsed side's (planarTwist). At relative
// 1e-2 it takes 832 triangles (1,152 with a cell a span at least), keeps the tolerance and is
// closed (its seam and tips included).
// Only one tolerance: OpenCASCADE's projections, which the verifier's measure makes, take 7 s
// on this surface at 1e-2 and 28 s at 1e-3 (the tessellation 17 and 33 ms).
TEST(CellsAcrossSpans, SphereOfManySpansKeepsItsTips) {
    const Handle(Geom_SphericalSurface) sphere = new Geom_SphericalSurface(gp_Ax3(), 10.0);
    GeomConvert_ApproxSurface approximation(sphere, 1e-4, GeomAbs_C1, GeomAbs_C1, 3, 3, 400, 1);
    ASSERT_TRUE(approximation.HasResult());
    const Handle(Geom_BSplineSurface) surface = approximation.Surface();
    ASSERT_GE(surface->NbUKnots() * surface->NbVKnots(), 100);
    const VerifiedFace verified = verifiedOneFace(BRepBuilderAPI_MakeFace(surface, 1e-6), 1e-2);
    EXPECT_LT(verified.triangles, 1000u);
    EXPECT_EQ(verified.report.openEdges, 0u);
}

// OpenCASCADE's sample MAT.brep (occt-misc, which libocct-foundation-dev depends on): one
// bumpy face of 77 x 80 bicubic spans, far smaller than it bends at relative 1e-3. A cell a
// span took 15,976 triangles there; cells across spans take 10,470 (BRepMesh at the same
// deflection: 8,060), and 11,324 with finer cells at its free chords for fewer open edges
// (TessellationOptions::refineAtFreeChords), within the tolerance.
TEST(CellsAcrossSpans, FittedSampleFaceTakesFewerCellsThanSpans) {
    const std::filesystem::path path = "/usr/share/opencascade/data/occ/MAT.brep";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "OpenCASCADE's samples not found";
    EXPECT_LT(verifiedOneFace(occ::readShape(path.string()), 1e-3).triangles, 12000u);
}

}  // namespace
}  // namespace nurbslod
