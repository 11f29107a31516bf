// output vtk PREFIX, and the verbs that list and close the recorders
// (output csv and output movie live in their own files).
#include <string>
#include <vector>

#include "output_verbs.hpp"
#include "sandflow/io/atomic_files.hpp"
#include "sandflow/io/vtk.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

Session& sessionOf(ClientData data) {
  return *static_cast<Session*>(data);
}

int OutputVtk(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "PREFIX");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string prefix = Tcl_GetString(objv[1]);
  if (prefix.empty()) return fail(interp, "VALUE PREFIX", "PREFIX must not be empty");
  const bool elements = !s.manager.assembly().empty();
  if (!s.manager.hasLattice() && !elements)
    return fail(interp, "LOOKUP SCENE",
                "nothing to write: the scene has no lattice and no elements");
  std::vector<io::FileContent> files;
  if (s.manager.hasLattice())
    files.push_back({prefix + ".vti",
                     [&](std::ostream& out) { io::writeLatticeVti(s.manager.lattice(), out); }});
  if (elements)
    files.push_back({prefix + ".vtp",
                     [&](std::ostream& out) { io::writeElementsVtp(s.manager.assembly(), out); }});
  return guarded(interp, [&] {
    io::writeAtomically(files);  // both appear, or neither
    Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
    for (const io::FileContent& f : files)
      Tcl_ListObjAppendElement(nullptr, list, newString(f.path));
    Tcl_SetObjResult(interp, list);
    return TCL_OK;
  });
}

// output list -> {FILE {kind csv every K written N} ...}
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

int OutputHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(
      interp,
      newString(helpText("output",
                         {"vtk PREFIX   -> files written: PREFIX.vti (lattice: density, "
                          "pressure, velocity, kind) and PREFIX.vtp (elements)",
                          "csv FILE -elements IDS ?-every K?   -> FILE; from now on a row "
                          "every K steps: step,time, then per element ID x_ID y_ID "
                          "angle_ID vx_ID vy_ID w_ID fx_ID fy_ID torque_ID fluidfx_ID "
                          "fluidfy_ID fluidtorque_ID",
                          "movie FILE ?-every K? ?-fps n? ?view options?   -> FILE (.mp4, "
                          ".mkv, .mov, .avi, .webm); from now on a frame every K steps, "
                          "piped to ffmpeg; the movie appears when closed",
                          "list   -> dict FILE {kind csv|record|movie every K written N}",
                          "close ?FILE?   finish one file being recorded, or all of them", "help"},
                         nullptr)));
  return TCL_OK;
}

}  // namespace

void registerOutputCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::output",
               {{"vtk", OutputVtk},
                {"csv", OutputCsv},
                {"movie", OutputMovie},
                {"list", OutputList},
                {"close", OutputClose},
                {"help", OutputHelp}},
               session);
}

}  // namespace sf::tcl
