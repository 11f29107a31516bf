// The `sandflow` command.
//   sandflow                  interactive Tcl prompt with the sandflow commands
//   sandflow script.tcl ...   runs the script headless; argv/argc as in tclsh
//   sandflow -c 'commands' ...  runs the commands and prints a non-empty result
#include <tcl.h>

#include <cstdio>
#include <cstring>

#include "sandflow/tcl/session.hpp"

namespace {

int appInit(Tcl_Interp* interp) {
  if (Tcl_Init(interp) != TCL_OK) return TCL_ERROR;
  if (Sandflow_Init(interp) != TCL_OK) return TCL_ERROR;
  Tcl_StaticPackage(interp, "sandflow", Sandflow_Init, nullptr);
  Tcl_SetVar(interp, "tcl_rcFileName", "~/.sandflowrc", TCL_GLOBAL_ONLY);
  return Tcl_Eval(interp, "namespace import ::sf::*; ::sf::shareSource");
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
  Tcl_Main(argc, argv, appInit);
  return 0;
}
