#pragma once
// The verbs of the "output" ensemble that live in files of their own.
#include <tcl.h>

#include <string>

namespace sf::tcl {

// output vtk PREFIX ?-every K?
int OutputVtk(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]);
// output csv FILE -elements IDS ?-every K?
int OutputCsv(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]);
// output movie FILE ?-every K? ?-fps n? ?view options?
int OutputMovie(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]);
// Their options, for output help: "options:" and a line each, from their tables.
std::string outputVtkOptions();
std::string outputCsvOptions();
std::string outputMovieOptions();

}  // namespace sf::tcl
