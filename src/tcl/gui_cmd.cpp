// The workbench's own commands, in ::sf::gui (not exported; users never need
// them): drawing the scene into the Togl view's context, or into a Tk photo
// where there is no GLX visual, and the hook that keeps the window alive while
// `run` goes on. Tk and Togl stay in Tcl: this file links neither.
#include <cmath>
#include <cstdio>
#include <string>

#include "remedy.hpp"
#include "sandflow/lb/lattice.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/picture.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// The view options of a GUI frame: `view configure`'s, at the widget's size,
// over the world window the user panned and zoomed to ({} for the automatic one).
bool frameOptions(Tcl_Interp* interp, const Session& s, Tcl_Obj* const objv[],
                  render::ViewOptions& v) {
  v = s.view;
  if (!getInt(interp, objv[1], "width", v.width) || !getInt(interp, objv[2], "height", v.height))
    return false;
  if (v.width < 1 || v.height < 1 || v.width > render::kMaxPictureSide ||
      v.height > render::kMaxPictureSide)
    return reject(interp, "VALUE SIZE",
                  "a view of " + std::to_string(v.width) + " x " + std::to_string(v.height) +
                      " pixels: each side must be 1 to " + std::to_string(render::kMaxPictureSide));
  int n = 0;
  if (Tcl_ListObjLength(interp, objv[3], &n) != TCL_OK) return false;
  if (n == 0) return true;
  std::vector<double> r;
  if (!getDoubles(interp, objv[3], "region", 4, r)) return false;
  v.region = std::array<double, 4>{r[0], r[1], r[2], r[3]};
  return true;
}

// The world window in Tk's pixel convention (origin top-left, y down): world
// point (wx0, wy0) is at pixel (px, py); `scale` pixels per unit length.
Tcl_Obj* geometry(const render::WorldWindow& w, int height) {
  Tcl_Obj* origin = Tcl_NewListObj(0, nullptr);
  Tcl_ListObjAppendElement(nullptr, origin, newDouble(w.px0));
  Tcl_ListObjAppendElement(nullptr, origin, newDouble(double(height) - w.py0));
  Tcl_Obj* world = Tcl_NewListObj(0, nullptr);
  Tcl_ListObjAppendElement(nullptr, world, newDouble(w.wx0));
  Tcl_ListObjAppendElement(nullptr, world, newDouble(w.wy0));
  return newDict({{"world", world}, {"pixel", origin}, {"scale", newDouble(w.pixelsPerUnit)}});
}

