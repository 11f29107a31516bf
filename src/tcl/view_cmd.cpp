// view configure|cget|help: what the view and later pictures show;
// snapshot FILE.png ?view options?: one picture of the scene, off-screen.
#include <algorithm>
#include <cctype>

#include "sandflow/io/atomic_files.hpp"
#include "sandflow/render/png.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/picture.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// The back end in effect: the loaded one, else the choice.
std::string offscreenShown() {
  const std::string loaded = loadedOffscreen();
  return loaded.empty() ? offscreenChoice() : loaded;
}

// The view's option table, one dict per option (the property panel).
int ViewOptionsTable(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, viewOptionTable());
  return TCL_OK;
}

int ViewConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc == 1) {
    Tcl_SetObjResult(interp, viewOptionList(s.view, offscreenShown()));
    return TCL_OK;
  }
  if (objc == 2) {
    Tcl_Obj* value = viewOptionValue(interp, objv[1], s.view, offscreenShown());
    if (!value) return TCL_ERROR;
    Tcl_SetObjResult(interp, value);
    return TCL_OK;
  }
  std::string offscreen = offscreenChoice();
  render::ViewOptions staged = s.view;
  if (!parseViewOptions(interp, objc, objv, 1, staged, &offscreen)) return TCL_ERROR;
  const int code = guarded(interp, [&] {
    setOffscreenChoice(offscreen);
    return TCL_OK;
  });
  if (code != TCL_OK) return code;
  s.view = std::move(staged);
  return TCL_OK;
}

int ViewCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "-option");
    return TCL_ERROR;
  }
  Tcl_Obj* value = viewOptionValue(interp, objv[1], sessionOf(data).view, offscreenShown());
  if (!value) return TCL_ERROR;
  Tcl_SetObjResult(interp, value);
  return TCL_OK;
}

// view pixel {x y} ?-option value ...? -> {column row}: where a world point
// lands in a picture (origin at the top-left pixel's corner), for picking and tests.
int ViewPixel(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "{x y} ?-option value ...?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  Vec2 x;
  if (!getVec2(interp, objv[1], "point", x)) return TCL_ERROR;
  render::ViewOptions v = s.view;
  if (!parseViewOptions(interp, objc, objv, 2, v, nullptr)) return TCL_ERROR;
  return guarded(interp, [&] {
    render::checkView(s.manager, v);
    const auto p = render::worldToImage(s.manager, v, x.x(), x.y());
    Tcl_SetObjResult(interp, newVec2(Vec2(p[0], p[1])));
    return TCL_OK;
  });
}

std::string viewHelp() {
  std::string text =
      helpText("view",
               {"configure ?-option value ...?", "cget -option",
                "pixel {x y} ?-option value ...?   -> {column row} in a picture",
                "options -> the options as dicts: name type choices default help ...", "help"},
               nullptr);
  text += "\noptions (also of snapshot and output movie):\n" + viewOptionHelp(true);
  text.pop_back();
  return text;
}

bool endsWithPng(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".png";
}

int Snapshot(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE.png ?-option value ...?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string path = Tcl_GetString(objv[1]);
  if (path == "help" && objc == 2) {
    const std::string text =
        "snapshot FILE.png ?-option value ...?   -> FILE.png\n"
        "options (view configure sets their defaults):\n" +
        viewOptionHelp(false);
    Tcl_SetObjResult(interp, newString(text.substr(0, text.size() - 1)));
    return TCL_OK;
  }
  if (!endsWithPng(path))
    return fail(interp, "VALUE FILE",
                "snapshot writes PNG pictures: FILE must end in .png, got \"" + path + "\"");
  render::ViewOptions v = s.view;
  if (!parseViewOptions(interp, objc, objv, 2, v, nullptr)) return TCL_ERROR;
  const auto t0 = Profile::Clock::now();
  // A run's pictures are one of its stages (sim info passes).
  struct Timed {
    Session& s;
    Profile::Clock::time_point t0;
    ~Timed() {
      if (s.running) s.manager.profile().lap(Stage::pictures, t0);
    }
  } timed{s, t0};
  return guarded(interp, [&] {
    requireConfined(s, path);
    const render::Image image = takePicture(s.manager, v);
    io::writeAtomically({{path, [&](std::ostream& out) {
                            try {
                              render::writePng(image, out);
                            } catch (const Error& e) {
                              throw Error(
                                  e.code(),
                                  "writing \"" + path + "\" failed: " + e.what() + " (disk full?)",
                                  e.remedy());
                            }
                          }}});
    Tcl_SetObjResult(interp, newString(path));
    return TCL_OK;
  });
}

}  // namespace

void registerViewCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::view",
               {{"configure", ViewConfigure},
                {"cget", ViewCget},
                {"pixel", ViewPixel},
                {"options", ViewOptionsTable}},
               session, {.help = viewHelp()});
  Tcl_CreateObjCommand(interp, "::sf::snapshot", Snapshot, session, nullptr);
}

}  // namespace sf::tcl
