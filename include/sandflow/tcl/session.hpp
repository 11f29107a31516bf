#pragma once
// The state one interpreter's commands share: its own Manager (no globals).
#include <tcl.h>

#include "sandflow/sim/manager.hpp"

namespace sf::tcl {

struct Session {
  Tcl_Interp* interp = nullptr;
  sim::Manager manager;
};

// Passes the Manager's new warnings to the Tcl procedure ::sf::warn.
void flushWarnings(Session& session);

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

}  // namespace sf::tcl

extern "C" int Sandflow_Init(Tcl_Interp* interp);