// Overlay items in world coordinates, each {kind colour x y ...}:
//   box x0 y0 x1 y1 | circle cx cy r | line x y x y ... | closed x y x y ...
// drawn as 2-pixel strokes over the elements (rubber bands, the selection,
// a shape being drawn).
bool addOverlay(Tcl_Interp* interp, Tcl_Obj* items, const render::WorldWindow& w, float width,
                render::DrawList& list) {
  static const char* const kinds[] = {"box", "circle", "line", "closed", nullptr};
  int n = 0;
  Tcl_Obj** item = nullptr;
  if (Tcl_ListObjGetElements(interp, items, &n, &item) != TCL_OK) return false;
  const auto pixel = [&](double x, double y) {
    return render::Point{float(w.px0 + (x - w.wx0) * w.pixelsPerUnit),
                         float(w.py0 + (y - w.wy0) * w.pixelsPerUnit)};
  };
  for (int k = 0; k < n; ++k) {
    int m = 0;
    Tcl_Obj** word = nullptr;
    if (Tcl_ListObjGetElements(interp, item[k], &m, &word) != TCL_OK) return false;
    int kind = 0;
    if (m < 2 || !getChoice(interp, word[0], "overlay item", kinds, kind)) {
      if (m < 2) return reject(interp, "VALUE OVERLAY", "an overlay item is {kind colour x y ...}");
      return false;
    }
    int r = 0, g = 0, b = 0;
    if (std::sscanf(Tcl_GetString(word[1]), "#%2x%2x%2x", &r, &g, &b) != 3)
      return reject(
          interp, "VALUE OVERLAY",
          std::string("bad overlay colour \"") + Tcl_GetString(word[1]) + "\": must be #rrggbb");
    std::vector<double> c(std::size_t(m - 2));
    for (int q = 2; q < m; ++q)
      if (!getDouble(interp, word[q], "overlay", c[std::size_t(q - 2)])) return false;
    const render::Rgba colour{std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255};
    std::vector<render::Point> points;
    bool closed = true;
    if (kind == 0 && c.size() == 4) {
      points = {pixel(c[0], c[1]), pixel(c[2], c[1]), pixel(c[2], c[3]), pixel(c[0], c[3])};
    } else if (kind == 1 && c.size() == 3) {
      for (int q = 0; q < 64; ++q) {
        const double t = 2 * 3.14159265358979323846 * q / 64;
        points.push_back(pixel(c[0] + c[2] * std::cos(t), c[1] + c[2] * std::sin(t)));
      }
    } else if ((kind == 2 || kind == 3) && c.size() >= 2 && c.size() % 2 == 0) {
      for (std::size_t q = 0; q < c.size(); q += 2) points.push_back(pixel(c[q], c[q + 1]));
      closed = kind == 3;
    } else {
      return reject(interp, "VALUE OVERLAY",
                    std::string("wrong number of coordinates for overlay item ") + kinds[kind]);
    }
    const std::size_t last = closed ? points.size() : points.size() - 1;
    for (std::size_t q = 0; q < last; ++q)
      list.worldStrokes.push_back({points[q], points[(q + 1) % points.size()], width, colour});
  }
  return true;
}

// The frame's draw list, s.viewList: built anew, or with `reuse` the last one
// when it was built at this size over this region (only the overlay changed).
bool frameList(Tcl_Interp* interp, Session& s, const render::ViewOptions& v, bool reuse) {
  const bool same =
      reuse && s.viewList && s.viewList->width == v.width && s.viewList->height == v.height;
  if (!same) {
    const int code = guarded(interp, [&] {
      s.viewList = std::make_unique<render::DrawList>(render::buildView(s.manager, v, 1));
      return TCL_OK;
    });
    if (code != TCL_OK) return false;
  }
  return true;
}

// Strokes added to a kept list for one frame, taken off again after it.
struct StrokesAdded {
  std::vector<render::Stroke>& strokes;
  const std::size_t before = strokes.size();
  ~StrokesAdded() { strokes.resize(before); }
};

