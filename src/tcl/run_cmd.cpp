// run ?N? ?-every K script?, step, reset
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

#include "lattice_sides.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// One step, with the kernel's error turned into a Tcl error and warnings passed
// on, then the recorders (output csv, output movie) that are due.
int advance(Session& s) {
  const int code = guarded(s.interp, [&] {
    updateTimedSides(s.interp, s.manager);  // -expr sides in $t, at the step's time
    s.manager.step();
    return TCL_OK;
  });
  flushWarnings(s);
  if (code != TCL_OK) return code;
  return recordStep(s);
}

// Sets Session::running for the run, restored however it ends (a run in an
// -every script leaves the outer one running).
struct RunningFlag {
  Session& s;
  bool was;
  explicit RunningFlag(Session& session) : s(session), was(session.running) { s.running = true; }
  ~RunningFlag() { s.running = was; }
};

// Adds to `stage`, as it goes out of scope, the time it lived that no other
// stage took: a script's own time, less the snapshots, outputs or steps it ran.
struct OwnTime {
  Session& s;
  Stage stage;
  Profile::Clock::time_point t0 = Profile::Clock::now();
  double before = s.manager.profile().totalSeconds();
  ~OwnTime() {
    Profile& p = s.manager.profile();
    const double inside = p.totalSeconds() - before;
    p.add(stage, std::max(0.0, std::chrono::duration<double>(Profile::Clock::now() - t0).count() -
                                   inside));
  }
};

// Evaluates the tick script; TCL_BREAK asks the run to pause.
int tick(Session& s) {
  const OwnTime timed{s, Stage::tick};
  Tcl_Obj* script = s.runTick;
  Tcl_IncrRefCount(script);  // the tick may replace itself
  s.inTick = true;
  const int code = Tcl_EvalObjEx(s.interp, script, TCL_EVAL_GLOBAL);
  s.inTick = false;
  Tcl_DecrRefCount(script);
  if (code == TCL_ERROR) Tcl_AddErrorInfo(s.interp, "\n    (in the workbench's run tick)");
  return code;
}

// Evaluates the live plot's sample script (the workbench's ::sf::gui::runsample).
int sample(Session& s) {
  const OwnTime timed{s, Stage::tick};
  Tcl_Obj* script = s.runSample;
  Tcl_IncrRefCount(script);  // the script may replace itself
  const int code = Tcl_EvalObjEx(s.interp, script, TCL_EVAL_GLOBAL);
  Tcl_DecrRefCount(script);
  if (code == TCL_ERROR) Tcl_AddErrorInfo(s.interp, "\n    (in the workbench's run sample)");
  return code;
}

// What a run is asked to do: N steps, and every K steps the -every script or
// (a run with no N) a snapshot named after the step.
struct RunRequest {
  Tcl_WideInt steps = 0;
  int every = 0;
  Tcl_Obj* script = nullptr;
  std::string framePrefix;
};

// -every K script: the row converts K; the script, a second value, the
// command takes after it.
Option<RunRequest> everyScriptRow() {
  Option<RunRequest> row =
      everyRow("evaluate script every K steps; break stops the run", &RunRequest::every, "");
  row.info.synopsis = "K script";
  return row;
}
const OptionTable<RunRequest> kRunOptions{everyScriptRow()};

// A global variable as a whole number >= least; false (with the error) when it
// is not one.
bool globalCount(Tcl_Interp* interp, const char* name, Tcl_Obj* value, Tcl_WideInt least,
                 Tcl_WideInt& out) {
  if (Tcl_GetWideIntFromObj(nullptr, value, &out) == TCL_OK && out >= least) return true;
  fail(interp, std::string("VALUE ") + name,
       std::string(name) + " must be a whole number >= " + std::to_string(least) + ", got \"" +
           Tcl_GetString(value) + "\"");
  return false;
}

// `run` with no N runs the thesis's way (docs/thesis-compat.md): N is the
// global TIMESTEPS and, with no -every, a snapshot PREFIXnnnnnn.png (the step)
// is taken every GRAPHICSFRAMES steps when SNAPSHOTPREFIX is set. Read here,
// not in the Tcl layer, so that `run` stays one command with one set of errors.
int thesisRun(Tcl_Interp* interp, RunRequest& r) {
  Tcl_Obj* steps = Tcl_GetVar2Ex(interp, "TIMESTEPS", nullptr, TCL_GLOBAL_ONLY);
  if (!steps) return fail(interp, "VALUE STEPS", "run needs N: give a count, or set TIMESTEPS");
  if (!globalCount(interp, "TIMESTEPS", steps, 0, r.steps)) return TCL_ERROR;
  if (r.script) return TCL_OK;
  Tcl_Obj* prefix = Tcl_GetVar2Ex(interp, "SNAPSHOTPREFIX", nullptr, TCL_GLOBAL_ONLY);
  if (!prefix || Tcl_GetCharLength(prefix) == 0) return TCL_OK;
  Tcl_Obj* frames = Tcl_GetVar2Ex(interp, "GRAPHICSFRAMES", nullptr, TCL_GLOBAL_ONLY);
  if (!frames)
    return fail(interp, "VALUE GRAPHICSFRAMES",
                "SNAPSHOTPREFIX asks for snapshots: set GRAPHICSFRAMES to say how often");
  Tcl_WideInt every = 0;
  if (!globalCount(interp, "GRAPHICSFRAMES", frames, 1, every)) return TCL_ERROR;
  r.every = int(std::min<Tcl_WideInt>(every, std::numeric_limits<int>::max()));
  r.framePrefix = Tcl_GetString(prefix);
  return TCL_OK;
}

