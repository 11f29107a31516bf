// run N ?-every K script?, step, reset
#include <chrono>

#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

Session& sessionOf(ClientData data) {
  return *static_cast<Session*>(data);
}

const OptionSpec kRunOptions[] = {
    {"-every", "K script", "evaluate script every K steps; break stops the run"},
    {nullptr, nullptr, nullptr}};

// One step, with the kernel's error turned into a Tcl error and warnings passed
// on, then the recorders (output csv, output movie) that are due.
int advance(Session& s) {
  const int code = guarded(s.interp, [&] {
    s.manager.step();
    return TCL_OK;
  });
  flushWarnings(s);
  if (code != TCL_OK) return code;
  return recordStep(s);
}

int Run(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc != 2 && objc != 5) {
    Tcl_WrongNumArgs(interp, 1, objv, "N ?-every K script?");
    return TCL_ERROR;
  }
  Tcl_WideInt steps = 0;
  if (Tcl_GetWideIntFromObj(interp, objv[1], &steps) != TCL_OK) return TCL_ERROR;
  if (steps < 0) return fail(interp, "VALUE STEPS", "N must be >= 0, got " + std::to_string(steps));
  int every = 0;
  Tcl_Obj* script = nullptr;
  if (objc == 5) {
    if (optionIndex(interp, objv[2], kRunOptions) < 0) return TCL_ERROR;
    if (!getEvery(interp, objv[3], every)) return TCL_ERROR;
    script = objv[4];
  }
  double computeSeconds = 0.0;
  Tcl_WideInt done = 0;
  for (; done < steps; ++done) {
    const auto t0 = std::chrono::steady_clock::now();
    if (advance(s) != TCL_OK) return TCL_ERROR;
    computeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s.manager.hasLattice())  // the rate so far, so that -every scripts can report it
      s.manager.setMlups(double(s.manager.lattice().nodes()) * double(done + 1) / computeSeconds /
                         1e6);
    if (script && (done + 1) % every == 0) {
      const int code = Tcl_EvalObjEx(interp, script, TCL_EVAL_GLOBAL);
      if (code == TCL_BREAK) {
        ++done;
        break;
      }
      if (code == TCL_ERROR) {
        const std::string where =
            "\n    (in -every script after step " + std::to_string(s.manager.stepCount()) + ")";
        Tcl_AddErrorInfo(interp, where.c_str());
        return TCL_ERROR;
      }
      if (code != TCL_OK && code != TCL_CONTINUE) return code;
    }
  }
  Tcl_ResetResult(interp);
  return TCL_OK;
}

int Step(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  return advance(sessionOf(data));
}

int Reset(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  // Output of the old scene ends with it.
  Session& s = sessionOf(data);
  const int code = closeRecorders(s, nullptr);
  s.manager.reset();
  return code;
}

}  // namespace

void registerRunCommands(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::run", Run, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::step", Step, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::reset", Reset, session, nullptr);
}

}  // namespace sf::tcl
