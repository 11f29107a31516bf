#pragma once
// The lattice's sides as the commands read and show them: -walls
// {side kind ...} and -periodic {x y}.
#include <tcl.h>

#include "sandflow/lb/lattice_def.hpp"

namespace sf::tcl {

// Converts onto def's sides; false with the Tcl error set.
bool parseWalls(Tcl_Interp* interp, Tcl_Obj* value, lb::LatticeDef& def);
bool parsePeriodic(Tcl_Interp* interp, Tcl_Obj* value, lb::LatticeDef& def);
// {left {noslip} right {slip} ...}, as -walls takes it.
Tcl_Obj* wallsValue(const lb::LatticeDef& def);

}  // namespace sf::tcl
