#include <gtest/gtest.h>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "OcctSurface.hpp"
#include "RandomSurface.hpp"
#include "geometry/GridEvaluator.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"

namespace nurbslod {
namespace {

using testing::randomSurface;
using testing::uniformParameters;

double poleScale(const BSplineSurface& s) {
    double size = 1.0;
    for (const auto& p : s.poles()) size = std::max(size, (p.head<3>() / p[3]).norm());
    return size;
}

// Domain length over the length of the knot span holding t.
double spanShortness(const KnotVector& knots, double t) {
    const int span = knots.findSpan(t);
    return (knots.last() - knots.first()) / (knots.knots()[span + 1] - knots.knots()[span]);
}

// Compares a grid evaluation with OpenCASCADE's D1 on the same surface: points to 1e-9 of the
// model size, unit normals to 1e-9 (where OpenCASCADE's du x dv is well defined).
void expectMatchesOcct(const BSplineSurface& surface, const Handle(Geom_BSplineSurface) & occt,
                       const std::vector<double>& us, const std::vector<double>& vs,
                       const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                       const std::string& what) {
    const double scale = poleScale(surface);
    for (size_t i = 0; i < us.size(); ++i)
        for (size_t j = 0; j < vs.size(); ++j) {
            gp_Pnt p;
            gp_Vec du, dv;
            occt->D1(us[i], vs[j], p, du, dv);
            const size_t k = i * vs.size() + j;
            ASSERT_LT((points[k] - Point3(p.X(), p.Y(), p.Z())).norm() / scale, 1e-9)
                << what << " at (" << us[i] << ", " << vs[j] << ")";
            // The direction of du x dv is as sensitive to rounding as its condition number
            // (|du| |dv| / |du x dv|, times the ratio of the derivative lengths) says: the
            // normals agree to 1e-9 relative to that. Where it is ill-conditioned (a pole, a
            // collapsed edge) OpenCASCADE's normal is rounding noise; there the evaluator
            // promises BSplineSurface's pole-safe normal (to rounding amplified by the same
            // condition, hence the looser bound).
            const gp_Vec n = du.Crossed(dv);
            const double a = du.Magnitude(), b = dv.Magnitude();
            const double condition = n.Magnitude() > 0 && std::min(a, b) > 0
                                         ? a * b / n.Magnitude() * std::max(a, b) / std::min(a, b)
                                         : std::numeric_limits<double>::infinity();
            // ... and a derivative inside a sliver knot span (a file with knots 1 and 1+4e-7)
            // loses as many digits as the span is shorter than the domain
            const double sliver = std::max(spanShortness(surface.knotsU(), us[i]),
                                           spanShortness(surface.knotsV(), vs[j]));
            const bool wellConditioned = condition * sliver < 1e6;
            const Vector3 expected = wellConditioned ? Vector3(n.X(), n.Y(), n.Z()).normalized()
                                                     : surface.normal(us[i], vs[j]);
            ASSERT_LT((normals[k] - expected).norm(),
                      wellConditioned ? 1e-9 * condition * sliver : 1e-6)
                << what << " normal at (" << us[i] << ", " << vs[j] << ")";
        }
}

TEST(GridEvaluator, AgreesWithOpenCascadeOnRandomSurfaces) {
    std::mt19937 random(7);
    const std::pair<int, int> degrees[] = {{1, 1}, {2, 3},   {3, 3},  {5, 4},
                                           {7, 7}, {10, 10}, {15, 15}};
    for (auto [pu, pv] : degrees)
        for (bool rational : {false, true}) {
            const BSplineSurface surface = randomSurface(pu, pv, rational, random);
            const auto occt = testing::toOcctSurface(surface);
            GridEvaluator evaluator(surface);
            // 37 x 23: columns not a multiple of four, parameters on and between knots
            const auto us = uniformParameters(-0.5, 1.5, 37), vs = uniformParameters(-0.5, 1.5, 23);
            for (auto set :
                 {GridEvaluator::InstructionSet::Scalar, GridEvaluator::InstructionSet::Avx2}) {
                evaluator.setInstructionSet(set);
                std::vector<Point3> points;
                std::vector<Vector3> normals;
                evaluator.evaluate(us, vs, points, &normals);
                expectMatchesOcct(surface, occt, us, vs, points, normals,
                                  "degree " + std::to_string(pu) + "x" + std::to_string(pv) +
                                      (rational ? " rational" : ""));
                // points only gives the same points
                std::vector<Point3> pointsOnly;
                evaluator.evaluate(us, vs, pointsOnly, nullptr);
                for (size_t k = 0; k < points.size(); ++k) ASSERT_EQ(points[k], pointsOnly[k]);
            }
        }
}

// The AVX2 path and the scalar path agree to 1e-12 relative, threads do not change a bit, and
// random (unsorted, repeated, outside the domain) parameters are handled like the point-wise
// evaluation of BSplineSurface.
TEST(GridEvaluator, VectorScalarThreadedAndPointwiseAgree) {
    if (!GridEvaluator::avx2Available()) GTEST_SKIP() << "this CPU has no AVX2+FMA";
    std::mt19937 random(11);
    std::uniform_real_distribution<double> parameter(-0.7, 1.7);
    for (int degree : {1, 3, 6, 15}) {
        const BSplineSurface surface = randomSurface(degree, degree, true, random, 6, 8);
        std::vector<double> us(29), vs(61);
        for (double& u : us) u = parameter(random);
        for (double& v : vs) v = parameter(random);
        vs[5] = vs[4];
        GridEvaluator evaluator(surface);
        std::vector<Point3> p1, p2, p3;
        std::vector<Vector3> n1, n2, n3;
        evaluator.setInstructionSet(GridEvaluator::InstructionSet::Scalar);
        evaluator.evaluate(us, vs, p1, &n1);
        evaluator.setInstructionSet(GridEvaluator::InstructionSet::Avx2);
        evaluator.evaluate(us, vs, p2, &n2);
        evaluator.evaluate(us, vs, p3, &n3, 2);
        const double scale = poleScale(surface);
        for (size_t k = 0; k < p1.size(); ++k) {
            ASSERT_LT((p1[k] - p2[k]).norm() / scale, 1e-12) << "degree " << degree;
            ASSERT_LT((n1[k] - n2[k]).norm(), 1e-12) << "degree " << degree;
            ASSERT_EQ(p2[k], p3[k]);
            ASSERT_EQ(n2[k], n3[k]);
        }
        for (size_t i = 0; i < us.size(); ++i)
            for (size_t j = 0; j < vs.size(); ++j) {
                const size_t k = i * vs.size() + j;
                ASSERT_LT((p1[k] - surface.point(us[i], vs[j])).norm() / scale, 1e-12);
                ASSERT_LT((n1[k] - surface.normal(us[i], vs[j])).norm(), 1e-9);
            }
    }
}

// A grid large enough to be spread over threads gives the single-threaded results bit for bit.
TEST(GridEvaluator, ThreadsGiveTheSameResults) {
    std::mt19937 random(13);
    for (bool rational : {false, true}) {
        const BSplineSurface surface = randomSurface(3, 4, rational, random, 9, 7);
        const auto us = uniformParameters(-0.5, 1.5, 211), vs = uniformParameters(-0.5, 1.5, 203);
        for (auto set :
             {GridEvaluator::InstructionSet::Scalar, GridEvaluator::InstructionSet::Avx2}) {
            GridEvaluator evaluator(surface);
            evaluator.setInstructionSet(set);
            std::vector<Point3> p1, p2;
            std::vector<Vector3> n1, n2;
            evaluator.evaluate(us, vs, p1, &n1, 1);
            evaluator.evaluate(us, vs, p2, &n2, 3);
            ASSERT_EQ(p1, p2);
            ASSERT_EQ(n1, n2);
        }
    }
}

// At the poles of a sphere du vanishes; the evaluator gives BSplineSurface's pole-safe normal.
TEST(GridEvaluator, PoleNormalIsTheSurfaceNormal) {
    BRepBuilderAPI_NurbsConvert converter(BRepPrimAPI_MakeSphere(2.0).Shape(), Standard_False);
    TopExp_Explorer it(converter.Shape(), TopAbs_FACE);
    const auto occt = occ::faceSurfaceAsBSpline(TopoDS::Face(it.Current()));
    const BSplineSurface surface = occ::toBSplineSurface(occt);
    double u0, u1, v0, v1;
    occt->Bounds(u0, u1, v0, v1);
    const auto us = uniformParameters(u0, u1, 9), vs = uniformParameters(v0, v1, 9);
    for (auto set : {GridEvaluator::InstructionSet::Scalar, GridEvaluator::InstructionSet::Avx2}) {
        GridEvaluator evaluator(surface);
        evaluator.setInstructionSet(set);
        std::vector<Point3> points;
        std::vector<Vector3> normals;
        evaluator.evaluate(us, vs, points, &normals);
        int poles = 0;
        for (size_t i = 0; i < us.size(); ++i)
            for (size_t j = 0; j < vs.size(); ++j) {
                const auto d = surface.derivatives(us[i], vs[j]);
                if (d.du.norm() < 1e-8 * d.dv.norm() || d.dv.norm() < 1e-8 * d.du.norm()) ++poles;
                const Vector3 expected = surface.normal(us[i], vs[j]);
                ASSERT_LT((normals[i * vs.size() + j] - expected).norm(), 1e-9);
                // and it points away from the centre, as a sphere's normal should
                ASSERT_GT(normals[i * vs.size() + j].dot(points[i * vs.size() + j]), 1.9);
            }
        EXPECT_GT(poles, 0) << "the grid should reach the poles";
    }
}

TEST(GridEvaluator, RejectsBadInput) {
    std::mt19937 random(3);
    BSplineSurface surface = randomSurface(3, 3, true, random);
    GridEvaluator evaluator(surface);
    std::vector<Point3> points;
    const std::vector<double> good = {0.1, 0.2},
                              bad = {0.1, std::numeric_limits<double>::quiet_NaN()};
    EXPECT_THROW(evaluator.evaluate(good, bad, points, nullptr), std::invalid_argument);
    EXPECT_THROW(evaluator.evaluate(bad, good, points, nullptr), std::invalid_argument);
    surface.pole(1, 1)[3] = -1.0;
    EXPECT_THROW(GridEvaluator{surface}, std::invalid_argument);
    surface.pole(1, 1)[0] = std::numeric_limits<double>::infinity();
    EXPECT_THROW(GridEvaluator{surface}, std::invalid_argument);
}

// Every B-spline face of the corpus (analytic faces converted as the importer does).
TEST(GridEvaluator, AgreesWithOpenCascadeOnEveryCorpusFace) {
    const std::filesystem::path corpus = NURBSLOD_CORPUS_DIR;
    if (!std::filesystem::is_directory(corpus)) GTEST_SKIP() << "corpus not found at " << corpus;
    size_t faces = 0;
    for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
        const TopoDS_Shape shape = occ::readShape(entry.path().string());
        BRepBuilderAPI_NurbsConvert converter(shape, Standard_False);
        TopTools_IndexedMapOfShape map;
        TopExp::MapShapes(converter.Shape(), TopAbs_FACE, map);
        for (int k = 1; k <= map.Extent(); ++k) {
            const auto occt = occ::faceSurfaceAsBSpline(TopoDS::Face(map(k)));
            const BSplineSurface surface = occ::toBSplineSurface(occt);
            double u0, u1, v0, v1;
            occt->Bounds(u0, u1, v0, v1);
            const auto us = uniformParameters(u0, u1, 7), vs = uniformParameters(v0, v1, 9);
            GridEvaluator evaluator(surface);
            std::vector<Point3> points;
            std::vector<Vector3> normals;
            evaluator.evaluate(us, vs, points, &normals);
            expectMatchesOcct(surface, occt, us, vs, points, normals,
                              entry.path().filename().string() + " face " + std::to_string(k));
            ++faces;
        }
    }
    EXPECT_GT(faces, 100u);
}

}  // namespace
}  // namespace nurbslod
