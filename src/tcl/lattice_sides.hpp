#pragma once
// The lattice's sides as the commands read and show them: -walls
// {side kind ...} and -periodic {x y}.
#include <tcl.h>

#include "sandflow/lb/lattice_def.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::tcl {

// Converts onto def's sides; false with the Tcl error set.
bool parseWalls(Tcl_Interp* interp, Tcl_Obj* value, lb::LatticeDef& def);
bool parsePeriodic(Tcl_Interp* interp, Tcl_Obj* value, lb::LatticeDef& def);
// {left {noslip} right {slip} ...}, as -walls takes it (cget gives back what
// was given: a velocity side's -profile, -ramp and -expr too).
Tcl_Obj* wallsValue(const lb::LatticeDef& def);

// Velocity sides given by -expr: their expressions evaluated at every node
// ($s along the side, $t the time, $L the side's length), at time t, into
// the sides' values (before a lattice is made or reconfigured with them).
// Throws sf::Error "VALUE WALLS" with the failure's message or the value
// that is no number; def is then unchanged.
void evaluateSideExpressions(Tcl_Interp* interp, lb::LatticeDef& def, double t);
// Before a step: the sides whose expressions read $t, at the time the step
// reaches. Throws as above, with the lattice unchanged.
void updateTimedSides(Tcl_Interp* interp, sim::Manager& manager);

}  // namespace sf::tcl
