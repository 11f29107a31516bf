#pragma once
// sim info's passes and sim estimate: where the time of a run goes, and how
// long the next steps will take.
#include <tcl.h>

#include "sandflow/tcl/session.hpp"

namespace sf::tcl {

// The stages that ran in the last run (during a run: in this one so far), as
// a dict: name -> dict seconds steps perstep.
Tcl_Obj* passesDict(const Session& s);

// sim estimate ?N?
int SimEstimate(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]);

}  // namespace sf::tcl
