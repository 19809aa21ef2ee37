#pragma once

#include <csignal>

namespace nurbslod::occ {

// While one lives, a fault that OpenCASCADE's code raises (an access through a null handle in
// its STEP translator, on a file whose entities are missing or of the wrong type) jumps to the
// nearest OCC_CATCH_SIGNALS in the calling thread and is thrown there as a Standard_Failure
// (OSD::SetSignal), where it would otherwise end the process: a crash in FreeCAD loses the
// user's unsaved work. OpenCASCADE's own transfer catches it per entity and goes on with the
// rest; the reader's try block with OCC_CATCH_SIGNALS reports what is left.
//
// Only the fault signals (SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGSYS) are taken, without floating
// point traps (our code relies on NaN and infinity), and the handlers the process had are put
// back when the last guard of any thread ends: the FreeCAD process keeps its own.
class SignalsAsFailures {
public:
    SignalsAsFailures();
    ~SignalsAsFailures();
    SignalsAsFailures(const SignalsAsFailures&) = delete;
    SignalsAsFailures& operator=(const SignalsAsFailures&) = delete;
};

}  // namespace nurbslod::occ
