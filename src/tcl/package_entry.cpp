// The loadable module behind `package require sandflow`. Tcl's `load` looks up
// Sandflow_Init, which lives in the static command library; taking its address
// here makes the linker keep it (and everything it registers) in the module.
#include "sandflow/tcl/session.hpp"

extern "C" __attribute__((used)) Tcl_PackageInitProc* const sandflowEntryPoint = Sandflow_Init;
extern "C" __attribute__((used)) Tcl_PackageInitProc* const sandflowSafeEntryPoint =
    Sandflow_SafeInit;
