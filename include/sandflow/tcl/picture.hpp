#pragma once
// Pictures for the Tcl layer: the view options as Tcl options (shared by
// `view configure`, `snapshot` and `output movie`) and off-screen rendering
// through the back-end module this process loads.
#include <tcl.h>

#include <string>

#include "sandflow/render/draw_list.hpp"
#include "sandflow/render/view_options.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::tcl {

// Parses view options from objv[first..objc) into `v`. With `offscreen` non-null
// the option -offscreen is accepted too (view configure only). Scene-independent
// checks run here; false with the Tcl error set on the first problem.
bool parseViewOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                      render::ViewOptions& v, std::string* offscreen);
// "-field velocity -vectors 0 ..." as a list, or one option's value (nullptr if
// the name is not a view option; the Tcl error is then set).
Tcl_Obj* viewOptionList(const render::ViewOptions& v, const std::string& offscreen);
Tcl_Obj* viewOptionValue(Tcl_Interp* interp, Tcl_Obj* name, const render::ViewOptions& v,
                         const std::string& offscreen);
// The synopsis lines of the view options, for help texts.
std::string viewOptionHelp(bool withOffscreen);
// `view options`: the option table, one dict per option.
Tcl_Obj* viewOptionTable();

// The back end a process uses: "auto" (OSMesa, else EGL), "osmesa" or "egl".
// It can change only until the first picture loads a module.
std::string offscreenChoice();
void setOffscreenChoice(const std::string& choice);  // throws sf::Error once loaded
std::string loadedOffscreen();                       // "" until a picture is taken

// A draw list drawn off-screen, read back as it is. Throws sf::Error.
render::Image renderOffscreen(const render::DrawList& list);
// The scene under `v`, drawn off-screen (2x supersampled). Throws sf::Error.
render::Image takePicture(const sim::Manager& m, const render::ViewOptions& v);

// A draw list drawn into the OpenGL context current on this thread (the
// workbench's view). Throws sf::Error, also when the loaded module cannot draw
// into another library's context (OSMesa).
void drawIntoCurrentContext(const render::DrawList& list);

}  // namespace sf::tcl
