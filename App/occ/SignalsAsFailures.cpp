#include "occ/SignalsAsFailures.hpp"

#include <fenv.h>

#include <OSD.hxx>
#include <array>
#include <mutex>

namespace nurbslod::occ {

namespace {

// the signals OSD::SetSignal takes on Linux; only the faults are kept while a guard lives
constexpr std::array<int, 8> kTaken = {SIGHUP, SIGINT, SIGQUIT, SIGILL,
                                       SIGBUS, SIGFPE, SIGSEGV, SIGSYS};
constexpr std::array<int, 3> kNotFaults = {SIGHUP, SIGINT, SIGQUIT};

std::mutex guardMutex;
int guards = 0;
std::array<struct sigaction, kTaken.size()> saved{};
int savedTraps = 0;

void restore(int signal) {
    for (std::size_t k = 0; k < kTaken.size(); ++k)
        if (kTaken[k] == signal) sigaction(signal, &saved[k], nullptr);
}

}  // namespace

SignalsAsFailures::SignalsAsFailures() {
    const std::lock_guard<std::mutex> lock(guardMutex);
    if (guards++ > 0) return;
    for (std::size_t k = 0; k < kTaken.size(); ++k) sigaction(kTaken[k], nullptr, &saved[k]);
    savedTraps = fegetexcept();
    OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
    for (const int signal : kNotFaults) restore(signal);
}

SignalsAsFailures::~SignalsAsFailures() {
    const std::lock_guard<std::mutex> lock(guardMutex);
    if (--guards > 0) return;
    for (const int signal : kTaken) restore(signal);
    if (savedTraps != 0) feenableexcept(savedTraps);
}

}  // namespace nurbslod::occ
