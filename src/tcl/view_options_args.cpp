// The view options as Tcl options: -field -vectors -streamlines -range
// -colorby -materialcolors -bonds -forces -label -size -region (-offscreen).
#include <cmath>

#include "sandflow/render/colormap.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/picture.hpp"

namespace sf::tcl {
namespace {

enum Opt {
  kField,
  kVectors,
  kStreamlines,
  kRange,
  kColorBy,
  kMaterialColors,
  kFill,
  kBonds,
  kForces,
  kLabel,
  kSize,
  kRegion,
  kOffscreen,
  kOptionCount
};

const OptionSpec kOptions[] = {
    {"-field", "none|nodes|solid|density|pressure|velocity|vorticity",
     "lattice field under the colour map ({}: velocity with a lattice, else none)"},
    {"-vectors", "0|1", "velocity arrows on a sub-sampled grid"},
    {"-streamlines", "0|1", "streamlines of the velocity field"},
    {"-range", "{lo hi}", "the colour map's range ({}: the values shown)"},
    {"-colorby", "none|speed|mass|bond", "element fill: material colour, or a colour map"},
    {"-materialcolors", "{name #rrggbb ...}", "fill colours of materials (else a palette)"},
    {"-fill", "0|1", "elements filled (0: outlines only, the cells under them show)"},
    {"-bonds", "0|1", "intact bonds as lines, breaks as crosses"},
    {"-forces", "0|1", "contact force chains, width proportional to force"},
    {"-label", "0|1", "time and step in the top corner"},
    {"-size", "{W H}", "picture size in pixels"},
    {"-region", "{x0 y0 x1 y1}", "world window ({}: the lattice, else the elements)"},
    {"-offscreen", "auto|osmesa|egl", "headless OpenGL back end (before the first picture)"},
    {nullptr, nullptr, nullptr}};

const char* const kOffscreenNames[] = {"auto", "osmesa", "egl", nullptr};

bool isEmpty(Tcl_Obj* obj) {
  int length = 0;
  Tcl_GetStringFromObj(obj, &length);
  return length == 0;
}

bool getSize(Tcl_Interp* interp, Tcl_Obj* obj, int& w, int& h) {
  Tcl_Obj** items = nullptr;
  int n = 0;
  if (Tcl_ListObjGetElements(interp, obj, &n, &items) != TCL_OK) return false;
  if (n != 2)
    return reject(interp, "VALUE SIZE",
                  std::string("-size must be {W H}, got \"") + Tcl_GetString(obj) + "\"");
  if (!getInt(interp, items[0], "-size", w) || !getInt(interp, items[1], "-size", h)) return false;
  return true;
}

Tcl_Obj* doubles(const double* v, int n) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (int k = 0; k < n; ++k) Tcl_ListObjAppendElement(nullptr, list, newDouble(v[k]));
  return list;
}

Tcl_Obj* boolean(bool b) {
  return Tcl_NewIntObj(b ? 1 : 0);
}

Tcl_Obj* valueOf(const render::ViewOptions& v, int k, const std::string& offscreen) {
  switch (k) {
    case kField:
      return v.field ? Tcl_NewStringObj(render::fieldNames[int(*v.field)], -1) : Tcl_NewObj();
    case kVectors:
      return boolean(v.vectors);
    case kStreamlines:
      return boolean(v.streamlines);
    case kRange:
      return v.range ? doubles(v.range->data(), 2) : Tcl_NewObj();
    case kColorBy:
      return Tcl_NewStringObj(render::colorByNames[int(v.colorBy)], -1);
    case kMaterialColors: {
      Tcl_Obj* dict = Tcl_NewDictObj();
      for (const auto& [name, colour] : v.materialColors)
        Tcl_DictObjPut(nullptr, dict, newString(name), newString(render::formatColor(colour)));
      return dict;
    }
    case kFill:
      return boolean(v.fill);
    case kBonds:
      return boolean(v.bonds);
    case kForces:
      return boolean(v.forces);
    case kLabel:
      return boolean(v.label);
    case kSize: {
      Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
      Tcl_ListObjAppendElement(nullptr, list, Tcl_NewIntObj(v.width));
      Tcl_ListObjAppendElement(nullptr, list, Tcl_NewIntObj(v.height));
      return list;
    }
    case kRegion:
      return v.region ? doubles(v.region->data(), 4) : Tcl_NewObj();
    default:
      return newString(offscreen);
  }
}

}  // namespace

