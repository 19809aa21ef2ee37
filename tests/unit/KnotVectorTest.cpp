#include <gtest/gtest.h>

#include <cmath>

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

TEST(KnotVector, NamesWhatIsWrong) {
    EXPECT_NE(KnotVector(2, {0, 0, 0, 1, 1, 1}).problem(4)->find("do not fit"), std::string::npos);
    EXPECT_NE(KnotVector(1, {0, 0, 0.7, 0.5, 1, 1}).problem(4)->find("decrease"),
              std::string::npos);
    EXPECT_NE(KnotVector(1, {0, 0, std::nan(""), 1, 1}).problem(3)->find("not finite"),
              std::string::npos);
    EXPECT_NE(KnotVector(1, {1, 1, 1, 1}).problem(2)->find("empty"), std::string::npos);
}
