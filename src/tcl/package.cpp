// Package initialisation: one Session per interpreter, the commands in ::sf.
#include "remedy.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// `exit` does not delete the interpreter: recorders are finished here (a csv
// flushed, a movie's ffmpeg waited for) so that a script's last output is whole.
void finishAtExit(ClientData data) {
  closeRecorders(*static_cast<Session*>(data), nullptr);
}

void deleteSession(ClientData data, Tcl_Interp*) {
  Tcl_DeleteExitHandler(finishAtExit, data);
  delete static_cast<Session*>(data);
}

// Warnings go through a procedure the user (or the GUI) may redefine.
constexpr const char* kWarnProc = R"tcl(
namespace eval ::sf {
  if {[info commands ::sf::warn] eq ""} {
    proc warn {message} { puts stderr "sandflow warning: $message" }
  }
  namespace export lattice sim run step reset checkpoint output help material disc wall polygon ellipse superquadric element bond record plot view snapshot
  # "source" is also Tcl's command to read a file: ::sf::source is not exported;
  # the application installs a global "source" that serves both (sf::shareSource).
  proc shareSource {} {
    if {[info commands ::sf::TclSource] ne ""} return
    rename ::source ::sf::TclSource
    set map {}
    foreach verb {create delete ids info options help} {dict set map $verb ::sf::source::$verb}
    # Any other first word is Tcl's "source ?-encoding name? FILE".
    namespace ensemble create -command ::source -map $map -prefixes 0 \
        -unknown {apply {{ensemble word args} {list ::sf::TclSourceFile $word}}}
  }
  # Tcl's "source", with its own message under its own name (the renamed
  # command would say "::sf::TclSource" in it).
  proc TclSourceFile {args} {
    if {[llength $args] != 1 && [llength $args] != 3} {
      return -code error -errorcode {TCL WRONGARGS} \
          {wrong # args: should be "source ?-encoding name? fileName"}
    }
    tailcall ::sf::TclSource {*}$args
  }
}
)tcl";

}  // namespace

void warnUser(Session& session, const std::string& message) {
  Tcl_Obj* cmd[2] = {Tcl_NewStringObj("::sf::warn", -1), Tcl_NewStringObj(message.c_str(), -1)};
  for (Tcl_Obj* o : cmd) Tcl_IncrRefCount(o);
  // A failing warn procedure must not turn a warning into an error of the run.
  Tcl_Obj* saved = Tcl_GetObjResult(session.interp);
  Tcl_IncrRefCount(saved);
  Tcl_EvalObjv(session.interp, 2, cmd, TCL_EVAL_GLOBAL);
  Tcl_SetObjResult(session.interp, saved);
  Tcl_DecrRefCount(saved);
  for (Tcl_Obj* o : cmd) Tcl_DecrRefCount(o);
}

void flushWarnings(Session& session) {
  for (const sim::Warning& w : session.manager.takeWarnings())
    warnUser(session, withRemedy(w.text, w.remedy));
}

}  // namespace sf::tcl

namespace {

int initialise(Tcl_Interp* interp, bool safe) {
  using namespace sf::tcl;
  if (Tcl_PkgRequire(interp, "Tcl", "8.6", 0) == nullptr) return TCL_ERROR;
  auto* session = new Session;
  session->interp = interp;
  if (safe) confineToCurrentFolder(*session);
  Tcl_CallWhenDeleted(interp, deleteSession, session);
  Tcl_CreateExitHandler(finishAtExit, session);
  registerLatticeCommands(interp, session);
  registerSimCommands(interp, session);
  registerRunCommands(interp, session);
  registerOutputCommands(interp, session);
  registerHelpCommand(interp, session);
  registerMaterialCommands(interp, session);
  registerElementCommands(interp, session);
  registerBondCommands(interp, session);
  registerSourceCommands(interp, session);
  registerViewCommands(interp, session);
  registerRecordCommand(interp, session);
  registerPlotCommand(interp, session);
  if (!safe) registerGuiCommands(interp, session);  // no workbench in safe mode
  registerCheckpointCommands(interp, session);
  if (Tcl_Eval(interp, kWarnProc) != TCL_OK || defineScriptOptions(interp) != TCL_OK)
    return TCL_ERROR;
  return Tcl_PkgProvide(interp, "sandflow", SANDFLOW_VERSION);
}

}  // namespace

extern "C" int Sandflow_Init(Tcl_Interp* interp) {
  return initialise(interp, false);
}

extern "C" int Sandflow_SafeInit(Tcl_Interp* interp) {
  return initialise(interp, true);
}
