#include <gtest/gtest.h>

#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <cmath>
#include <csignal>

#include "occ/SignalsAsFailures.hpp"

namespace nurbslod {
namespace {

struct sigaction handlerOf(int signal) {
    struct sigaction action {};
    sigaction(signal, nullptr, &action);
    return action;
}

// the fault a malformed STEP file makes OpenCASCADE's translator raise (a null handle read),
// in a try block as the readers have it: whether it came back as a Standard_Failure
bool nullReadIsCaught() {
    try {
        OCC_CATCH_SIGNALS
        volatile int* volatile nowhere = nullptr;
        *nowhere = 1;
    } catch (const Standard_Failure&) {
        return true;
    }
    return false;
}

TEST(SignalsAsFailures, AFaultIsAFailureWhileAGuardLivesAndTheHandlersComeBack) {
    const struct sigaction segvBefore = handlerOf(SIGSEGV), intBefore = handlerOf(SIGINT);
    {
        const occ::SignalsAsFailures guard;
        EXPECT_TRUE(nullReadIsCaught());
        // an interrupt stays the process's; floating point keeps NaN, no trap
        EXPECT_EQ(handlerOf(SIGINT).sa_handler, intBefore.sa_handler);
        volatile double zero = 0;
        EXPECT_TRUE(std::isnan(zero / zero));
        // a second guard (another reader) inside the first changes nothing when it ends
        { const occ::SignalsAsFailures inner; }
        EXPECT_TRUE(nullReadIsCaught());
    }
    EXPECT_EQ(handlerOf(SIGSEGV).sa_handler, segvBefore.sa_handler);
}

}  // namespace
}  // namespace nurbslod
