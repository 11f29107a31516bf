// The `sandflow` command.
//   sandflow                  interactive Tcl prompt with the sandflow commands
//   sandflow script.tcl ...   runs the script headless; argv/argc as in tclsh
//   sandflow -c 'commands' ...  runs the commands and prints a non-empty result
//   sandflow -gui ?script.tcl? ?arg ...?  the workbench (Tk, loaded only here),
//                             the script sourced into it once the window is up
//   sandflow -safe ?-outdir DIR? script.tcl ?arg ...?  an untrusted script in a
//                             safe interpreter, its files confined to DIR
#include <tcl.h>

#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <string>

#include "sandflow/tcl/session.hpp"

namespace {

// The parts of sandflow written in Tcl (the workbench, the thesis layer, safe
// mode) are found in $ENV, the source tree this program was built from, or
// share/sandflow/SUBDIR beside an installed program.
constexpr const char* kFindLibrary = R"tcl(
  namespace eval ::sf {}
  proc ::sf::findLibrary {envName builtFrom subdir file what} {
    foreach dir [list [expr {[info exists ::env($envName)] ? $::env($envName) : ""}] \
                     $builtFrom [file join [file dirname [file dirname \
                         [info nameofexecutable]]] share sandflow $subdir]] {
      if {$dir ne "" && [file exists [file join $dir $file]]} { return $dir }
    }
    error "$what ($subdir/$file) were not found"
  }
  proc ::sf::sourceLibrary {ns args} {
    namespace eval $ns {}
    set ${ns}::library [::sf::findLibrary {*}$args]
    uplevel #0 [list source [file join [set ${ns}::library] [lindex $args 3]]]
  }
)tcl";

// Evaluates the command made of these words, in the global namespace.
int evalWords(Tcl_Interp* interp, std::initializer_list<const char*> words) {
  Tcl_Obj* cmd = Tcl_NewListObj(0, nullptr);
  for (const char* w : words) Tcl_ListObjAppendElement(nullptr, cmd, Tcl_NewStringObj(w, -1));
  Tcl_IncrRefCount(cmd);
  const int code = Tcl_EvalObjEx(interp, cmd, TCL_EVAL_GLOBAL);
  Tcl_DecrRefCount(cmd);
  return code;
}

// Sets NS::library to the folder of a part written in Tcl and sources FILE
// from it.
int sourceLibrary(Tcl_Interp* interp, const char* ns, const char* env, const char* builtFrom,
                  const char* subdir, const char* file, const char* what) {
  if (Tcl_Eval(interp, kFindLibrary) != TCL_OK) return TCL_ERROR;
  return evalWords(interp, {"::sf::sourceLibrary", ns, env, builtFrom, subdir, file, what});
}

int appInit(Tcl_Interp* interp) {
  if (Tcl_Init(interp) != TCL_OK) return TCL_ERROR;
  if (Sandflow_Init(interp) != TCL_OK) return TCL_ERROR;
  Tcl_StaticPackage(interp, "sandflow", Sandflow_Init, Sandflow_SafeInit);
  Tcl_SetVar(interp, "tcl_rcFileName", "~/.sandflowrc", TCL_GLOBAL_ONLY);
  if (Tcl_Eval(interp, "namespace import ::sf::*; ::sf::shareSource") != TCL_OK) return TCL_ERROR;
  // The thesis's command language (docs/thesis-compat.md), in every mode, so
  // that the thesis's scripts run unchanged.
  return sourceLibrary(interp, "::sf::thesis", "SANDFLOW_COMPAT_DIR", SANDFLOW_COMPAT_DIR, "compat",
                       "thesis.tcl", "the thesis layer's Tcl files");
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
    code = sourceLibrary(interp, "::sf::gui", "SANDFLOW_GUI_DIR", SANDFLOW_GUI_DIR, "gui",
                         "main.tcl", "the workbench's Tcl files");
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

// Safe mode: this interpreter only makes the safe one (tcl/safe/safe.tcl),
// into which sandflow is loaded through Sandflow_SafeInit.
int runSafe(const char* argv0, int argc, char** argv) {
  const char* outdir = ".";
  if (argc >= 2 && std::strcmp(argv[0], "-outdir") == 0) {
    outdir = argv[1];
    argc -= 2;
    argv += 2;
  }
  if (argc < 1) {
    std::fprintf(stderr, "usage: %s -safe ?-outdir DIR? script.tcl ?arg ...?\n", argv0);
    return 2;
  }
  Tcl_Interp* interp = Tcl_CreateInterp();
  Tcl_StaticPackage(nullptr, "sandflow", Sandflow_Init, Sandflow_SafeInit);
  int code = Tcl_Init(interp);
  if (code == TCL_OK)
    code = sourceLibrary(interp, "::sf::safe", "SANDFLOW_SAFE_DIR", SANDFLOW_SAFE_DIR, "safe",
                         "safe.tcl", "safe mode's Tcl files");
  if (code == TCL_OK)
    code = evalWords(interp, {"::sf::findLibrary", "SANDFLOW_COMPAT_DIR", SANDFLOW_COMPAT_DIR,
                              "compat", "thesis.tcl", "the thesis layer's Tcl files"});
  if (code == TCL_OK) {
    Tcl_Obj* cmd = Tcl_NewListObj(0, nullptr);
    Tcl_Obj* args = Tcl_NewListObj(0, nullptr);
    for (int i = 1; i < argc; ++i)
      Tcl_ListObjAppendElement(nullptr, args, Tcl_NewStringObj(argv[i], -1));
    for (Tcl_Obj* w :
         {Tcl_NewStringObj("::sf::safe::run", -1), Tcl_NewStringObj(outdir, -1),
          Tcl_DuplicateObj(Tcl_GetObjResult(interp)), Tcl_NewStringObj(argv[0], -1), args})
      Tcl_ListObjAppendElement(nullptr, cmd, w);
    Tcl_IncrRefCount(cmd);
    code = Tcl_EvalObjEx(interp, cmd, TCL_EVAL_GLOBAL);
    Tcl_DecrRefCount(cmd);
  }
  const bool failed = code != TCL_OK || std::strcmp(Tcl_GetStringResult(interp), "0") != 0;
  if (code != TCL_OK) {
    const char* info = Tcl_GetVar(interp, "errorInfo", TCL_GLOBAL_ONLY);
    std::fprintf(stderr, "%s\n", info ? info : Tcl_GetStringResult(interp));
  }
  Tcl_Eval(interp, failed ? "exit 1" : "exit 0");  // exit handlers finish the recordings
  return failed ? 1 : 0;
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
  if (argc >= 2 && std::strcmp(argv[1], "-safe") == 0) return runSafe(argv[0], argc - 2, argv + 2);
  Tcl_Main(argc, argv, appInit);
  return 0;
}