// run ?N? ?-every K script?: N may be left out (thesisRun), so four words are
// "-every K script" unless the first is a count.
int parseRun(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], RunRequest& r) {
  Tcl_WideInt unused = 0;
  const bool counted = objc == 2 || objc == 5 ||
                       (objc == 4 && Tcl_GetWideIntFromObj(nullptr, objv[1], &unused) == TCL_OK);
  if (objc < 1 || objc > 5 || objc == 3 || (objc == 4 && counted)) {
    Tcl_WrongNumArgs(interp, 1, objv, "?N? ?-every K script?");
    return TCL_ERROR;
  }
  if (counted) {
    if (Tcl_GetWideIntFromObj(interp, objv[1], &r.steps) != TCL_OK) return TCL_ERROR;
    if (r.steps < 0)
      return fail(interp, "VALUE STEPS", "N must be >= 0, got " + std::to_string(r.steps));
  }
  if (objc == 4 || objc == 5) {
    const int at = objc - 3;
    OptionValue every;
    if (optionIndex(interp, objv[at], kRunOptions.specs()) < 0 ||
        !convertOption(interp, objv[at + 1], kRunOptions.info(0), every))
      return TCL_ERROR;
    r.every = every.integer;
    r.script = objv[at + 2];
  }
  return counted ? TCL_OK : thesisRun(interp, r);
}

// What is due every K steps: the -every script, or the run's snapshot.
int everyK(Session& s, const RunRequest& r) {
  const OwnTime timed{s, Stage::scripts};
  Tcl_Obj* script = r.script;
  if (!script) {
    char step[32];
    std::snprintf(step, sizeof step, "%06lld.png", s.manager.stepCount());
    script = Tcl_NewListObj(0, nullptr);
    Tcl_ListObjAppendElement(nullptr, script, Tcl_NewStringObj("::sf::snapshot", -1));
    Tcl_ListObjAppendElement(nullptr, script, newString(r.framePrefix + step));
  }
  Tcl_IncrRefCount(script);
  const int code = Tcl_EvalObjEx(s.interp, script, TCL_EVAL_GLOBAL);
  Tcl_DecrRefCount(script);
  if (code == TCL_ERROR) {
    const std::string where = std::string("\n    (in ") +
                              (r.script ? "-every script" : "snapshot") + " after step " +
                              std::to_string(s.manager.stepCount()) + ")";
    Tcl_AddErrorInfo(s.interp, where.c_str());
  }
  return code;
}

int Run(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  static const std::string help = kRunOptions.help("run", {"?N? ?-every K script?", "help"}, {});
  if (answerHelp(interp, objc, objv, help)) return TCL_OK;
  Session& s = sessionOf(data);
  if (refuseWhileRunning(s) != TCL_OK) return TCL_ERROR;
  RunRequest r;
  if (parseRun(interp, objc, objv, r) != TCL_OK) return TCL_ERROR;
  double computeSeconds = 0.0;
  Tcl_WideInt done = 0;
  RunningFlag running(s);
  s.runTotal = r.steps;
  ++s.runs;
  using Clock = std::chrono::steady_clock;
  // The run's profile, however it ends (sim info passes). A run in an -every
  // script is part of that script.
  struct Record {
    Session& s;
    const bool outer;
    const Tcl_WideInt& done;
    const Clock::time_point start = Clock::now();
    ~Record() {
      if (outer)
        s.lastRun = sim::recordRun(
            s.manager, std::chrono::duration<double>(Clock::now() - start).count(), done);
    }
  } record{s, !running.was, done};
  if (record.outer) s.manager.profile().reset();
  auto lastTick = Clock::now();
  for (; done < r.steps; ++done) {
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
      s.mlups = double(s.manager.lattice().nodes()) * double(done + 1) / computeSeconds / 1e6;
    if (s.runSample && s.runSampleEvery > 0 && (done + 1) % s.runSampleEvery == 0) {
      const int code = sample(s);
      if (code != TCL_OK) return code;
    }
    if (r.every > 0 && (done + 1) % r.every == 0) {
      const int code = everyK(s, r);
      if (code == TCL_BREAK) {
        ++done;
        break;
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
  s.lastRun = sim::RunRecord();
  s.mlups = 0.0;
  return code;
}

}  // namespace

// A run's tick (the workbench's ::sf::gui::runtick) may serve a click or a
// typed command that asks for another run, a step, a reset or a checkpoint load: refused, the
// run in progress goes on. (An -every script may do all three.)
int refuseWhileRunning(const Session& s) {
  if (!s.inTick) return TCL_OK;
  return fail(
      s.interp, "BUSY RUN",
      "a run is in progress (step " + std::to_string(s.manager.stepCount()) + "): pause it first");
}

void registerRunCommands(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::run", Run, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::step", Step, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::reset", Reset, session, nullptr);
}

}  // namespace sf::tcl
