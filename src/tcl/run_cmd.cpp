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

// A run's tick (the workbench's ::sf::gui::runtick) may serve a click or a
// typed command that asks for another run, a step or a reset: refused, the
// run in progress goes on. (An -every script may do all three.)
int refuseWhileRunning(const Session& s) {
  if (!s.inTick) return TCL_OK;
  return fail(
      s.interp, "BUSY RUN",
      "a run is in progress (step " + std::to_string(s.manager.stepCount()) + "): pause it first");
}

// Sets Session::running for the run, restored however it ends (a run in an
// -every script leaves the outer one running).
struct RunningFlag {
  Session& s;
  bool was;
  explicit RunningFlag(Session& session) : s(session), was(session.running) { s.running = true; }
  ~RunningFlag() { s.running = was; }
};

// Evaluates the tick script; TCL_BREAK asks the run to pause.
int tick(Session& s) {
  Tcl_Obj* script = s.runTick;
  Tcl_IncrRefCount(script);  // the tick may replace itself
  s.inTick = true;
  const int code = Tcl_EvalObjEx(s.interp, script, TCL_EVAL_GLOBAL);
  s.inTick = false;
  Tcl_DecrRefCount(script);
  if (code == TCL_ERROR) Tcl_AddErrorInfo(s.interp, "\n    (in the workbench's run tick)");
  return code;
}

int Run(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (refuseWhileRunning(s) != TCL_OK) return TCL_ERROR;
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
  RunningFlag running(s);
  s.runTotal = steps;
  ++s.runs;
  using Clock = std::chrono::steady_clock;
  auto lastTick = Clock::now();
  for (; done < steps; ++done) {
    const auto t0 = Clock::now();
    s.runDone = done;
    if (s.runTick && t0 - lastTick >= std::chrono::milliseconds(s.runTickMs)) {
      const int code = tick(s);
      lastTick = Clock::now();
      if (code == TCL_BREAK) {  // paused: the step reached is the result
        Tcl_SetObjResult(interp, Tcl_NewWideIntObj(s.manager.stepCount()));
        return TCL_OK;
      }
      if (code != TCL_OK) return code;
    }
    const auto t1 = Clock::now();
    if (advance(s) != TCL_OK) return TCL_ERROR;
    computeSeconds += std::chrono::duration<double>(Clock::now() - t1).count();
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
  if (refuseWhileRunning(sessionOf(data)) != TCL_OK) return TCL_ERROR;
  return advance(sessionOf(data));
}

int Reset(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  // Output of the old scene ends with it.
  Session& s = sessionOf(data);
  if (refuseWhileRunning(s) != TCL_OK) return TCL_ERROR;
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
