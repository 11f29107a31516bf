// output vtk PREFIX
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
  return guarded(interp, [&] {
    Tcl_Obj* files = Tcl_NewListObj(0, nullptr);
    if (s.manager.hasLattice()) {
      io::writeLatticeVti(s.manager.lattice(), prefix + ".vti");
      Tcl_ListObjAppendElement(nullptr, files, newString(prefix + ".vti"));
    }
    if (elements) {
      io::writeElementsVtp(s.manager.assembly(), prefix + ".vtp");
      Tcl_ListObjAppendElement(nullptr, files, newString(prefix + ".vtp"));
    }
    Tcl_SetObjResult(interp, files);
    return TCL_OK;
  });
}

int OutputHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, "");
    return TCL_ERROR;
  }
  Tcl_SetObjResult(
      interp, newString(helpText("output",
                                 {"vtk PREFIX   -> files written: PREFIX.vti (lattice: density, "
                                  "pressure, velocity, kind) and PREFIX.vtp (elements)",
                                  "help"},
                                 nullptr)));
  return TCL_OK;
}

}  // namespace

void registerOutputCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::output", {{"vtk", OutputVtk}, {"help", OutputHelp}}, session);
}

}  // namespace sf::tcl
