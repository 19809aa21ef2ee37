#include <gtest/gtest.h>

#include <cmath>

#include "geometry/BasisFunctions.hpp"
#include "geometry/KnotVector.hpp"

using nurbslod::KnotVector;

TEST(KnotVector, FindsSpansAndBreakpoints) {
    KnotVector k(2, {0, 0, 0, 0.5, 1, 1, 1});
    EXPECT_EQ(k.controlPointCount(), 4);
    EXPECT_EQ(k.findSpan(0.0), 2);
    EXPECT_EQ(k.findSpan(0.25), 2);
    EXPECT_EQ(k.findSpan(0.5), 3);
    EXPECT_EQ(k.findSpan(1.0), 3);
    EXPECT_EQ(k.breakpoints(), (std::vector<double>{0, 0.5, 1}));
    EXPECT_FALSE(k.problem(4).has_value());
}

TEST(KnotVector, ASingleSpanIsTheSpanOfEveryParameter) {
    const KnotVector bezier(2, {0, 0, 0, 1, 1, 1});
    for (double t : {-5.0, 0.0, 0.5, 1.0, 7.0}) EXPECT_EQ(bezier.findSpan(t), 2) << t;
    const KnotVector unclamped(1, {0, 1, 2, 3});  // two control points: one span, [1, 2]
    for (double t : {-1.0, 1.0, 1.5, 2.0, 9.0}) EXPECT_EQ(unclamped.findSpan(t), 1) << t;
    const KnotVector twoSpans(2, {0, 0, 0, 0.5, 1, 1, 1});
    EXPECT_EQ(twoSpans.findSpan(0.75), 3);
}

TEST(KnotVector, NamesWhatIsWrong) {
    EXPECT_NE(KnotVector(2, {0, 0, 0, 1, 1, 1}).problem(4)->find("do not fit"), std::string::npos);
    EXPECT_NE(KnotVector(1, {0, 0, 0.7, 0.5, 1, 1}).problem(4)->find("decrease"),
              std::string::npos);
    EXPECT_NE(KnotVector(1, {0, 0, std::nan(""), 1, 1}).problem(3)->find("not finite"),
              std::string::npos);
    EXPECT_NE(KnotVector(1, {1, 1, 1, 1}).problem(2)->find("empty"), std::string::npos);
}

namespace {

// The Cox-de Boor recursion as defined (NURBS Book, equation 2.5), with 0/0 = 0; the degree-0
// function is 1 on the span findSpan chose for t, which settles t on a knot.
double coxDeBoor(const std::vector<double>& U, int i, int p, double t, int span) {
    if (p == 0) return i == span ? 1.0 : 0.0;
    double value = 0.0;
    if (U[i + p] != U[i]) value += (t - U[i]) / (U[i + p] - U[i]) * coxDeBoor(U, i, p - 1, t, span);
    if (U[i + p + 1] != U[i + 1])
        value +=
            (U[i + p + 1] - t) / (U[i + p + 1] - U[i + 1]) * coxDeBoor(U, i + 1, p - 1, t, span);
    return value;
}

}  // namespace

TEST(KnotVector, BasisFunctionsFromKeptReciprocalsMatchTheRecursion) {
    // Clamped, with an interior knot of full multiplicity, and unclamped with equal steps; and
    // Bezier segments, of degree 1, 2 (a circle's knots), 5 and 16: the kept reciprocals must be
    // 0 exactly where knots repeat, and the values those of the recursion everywhere, on the
    // Bernstein shortcut as on the triangular scheme.
    const std::vector<std::pair<int, std::vector<double>>> cases = {
        {3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.5, 0.9, 1, 1, 1, 1}},
        {2, {-3, -2, -1, 0, 1.5, 2, 3, 4}},
        {5, {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1}},
        {1, {0, 0, 0.25, 0.25, 1, 1}},
        {2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 1, 1, 1}},
        {16, std::vector<double>(17, -2.0)},
    };
    auto withEnd = [](std::vector<double> U) {
        U.insert(U.end(), 17, 3.0);
        return U;
    };
    for (auto [p, U] : cases) {
        if (p == 16) U = withEnd(U);
        const KnotVector k(p, U);
        const int n = k.controlPointCount();
        for (int j = 1; j <= p; ++j)
            for (size_t i = 0; i + j < U.size(); ++i) {
                const double d = U[i + j] - U[i];
                EXPECT_EQ(k.reciprocalDifferences(j)[i], d != 0.0 ? 1.0 / d : 0.0);
            }
        for (int step = 0; step <= 200; ++step) {
            const double t = k.first() + (k.last() - k.first()) * step / 200.0;
            const int span = k.findSpan(t);
            double N[nurbslod::kMaxDegree + 1];
            nurbslod::basisFunctions(k, span, t, N);
            double sum = 0.0;
            for (int r = 0; r <= p; ++r) {
                EXPECT_NEAR(N[r], coxDeBoor(U, span - p + r, p, t, span), 1e-14)
                    << "degree " << p << " t " << t << " r " << r;
                sum += N[r];
            }
            EXPECT_NEAR(sum, 1.0, 1e-14);
            EXPECT_LT(span, n);
        }
    }
}

TEST(KnotVector, TellsBezierSpans) {
    const KnotVector circle(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 1, 1, 1});
    EXPECT_TRUE(circle.isBezierSpan(2));
    EXPECT_TRUE(circle.isBezierSpan(4));
    EXPECT_TRUE(circle.isBezierSpan(6));
    EXPECT_FALSE(circle.isBezierSpan(3));  // empty
    const KnotVector cubic(3, {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.5, 0.9, 1, 1, 1, 1});
    for (int span = 3; span <= 8; ++span) EXPECT_FALSE(cubic.isBezierSpan(span)) << span;
    const KnotVector unclamped(2, {-3, -2, -1, 0, 1.5, 2, 3, 4});
    for (int span = 2; span <= 4; ++span) EXPECT_FALSE(unclamped.isBezierSpan(span)) << span;
}
