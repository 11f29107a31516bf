// The `sandflow` command.
//   sandflow                  interactive Tcl prompt with the sandflow commands
//   sandflow script.tcl ...   runs the script headless; argv/argc as in tclsh
//   sandflow -c 'commands' ...  runs the commands and prints a non-empty result
//   sandflow -gui ?script.tcl? ?arg ...?  the workbench (Tk, loaded only here),
//                             the script sourced into it once the window is up
#include <tcl.h>

#include <cstdio>
#include <cstring>

#include "sandflow/tcl/session.hpp"

namespace {

// The thesis's command language (docs/thesis-compat.md), loaded in every mode
// so that the thesis's scripts run unchanged: from $SANDFLOW_COMPAT_DIR, the
// source tree this program was built from, or beside an installed program.
constexpr const char* kLoadThesis = R"tcl(
  set ::sf::thesis::library ""
  foreach dir [list [expr {[info exists ::env(SANDFLOW_COMPAT_DIR)] ? $::env(SANDFLOW_COMPAT_DIR) : ""}] \
                   $::sf::thesis::builtFrom \
                   [file join [file dirname [file dirname [info nameofexecutable]]] share sandflow compat]] {
    if {$dir ne "" && [file exists [file join $dir thesis.tcl]]} {
      set ::sf::thesis::library $dir
      break
    }
  }
  if {$::sf::thesis::library eq ""} { error "the thesis layer's Tcl files (compat/thesis.tcl) were not found" }
  source [file join $::sf::thesis::library thesis.tcl]
)tcl";

int appInit(Tcl_Interp* interp) {
  if (Tcl_Init(interp) != TCL_OK) return TCL_ERROR;
  if (Sandflow_Init(interp) != TCL_OK) return TCL_ERROR;
  Tcl_StaticPackage(interp, "sandflow", Sandflow_Init, nullptr);
  Tcl_SetVar(interp, "tcl_rcFileName", "~/.sandflowrc", TCL_GLOBAL_ONLY);
  if (Tcl_Eval(interp, "namespace import ::sf::*; ::sf::shareSource") != TCL_OK) return TCL_ERROR;
  Tcl_Eval(interp, "namespace eval ::sf::thesis {}");
  Tcl_SetVar(interp, "::sf::thesis::builtFrom", SANDFLOW_COMPAT_DIR, TCL_GLOBAL_ONLY);
  return Tcl_Eval(interp, kLoadThesis);
}

void setArgv(Tcl_Interp* interp, const char* argv0, int argc, char** argv) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (int i = 0; i < argc; ++i)
    Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(argv[i], -1));
  Tcl_SetVar2Ex(interp, "argv", nullptr, list, TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argc", nullptr, Tcl_NewIntObj(argc), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argv0", nullptr, Tcl_NewStringObj(argv0, -1), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "tcl_interactive", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
}

int runCommands(const char* argv0, const char* commands, int argc, char** argv) {
  Tcl_Interp* interp = Tcl_CreateInterp();
  setArgv(interp, argv0, argc, argv);
  int code = appInit(interp);
  if (code == TCL_OK) code = Tcl_Eval(interp, commands);
  if (code == TCL_OK) {
    const char* result = Tcl_GetStringResult(interp);
    if (*result) std::printf("%s\n", result);
  } else {
    const char* info = Tcl_GetVar(interp, "errorInfo", TCL_GLOBAL_ONLY);
    std::fprintf(stderr, "%s\n", info ? info : Tcl_GetStringResult(interp));
  }
  std::fflush(stdout);
  Tcl_DeleteInterp(interp);
  Tcl_Finalize();
  return code == TCL_OK ? 0 : 1;
}

// Where the workbench's Tcl sources are: $SANDFLOW_GUI_DIR, the source tree
// this program was built from, or beside an installed program.
constexpr const char* kFindGui = R"tcl(
  set ::sf::gui::library ""
  foreach dir [list [expr {[info exists ::env(SANDFLOW_GUI_DIR)] ? $::env(SANDFLOW_GUI_DIR) : ""}] \
                   $::sf::gui::builtFrom \
                   [file join [file dirname [file dirname [info nameofexecutable]]] share sandflow gui]] {
    if {$dir ne "" && [file exists [file join $dir main.tcl]]} {
      set ::sf::gui::library $dir
      break
    }
  }
  if {$::sf::gui::library eq ""} { error "the workbench's Tcl files (gui/main.tcl) were not found" }
  source [file join $::sf::gui::library main.tcl]
)tcl";

// The workbench: Tk is loaded into this interpreter only here, so headless runs
// load neither Tk nor X. Returns when the main window is closed.
int runGui(const char* argv0, int argc, char** argv) {
  Tcl_Interp* interp = Tcl_CreateInterp();
  // As for a headless script: argv0 is the script, argv its arguments.
  const bool hasScript = argc >= 1;
  setArgv(interp, hasScript ? argv[0] : argv0, hasScript ? argc - 1 : 0,
          argv + (hasScript ? 1 : 0));
  int code = appInit(interp);
  if (code == TCL_OK) {
    Tcl_Eval(interp, "namespace eval ::sf::gui {}");
    Tcl_SetVar(interp, "::sf::gui::builtFrom", SANDFLOW_GUI_DIR, TCL_GLOBAL_ONLY);
    code = Tcl_Eval(interp, kFindGui);
  }
  if (code == TCL_OK) {
    Tcl_Obj* cmd = Tcl_NewListObj(0, nullptr);
    Tcl_ListObjAppendElement(nullptr, cmd, Tcl_NewStringObj("::sf::gui::main", -1));
    if (hasScript) Tcl_ListObjAppendElement(nullptr, cmd, Tcl_NewStringObj(argv[0], -1));
    Tcl_IncrRefCount(cmd);
    code = Tcl_EvalObjEx(interp, cmd, TCL_EVAL_GLOBAL);
    Tcl_DecrRefCount(cmd);
  }
  if (code == TCL_OK) code = Tcl_Eval(interp, "if {[winfo exists .]} {tkwait window .}");
  if (code != TCL_OK) {
    const char* info = Tcl_GetVar(interp, "errorInfo", TCL_GLOBAL_ONLY);
    std::fprintf(stderr, "%s\n", info ? info : Tcl_GetStringResult(interp));
  }
  Tcl_Eval(interp, code == TCL_OK ? "exit 0" : "exit 1");  // exit handlers finish the recordings
  return code == TCL_OK ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Tcl_FindExecutable(argv[0]);
  if (argc >= 2 && std::strcmp(argv[1], "-c") == 0) {
    if (argc < 3) {
      std::fprintf(stderr, "usage: %s -c 'commands' ?arg ...?\n", argv[0]);
      return 2;
    }
    return runCommands(argv[0], argv[2], argc - 3, argv + 3);
  }
  if (argc >= 2 && std::strcmp(argv[1], "-gui") == 0) return runGui(argv[0], argc - 2, argv + 2);
  Tcl_Main(argc, argv, appInit);
  return 0;
}
