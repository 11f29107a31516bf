// help: the ensembles and commands, one line each.
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

constexpr const char* kHelp =
    "sandflow commands (\"NOUN help\" lists a noun's verbs and options):\n"
    "  lattice   the lattice-Boltzmann fluid: create, configure, info, probe, obstacles\n"
    "  material  materials: create, configure, cget, names\n"
    "  disc      disc create -center {x y} -radius r ...\n"
    "  wall      wall create -from {x y} -to {x y} ...  (a line element)\n"
    "  polygon   polygon create -vertices {x1 y1 ...} ...  (convex)\n"
    "  ellipse   ellipse create -center {x y} -axes {a b} ?-sides N? ...\n"
    "  superquadric  superquadric create -center {x y} -axes {a b} -exponents {m n} ...\n"
    "  element   any element: configure, cget, info, ids, delete, next\n"
    "  bond      bonds (cementation): create, auto, ids, info, delete, broken\n"
    "  source    sources (elements that clone themselves): create, delete, ids, info\n"
    "  sim       settings and state: configure -timestep -threads -gravity -integrator, info\n"
    "  run ?N? ?-every K script?   advance N steps (no N: TIMESTEPS)\n"
    "  step      advance one step\n"
    "  reset     empty the scene\n"
    "  checkpoint  the whole scene in a file: save FILE, load FILE (continues bit for bit)\n"
    "  output    write results: vtk PREFIX ?-every K?, csv FILE -elements IDS, movie FILE, list, "
    "close\n"
    "  record FILE ?-every K? ?-quantities LIST?   scene time series (CSV)\n"
    "  plot OUT.png CSVFILE ?-x COL? ?-y COLS? ...   PNG plot of CSV columns (gnuplot)\n"
    "  view      what pictures show: configure, cget, pixel (-field -vectors -range -size ...)\n"
    "  snapshot FILE.png ?view options?   a picture of the scene (headless: OSMesa or EGL)\n"
    "  help      this text";

int Help(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, Tcl_NewStringObj(kHelp, -1));
  return TCL_OK;
}

}  // namespace

void registerHelpCommand(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::help", Help, session, nullptr);
}

}  // namespace sf::tcl
