#pragma once
// The state one interpreter's commands share: its own Manager (no globals).
#include <tcl.h>

#include <memory>
#include <string>
#include <vector>

#include "sandflow/render/draw_list.hpp"
#include "sandflow/render/view_options.hpp"
#include "sandflow/sim/estimate.hpp"
#include "sandflow/sim/manager.hpp"
#include "sandflow/tcl/recorder.hpp"

namespace sf::tcl {

struct Session {
  Tcl_Interp* interp = nullptr;
  sim::Manager manager;
  std::vector<std::unique_ptr<Recorder>> recorders;
  render::ViewOptions view;  // what the view and snapshots show (view configure)
  // The workbench's hook into `run` (::sf::gui::runtick): a script evaluated at
  // most every runTickMs milliseconds of a run, which serves the GUI's events
  // and redraws; `break` from it pauses the run.
  Tcl_Obj* runTick = nullptr;
  int runTickMs = 50;
  // And its live plot's (::sf::gui::runsample): a script evaluated after every
  // runSampleEvery-th step of a run, counted from the run's start.
  Tcl_Obj* runSample = nullptr;
  long long runSampleEvery = 0;
  bool running = false;                 // a run is in progress
  bool inTick = false;                  // its tick is serving the GUI's events
  long long runDone = 0, runTotal = 0;  // the run's progress, for the GUI's bar
  long long runs = 0;                   // runs started (the GUI tells one from the next)
  // The last run's stages and scene (sim info passes, sim estimate); a run
  // in an -every script is part of that script's time, not a run of its own.
  sim::RunRecord lastRun;
  // The lattice's speed in the run going on, so far, or in the last one
  // (sim info mlups): the command layer's measurement, not the scene's.
  double mlups = 0.0;
  // While `checkpoint load` starts the checkpoint's recordings again: its
  // step, from which a CSV series continues its file (else -1).
  long long resumeStep = -1;
  // The workbench view's last picture without its overlay (rubber bands, the
  // selection), so that a drag redraws only what moves.
  std::unique_ptr<render::DrawList> viewList;
  // Safe mode (Sandflow_SafeInit): the only folder whose files the commands
  // read and write; empty when they may use any.
  std::string confinedTo;
  ~Session();
};

// A command's client data: the session it was registered with.
inline Session& sessionOf(ClientData data) {
  return *static_cast<Session*>(data);
}

// Whether a recorder writes to this path (as the same file by any name).
bool recording(const Session& s, const std::string& path);
// Calls the recorders due after the step just taken. A recorder that fails is
// finished (as far as it can be) and removed; the Tcl error names its file.
int recordStep(Session& s);
// Finishes and removes the recorder writing `path`, or all when path is null.
int closeRecorders(Session& s, const std::string* path);
// Adds a recorder after its first record (taken now, for the current state).
int startRecorder(Session& s, std::unique_ptr<Recorder> recorder);
// The same, keeping the command that starts it (objv) for checkpoints.
int startRecorder(Session& s, std::unique_ptr<Recorder> recorder, int objc, Tcl_Obj* const objv[]);

// Defines ::sf::scriptOptions, the options of a script (script_options.cpp).
int defineScriptOptions(Tcl_Interp* interp);

// Safe mode: confines the session's files to the current folder; and throws
// Error (SAFE PATH) for a path outside it, when confined.
void confineToCurrentFolder(Session& s);
void requireConfined(const Session& s, const std::string& path);

// Refuses (BUSY RUN) a command that would replace or advance the scene while
// a run's tick serves the workbench; TCL_OK otherwise.
int refuseWhileRunning(const Session& s);

// Passes the Manager's new warnings to the Tcl procedure ::sf::warn.
void flushWarnings(Session& session);
// Passes one message to ::sf::warn (whose failure is ignored).
void warnUser(Session& session, const std::string& message);

// Each registers one ensemble (or command) in namespace ::sf.
void registerLatticeCommands(Tcl_Interp* interp, Session* session);
void registerSimCommands(Tcl_Interp* interp, Session* session);
void registerRunCommands(Tcl_Interp* interp, Session* session);
void registerOutputCommands(Tcl_Interp* interp, Session* session);
void registerHelpCommand(Tcl_Interp* interp, Session* session);
void registerMaterialCommands(Tcl_Interp* interp, Session* session);
void registerElementCommands(Tcl_Interp* interp, Session* session);
void registerBondCommands(Tcl_Interp* interp, Session* session);
void registerSourceCommands(Tcl_Interp* interp, Session* session);
void registerViewCommands(Tcl_Interp* interp, Session* session);
void registerRecordCommand(Tcl_Interp* interp, Session* session);
void registerPlotCommand(Tcl_Interp* interp, Session* session);
void registerGuiCommands(Tcl_Interp* interp, Session* session);
void registerCheckpointCommands(Tcl_Interp* interp, Session* session);

}  // namespace sf::tcl

extern "C" int Sandflow_Init(Tcl_Interp* interp);
// The same commands for a safe interpreter (Tcl calls it for `load` into one):
// their files confined to the folder current at the time (docs/robustness.md).
extern "C" int Sandflow_SafeInit(Tcl_Interp* interp);
