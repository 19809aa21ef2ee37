#include <gtest/gtest.h>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <limits>
#include <random>

#include "RandomSurface.hpp"
#include "geometry/PointSetEvaluator.hpp"
#include "occ/ModelImporter.hpp"

namespace nurbslod {
namespace {

// Pairs as a tessellation makes them: many share their u (cell corners), some lone, some
// outside the domain; the results are BSplineSurface's, point by point, on any thread count.
TEST(PointSetEvaluator, MatchesBSplineSurfacePointByPoint) {
    std::mt19937 random(21);
    std::uniform_real_distribution<double> parameter(-0.7, 1.7);
    for (int degree : {1, 2, 3, 5, 9, 15})
        for (bool rational : {false, true}) {
            const BSplineSurface surface =
                testing::randomSurface(degree, std::max(1, degree - 1), rational, random, 5, 6);
            std::vector<Point2> uv;
            std::vector<double> sharedU(40);
            for (double& u : sharedU) u = parameter(random);
            for (int k = 0; k < 6000; ++k)
                uv.emplace_back(k % 3 ? sharedU[k % sharedU.size()] : parameter(random),
                                parameter(random));
            const PointSetEvaluator evaluator(surface);
            std::vector<Point3> points(uv.size()), pointsOnly(uv.size()), points2(uv.size());
            std::vector<Vector3> normals(uv.size()), normals2(uv.size());
            evaluator.evaluate(uv, points.data(), normals.data());
            evaluator.evaluate(uv, pointsOnly.data(), nullptr);
            evaluator.evaluate(uv, points2.data(), normals2.data(), 2);
            double scale = 1;
            for (const auto& p : surface.poles())
                scale = std::max(scale, (p.head<3>() / p[3]).norm());
            for (size_t k = 0; k < uv.size(); ++k) {
                const Point3 p = surface.point(uv[k].x(), uv[k].y());
                ASSERT_LT((points[k] - p).norm() / scale, 1e-12) << "degree " << degree;
                ASSERT_EQ(points[k], pointsOnly[k]);
                ASSERT_EQ(points[k], points2[k]);
                ASSERT_EQ(normals[k], normals2[k]);
                ASSERT_LT((normals[k] - surface.normal(uv[k].x(), uv[k].y())).norm(), 1e-9)
                    << "degree " << degree << " at " << uv[k].transpose();
            }
        }
}

// A face's vertex set: a few dozen pairs, a few sharing a u or a v value, the rest lone, on
// surfaces of unequal degrees (the unrolled kernels of degrees 1 to 3 and the general loops
// above, degree 17 past the unrolled basis functions too).
TEST(PointSetEvaluator, SmallSetsOfEveryDegreePair) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> parameter(-0.1, 1.1);
    for (auto [degreeU, degreeV] :
         {std::pair{1, 1}, {2, 1}, {1, 3}, {3, 2}, {3, 3}, {4, 2}, {2, 6}, {17, 3}})
        for (bool rational : {false, true}) {
            const BSplineSurface surface =
                testing::randomSurface(degreeU, degreeV, rational, random, 4, 5);
            std::vector<Point2> uv;
            for (int k = 0; k < 24; ++k) {
                const double u = k % 4 == 1 ? uv.back().x() : parameter(random);
                const double v = k % 4 == 2 ? uv.back().y() : parameter(random);
                uv.emplace_back(u, v);
            }
            std::vector<Point3> points(uv.size());
            std::vector<Vector3> normals(uv.size());
            PointSetEvaluator(surface).evaluate(uv, points.data(), normals.data());
            double scale = 1;
            for (const auto& p : surface.poles())
                scale = std::max(scale, (p.head<3>() / p[3]).norm());
            for (size_t k = 0; k < uv.size(); ++k) {
                EXPECT_LT((points[k] - surface.point(uv[k].x(), uv[k].y())).norm() / scale, 1e-12)
                    << "degrees " << degreeU << " x " << degreeV;
                EXPECT_LT((normals[k] - surface.normal(uv[k].x(), uv[k].y())).norm(), 1e-9)
                    << "degrees " << degreeU << " x " << degreeV;
            }
        }
}

TEST(PointSetEvaluator, PoleNormalsAndBadInput) {
    BRepBuilderAPI_NurbsConvert converter(BRepPrimAPI_MakeSphere(1.5).Shape(), Standard_False);
    TopExp_Explorer it(converter.Shape(), TopAbs_FACE);
    const BSplineSurface sphere =
        occ::toBSplineSurface(occ::faceSurfaceAsBSpline(TopoDS::Face(it.Current())));
    const double u0 = sphere.knotsU().first(), u1 = sphere.knotsU().last();
    const double v0 = sphere.knotsV().first(), v1 = sphere.knotsV().last();
    std::vector<Point2> uv;
    for (double u : {u0, 0.5 * (u0 + u1), u1})
        for (double v : {v0, 0.3 * v0 + 0.7 * v1, v1}) uv.emplace_back(u, v);
    const PointSetEvaluator evaluator(sphere);
    std::vector<Point3> points(uv.size());
    std::vector<Vector3> normals(uv.size());
    evaluator.evaluate(uv, points.data(), normals.data());
    for (size_t k = 0; k < uv.size(); ++k) {
        EXPECT_LT((normals[k] - sphere.normal(uv[k].x(), uv[k].y())).norm(), 1e-9);
        EXPECT_GT(normals[k].dot(points[k]), 1.4);  // outward, poles included
    }
    uv.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0.0);
    points.resize(uv.size());
    EXPECT_THROW(evaluator.evaluate(uv, points.data(), nullptr), std::invalid_argument);
    BSplineSurface bad = sphere;
    bad.pole(0, 0)[3] = -2;
    EXPECT_THROW(PointSetEvaluator{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace nurbslod