// ::sf::gui::draw W H REGION ?OVERLAY? ?REUSE? -> geometry: into the current
// GL context.
int Draw(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 4 || objc > 6) {
    Tcl_WrongNumArgs(interp, 1, objv, "width height region ?overlay? ?reuse?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  render::ViewOptions v;
  if (!frameOptions(interp, s, objv, v)) return TCL_ERROR;
  bool reuse = false;
  if (objc == 6 && !getBool(interp, objv[5], "reuse", reuse)) return TCL_ERROR;
  if (!frameList(interp, s, v, reuse)) return TCL_ERROR;
  // The overlay goes onto the kept list for this frame: no copy of the list
  // (its field alone is a texel per pixel of the view).
  render::DrawList& list = *s.viewList;
  const StrokesAdded overlay{list.worldStrokes};
  if (objc >= 5 && !addOverlay(interp, objv[4], list.world, 2.0f, list)) return TCL_ERROR;
  return guarded(interp, [&] {
    drawIntoCurrentContext(list);
    Tcl_SetObjResult(interp, geometry(list.world, v.height));
    return TCL_OK;
  });
}

// ::sf::gui::picture W H REGION ?OVERLAY? -> {ppm geometry}: off-screen, as
// binary PPM data for a Tk photo (the view's fallback without GLX).
int Picture(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 4 || objc > 5) {
    Tcl_WrongNumArgs(interp, 1, objv, "width height region ?overlay?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  render::ViewOptions v;
  if (!frameOptions(interp, s, objv, v)) return TCL_ERROR;
  render::DrawList list;
  int code = guarded(interp, [&] {
    list = render::buildView(s.manager, v, 2);  // supersampled, as snapshots are
    return TCL_OK;
  });
  if (code != TCL_OK) return code;
  // Two pixels wide after the picture is halved, as in the view.
  if (objc == 5 && !addOverlay(interp, objv[4], list.world, 4.0f, list)) return TCL_ERROR;
  return guarded(interp, [&] {
    const render::Image image = render::halve(renderOffscreen(list));
    const std::string header =
        "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    std::string ppm = header;
    ppm.resize(header.size() + std::size_t(image.width) * image.height * 3);
    char* out = ppm.data() + header.size();
    for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
      for (int c = 0; c < 3; ++c) *out++ = char(image.rgba[4 * p + std::size_t(c)]);
    render::WorldWindow w = list.world;  // at scale 1
    w.px0 /= 2;
    w.py0 /= 2;
    w.pixelsPerUnit /= 2;
    Tcl_Obj* result = Tcl_NewListObj(0, nullptr);
    Tcl_ListObjAppendElement(
        nullptr, result,
        Tcl_NewByteArrayObj(reinterpret_cast<const unsigned char*>(ppm.data()), int(ppm.size())));
    Tcl_ListObjAppendElement(nullptr, result, geometry(w, v.height));
    Tcl_SetObjResult(interp, result);
    return TCL_OK;
  });
}

// ::sf::gui::elements -> {id type x y reach ...}: every element's centre and
// bounding radius, for picking and the selection's outline.
int Elements(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const dem::Bodies& b = sessionOf(data).manager.assembly().bodies();
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (int k = 0; k < b.size(); ++k) {
    const std::size_t i = std::size_t(k);
    Tcl_ListObjAppendElement(nullptr, list, Tcl_NewIntObj(b.id[i]));
    Tcl_ListObjAppendElement(nullptr, list,
                             Tcl_NewStringObj(dem::shapeTypeNames[int(b.shape[i]->type())], -1));
    Tcl_ListObjAppendElement(nullptr, list, newDouble(b.x[i].x()));
    Tcl_ListObjAppendElement(nullptr, list, newDouble(b.x[i].y()));
    Tcl_ListObjAppendElement(nullptr, list, newDouble(b.shape[i]->boundingRadius()));
  }
  Tcl_SetObjResult(interp, list);
  return TCL_OK;
}

// ::sf::gui::region -> {x0 y0 x1 y1}: the world window `view configure` shows
// (its -region, else the lattice or the elements): zoom to fit.
int Region(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const Session& s = sessionOf(data);
  const auto r = render::shownRegion(s.manager, s.view);
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (double x : r) Tcl_ListObjAppendElement(nullptr, list, newDouble(x));
  Tcl_SetObjResult(interp, list);
  return TCL_OK;
}

// A hook of `run` as its getter shows it: {script number}.
Tcl_Obj* hookObj(Tcl_Obj* script, Tcl_Obj* number) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  Tcl_ListObjAppendElement(nullptr, list, script ? script : Tcl_NewObj());
  Tcl_ListObjAppendElement(nullptr, list, number);
  return list;
}

// Replaces a hook's script with a copy of `script`; an empty one removes it.
void replaceHook(Tcl_Obj*& hook, Tcl_Obj* script) {
  if (hook) Tcl_DecrRefCount(hook);
  hook = nullptr;
  int length = 0;
  Tcl_GetStringFromObj(script, &length);
  if (length == 0) return;
  hook = Tcl_DuplicateObj(script);
  Tcl_IncrRefCount(hook);
}

// ::sf::gui::runtick ?script ?ms?? : the script `run` evaluates at most every
// ms milliseconds (default 50); an empty script removes it. With no
// arguments: the current {script ms}.
int RunTick(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc > 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "?script ?ms??");
    return TCL_ERROR;
  }
  if (objc == 1) {
    Tcl_SetObjResult(interp, hookObj(s.runTick, Tcl_NewIntObj(s.runTickMs)));
    return TCL_OK;
  }
  int ms = s.runTickMs;
  if (objc == 3) {
    if (!getInt(interp, objv[2], "ms", ms)) return TCL_ERROR;
    if (ms < 1 || ms > 10000)
      return fail(interp, "VALUE TICK",
                  "the tick interval must be 1 to 10000 ms, got " + std::to_string(ms));
  }
  replaceHook(s.runTick, objv[1]);
  s.runTickMs = ms;
  return TCL_OK;
}

