#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "tessellate/ToleranceRequest.hpp"

using namespace nurbslod;

TEST(ToleranceRequest, AbsoluteWinsAndRelativeScalesTheDiagonal) {
    EXPECT_DOUBLE_EQ(resolveTolerance({.absolute = 0.25}, 100.0), 0.25);
    EXPECT_DOUBLE_EQ(resolveTolerance({.relative = 1e-2}, 100.0), 1.0);
    EXPECT_DOUBLE_EQ(resolveTolerance({}, 100.0), defaultRelativeTolerance * 100.0);
    EXPECT_DOUBLE_EQ(resolveTolerance({}, 100.0, 0.5), 50.0);
}

TEST(ToleranceRequest, BadRequestsNameTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double bad : {0.0, -1.0, nan, inf}) {
        EXPECT_THROW(checkToleranceRequest({.absolute = bad}), std::invalid_argument) << bad;
        EXPECT_THROW(checkToleranceRequest({.relative = bad}), std::invalid_argument) << bad;
    }
    try {
        checkToleranceRequest({.absolute = 1.0, .relative = 1e-3},
                              {.absolute = "--tolerance", .relative = "--relative"});
        FAIL() << "both accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("--tolerance"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("not both"), std::string::npos);
    }
}

TEST(ToleranceRequest, RelativeNeedsAModelWithExtent) {
    EXPECT_THROW(resolveTolerance({.relative = 1e-3}, 0.0), std::invalid_argument);
    EXPECT_THROW(resolveTolerance({}, std::numeric_limits<double>::quiet_NaN()),
                 std::invalid_argument);
    EXPECT_DOUBLE_EQ(resolveTolerance({.absolute = 2.0}, 0.0), 2.0);  // no diagonal needed
}

TEST(ToleranceRequest, RelativeThatOverflowsSaysSo) {
    try {
        resolveTolerance({.relative = 1e308}, 24.0);
        FAIL() << "1e308 of 24 was accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("is not a finite number"), std::string::npos)
            << error.what();
    }
}