bool parseViewOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                      render::ViewOptions& v, std::string* offscreen) {
  // Stage into a copy: a refused option changes nothing.
  render::ViewOptions staged = v;
  std::string stagedOffscreen = offscreen ? *offscreen : std::string();
  const bool ok = parseOptions(interp, objc, objv, first, kOptions, [&](int k, Tcl_Obj* val) {
    int choice = 0;
    switch (k) {
      case kField:
        if (isEmpty(val)) {
          staged.field.reset();
          return true;
        }
        if (!getChoice(interp, val, "field", render::fieldNames, choice)) return false;
        staged.field = render::Field(choice);
        return true;
      case kVectors:
        return getBool(interp, val, "-vectors", staged.vectors);
      case kStreamlines:
        return getBool(interp, val, "-streamlines", staged.streamlines);
      case kRange: {
        if (isEmpty(val)) {
          staged.range.reset();
          return true;
        }
        std::vector<double> r;
        if (!getDoubles(interp, val, "-range", 2, r)) return false;
        staged.range = std::array<double, 2>{r[0], r[1]};
        return true;
      }
      case kColorBy:
        if (!getChoice(interp, val, "colorby", render::colorByNames, choice)) return false;
        staged.colorBy = render::ColorBy(choice);
        return true;
      case kMaterialColors: {
        Tcl_Obj** items = nullptr;
        int n = 0;
        if (Tcl_ListObjGetElements(interp, val, &n, &items) != TCL_OK) return false;
        if (n % 2 != 0)
          return reject(interp, "VALUE COLOR",
                        "-materialcolors must be a dict {name #rrggbb ...}, got an odd count");
        std::map<std::string, render::Rgb> colours;
        for (int i = 0; i < n; i += 2) {
          const auto c = render::parseColor(Tcl_GetString(items[i + 1]));
          if (!c)
            return reject(interp, "VALUE COLOR",
                          std::string("bad colour \"") + Tcl_GetString(items[i + 1]) +
                              "\" for material \"" + Tcl_GetString(items[i]) +
                              "\": must be #rrggbb or #rgb");
          colours[Tcl_GetString(items[i])] = *c;
        }
        staged.materialColors = std::move(colours);
        return true;
      }
      case kFill:
        return getBool(interp, val, "-fill", staged.fill);
      case kBonds:
        return getBool(interp, val, "-bonds", staged.bonds);
      case kForces:
        return getBool(interp, val, "-forces", staged.forces);
      case kLabel:
        return getBool(interp, val, "-label", staged.label);
      case kSize:
        return getSize(interp, val, staged.width, staged.height);
      case kRegion: {
        if (isEmpty(val)) {
          staged.region.reset();
          return true;
        }
        std::vector<double> r;
        if (!getDoubles(interp, val, "-region", 4, r)) return false;
        staged.region = std::array<double, 4>{r[0], r[1], r[2], r[3]};
        return true;
      }
      default:
        if (!offscreen)
          return reject(interp, "VALUE OPTION",
                        "-offscreen is set with view configure, before the first picture");
        if (!getChoice(interp, val, "offscreen", kOffscreenNames, choice)) return false;
        stagedOffscreen = kOffscreenNames[choice];
        return true;
    }
  });
  if (!ok) return false;
  const int code = guarded(interp, [&] {
    render::checkOptions(staged);
    return TCL_OK;
  });
  if (code != TCL_OK) return false;
  v = std::move(staged);
  if (offscreen) *offscreen = stagedOffscreen;
  return true;
}

Tcl_Obj* viewOptionList(const render::ViewOptions& v, const std::string& offscreen) {
  Tcl_Obj* all = Tcl_NewListObj(0, nullptr);
  for (int k = 0; k < kOptionCount; ++k) {
    Tcl_ListObjAppendElement(nullptr, all, Tcl_NewStringObj(kOptions[k].name, -1));
    Tcl_ListObjAppendElement(nullptr, all, valueOf(v, k, offscreen));
  }
  return all;
}

Tcl_Obj* viewOptionValue(Tcl_Interp* interp, Tcl_Obj* name, const render::ViewOptions& v,
                         const std::string& offscreen) {
  const int k = optionIndex(interp, name, kOptions);
  if (k < 0) return nullptr;
  return valueOf(v, k, offscreen);
}

std::string viewOptionHelp(bool withOffscreen) {
  std::string text;
  for (int k = 0; k < kOptionCount; ++k) {
    if (k == kOffscreen && !withOffscreen) continue;
    text += std::string("  ") + kOptions[k].name + " " + kOptions[k].synopsis + "\n      " +
            kOptions[k].help + "\n";
  }
  return text;
}

}  // namespace sf::tcl