// ::sf::gui::runsample ?script ?K?? : the script `run` evaluates after every
// K-th step of a run, counted from its start, whatever the clock (the live
// plot's samples); an empty script or K 0 removes it. With no arguments: the
// current {script K}.
int RunSample(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  if (objc > 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "?script ?K??");
    return TCL_ERROR;
  }
  if (objc == 1) {
    Tcl_SetObjResult(interp, hookObj(s.runSample, Tcl_NewWideIntObj(s.runSampleEvery)));
    return TCL_OK;
  }
  Tcl_WideInt every = s.runSampleEvery;
  if (objc == 3) {
    if (Tcl_GetWideIntFromObj(interp, objv[2], &every) != TCL_OK) return TCL_ERROR;
    if (every < 0)
      return fail(interp, "VALUE EVERY", "K must be >= 0, got " + std::to_string(every));
  }
  replaceHook(s.runSample, objv[1]);
  s.runSampleEvery = every;
  return TCL_OK;
}

// ::sf::gui::progress -> {done total run}: steps of the run in progress (or the
// last), and how many runs have started.
int Progress(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const Session& s = sessionOf(data);
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  Tcl_ListObjAppendElement(nullptr, list, Tcl_NewWideIntObj(s.runDone));
  Tcl_ListObjAppendElement(nullptr, list, Tcl_NewWideIntObj(s.runTotal));
  Tcl_ListObjAppendElement(nullptr, list, Tcl_NewWideIntObj(s.runs));
  Tcl_SetObjResult(interp, list);
  return TCL_OK;
}

// ::sf::gui::statusinfo -> dict step time nodes mlups mach elements warnings:
// what the status bar shows, as `sim info` has it, but with the Mach number
// of the last step (which the step finds anyway) instead of a scan of the
// lattice: a run's tick asks for it every frame, and on a 1024^2 lattice the
// scan took as long as the frame.
int StatusInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const Session& s = sessionOf(data);
  const sim::Manager& m = s.manager;
  const bool lattice = m.hasLattice();
  Tcl_Obj* warnings = Tcl_NewListObj(0, nullptr);
  for (const sim::Warning& w : m.warnings())
    Tcl_ListObjAppendElement(nullptr, warnings, newString(withRemedy(w.text, w.remedy)));
  Tcl_SetObjResult(
      interp, newDict({{"step", Tcl_NewWideIntObj(m.stepCount())},
                       {"time", newDouble(m.time())},
                       {"nodes", Tcl_NewWideIntObj(lattice ? Tcl_WideInt(m.lattice().nodes()) : 0)},
                       {"mlups", newDouble(s.mlups)},
                       {"mach", newDouble(lattice ? m.lattice().lastStepMach() : 0.0)},
                       {"elements", Tcl_NewIntObj(m.assembly().bodies().size())},
                       {"warnings", warnings}}));
  return TCL_OK;
}

// ::sf::gui::running -> 1 while a run is in progress (its tick is serving events).
int Running(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(interp, Tcl_NewBooleanObj(sessionOf(data).running));
  return TCL_OK;
}

}  // namespace

void registerGuiCommands(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::gui::draw", Draw, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::picture", Picture, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::region", Region, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::elements", Elements, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::runtick", RunTick, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::runsample", RunSample, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::running", Running, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::statusinfo", StatusInfo, session, nullptr);
  Tcl_CreateObjCommand(interp, "::sf::gui::progress", Progress, session, nullptr);
}

}  // namespace sf::tcl
