// The "output" ensemble: the verbs that list and close the recorders (output
// vtk, csv and movie live in their own files).
#include <string>
#include <vector>

#include "output_verbs.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// output list -> {FILE {kind csv|record|movie|vtk every K written N} ...}
int OutputList(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_Obj* dict = Tcl_NewDictObj();
  for (const auto& r : sessionOf(data).recorders)
    Tcl_DictObjPut(nullptr, dict, newString(r->path()),
                   newDict({{"kind", Tcl_NewStringObj(r->kind(), -1)},
                            {"every", Tcl_NewIntObj(r->every())},
                            {"written", Tcl_NewWideIntObj(r->written())}}));
  Tcl_SetObjResult(interp, dict);
  return TCL_OK;
}

// output close ?FILE?: finishes one recorder, or all of them.
int OutputClose(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc > 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "?FILE?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  if (objc == 1) return closeRecorders(s, nullptr);
  const std::string path = Tcl_GetString(objv[1]);
  return closeRecorders(s, &path);
}

// The verbs, then the options of vtk, csv and movie from their tables.
std::string outputHelp() {
  return helpText("output",
                  {"vtk PREFIX   -> files written: PREFIX.vti (lattice: density, "
                   "pressure, velocity, kind, solid), PREFIX.vtp (elements), "
                   "PREFIX_bonds.vtp (bonds)",
                   "vtk PREFIX -every K   -> PREFIX.pvd; from now on the same files as "
                   "PREFIX_0000, PREFIX_0001, ... every K steps, listed with their "
                   "times in PREFIX.pvd (open it in ParaView)",
                   "csv FILE -elements IDS ?-every K?   -> FILE; from now on a row "
                   "every K steps: step,time, then per element ID x_ID y_ID "
                   "angle_ID vx_ID vy_ID w_ID fx_ID fy_ID torque_ID fluidfx_ID "
                   "fluidfy_ID fluidtorque_ID",
                   "movie FILE ?-every K? ?-fps n? ?view options?   -> FILE (.mp4, "
                   ".mkv, .mov, .avi, .webm); from now on a frame every K steps, "
                   "piped to ffmpeg; the movie appears when closed",
                   "list   -> dict FILE {kind csv|record|movie|vtk every K written N}",
                   "close ?FILE?   finish one file being recorded, or all of them", "help"},
                  nullptr) +
         "\noutput vtk " + outputVtkOptions() + "\noutput csv " + outputCsvOptions() +
         "\noutput movie " + outputMovieOptions() + "\n  (and the view options: view help)";
}

}  // namespace

void registerOutputCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::output",
               {{"vtk", OutputVtk},
                {"csv", OutputCsv},
                {"movie", OutputMovie},
                {"list", OutputList},
                {"close", OutputClose}},
               session, {.help = outputHelp()});
}

}  // namespace sf::tcl
