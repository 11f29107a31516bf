// The view options as Tcl options: -field -vectors -streamlines -range
// -colorby -materialcolors -fill -bonds -forces -label -grid -axes -scalebar
// -size -region (-offscreen).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "sandflow/render/colormap.hpp"
#include "sandflow/render/scene_builder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/picture.hpp"

namespace sf::tcl {
namespace {

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

// {} or N numbers into `out`.
template <std::size_t N>
bool getOptionalDoubles(Tcl_Interp* interp, Tcl_Obj* obj, const char* what,
                        std::optional<std::array<double, N>>& out) {
  if (isEmpty(obj)) {
    out.reset();
    return true;
  }
  std::vector<double> r;
  if (!getDoubles(interp, obj, what, int(N), r)) return false;
  out.emplace();
  std::copy(r.begin(), r.end(), out->begin());
  return true;
}

bool getMaterialColors(Tcl_Interp* interp, Tcl_Obj* val, render::ViewOptions& v) {
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
  v.materialColors = std::move(colours);
  return true;
}

// What view configure, snapshot and output movie set, staged.
struct ViewDraft {
  render::ViewOptions v;
  std::string offscreen;
  bool withOffscreen = false;  // view configure only
};

// A boolean row of the view.
Option<ViewDraft> flag(const char* name, const char* help, bool render::ViewOptions::*field) {
  return {{name, "0|1", help, ValueKind::boolean},
          [field](const ViewDraft& s) { return booleanValue(s.v.*field); },
          [field](ViewDraft& s, const OptionValue& x) { s.v.*field = x.boolean; }};
}

using Row = Option<ViewDraft>;
const OptionTable<ViewDraft> kOptions{
    Row{.info = {.name = "-field",
                 .synopsis = "none|nodes|solid|density|pressure|velocity|vorticity",
                 .help =
                     "lattice field under the colour map ({}: velocity with a lattice, else none)",
                 .kind = ValueKind::choice,
                 .choices = render::fieldNames,
                 .what = "field",
                 .orEmpty = true},
        .get =
            [](const ViewDraft& s) {
              return s.v.field ? OptionValue{.choice = int(*s.v.field)}
                               : OptionValue{.empty = true};
            },
        .set =
            [](ViewDraft& s, const OptionValue& x) {
              if (x.empty)
                s.v.field.reset();
              else
                s.v.field = render::Field(x.choice);
            }},
    flag("-vectors", "velocity arrows on a sub-sampled grid", &render::ViewOptions::vectors),
    flag("-streamlines", "streamlines of the velocity field", &render::ViewOptions::streamlines),
    Row{.info = {.name = "-range",
                 .synopsis = "{lo hi}",
                 .help = "the colour map's range ({}: the values shown)",
                 .kind = ValueKind::custom},
        .parse = [](Tcl_Interp* interp, Tcl_Obj* x,
                    ViewDraft& s) { return getOptionalDoubles(interp, x, "-range", s.v.range); },
        .show =
            [](const ViewDraft& s) {
              return s.v.range ? doubles(s.v.range->data(), 2) : Tcl_NewObj();
            }},
    Row{.info = {.name = "-colorby",
                 .synopsis = "none|speed|mass|bond",
                 .help = "element fill: material colour, or a colour map",
                 .kind = ValueKind::choice,
                 .choices = render::colorByNames,
                 .what = "colorby"},
        .get = [](const ViewDraft& s) { return OptionValue{.choice = int(s.v.colorBy)}; },
        .set = [](ViewDraft& s, const OptionValue& x) { s.v.colorBy = render::ColorBy(x.choice); }},
    Row{.info = {.name = "-materialcolors",
                 .synopsis = "{name #rrggbb ...}",
                 .help = "fill colours of materials (else a palette)",
                 .kind = ValueKind::custom},
        .parse = [](Tcl_Interp* interp, Tcl_Obj* x,
                    ViewDraft& s) { return getMaterialColors(interp, x, s.v); },
        .show =
            [](const ViewDraft& s) {
              Tcl_Obj* dict = Tcl_NewDictObj();
              for (const auto& [name, colour] : s.v.materialColors)
                Tcl_DictObjPut(nullptr, dict, newString(name),
                               newString(render::formatColor(colour)));
              return dict;
            }},
    flag("-fill", "elements filled (0: outlines only, the cells under them show)",
         &render::ViewOptions::fill),
    flag("-bonds", "intact bonds as lines, breaks as crosses", &render::ViewOptions::bonds),
    flag("-forces", "contact force chains, width proportional to force",
         &render::ViewOptions::forces),
    flag("-label", "time and step in the top corner", &render::ViewOptions::label),
    flag("-grid", "grid lines at a round spacing", &render::ViewOptions::grid),
    flag("-axes", "the axes x = 0 and y = 0, coordinates along the edges",
         &render::ViewOptions::axes),
    flag("-scalebar", "a bar of a round length, bottom right", &render::ViewOptions::scalebar),
    Row{.info = {.name = "-size",
                 .synopsis = "{W H}",
                 .help = "picture size in pixels",
                 .kind = ValueKind::custom},
        .parse = [](Tcl_Interp* interp, Tcl_Obj* x,
                    ViewDraft& s) { return getSize(interp, x, s.v.width, s.v.height); },
        .show =
            [](const ViewDraft& s) {
              Tcl_Obj* wh[2] = {Tcl_NewIntObj(s.v.width), Tcl_NewIntObj(s.v.height)};
              return Tcl_NewListObj(2, wh);
            }},
    Row{.info = {.name = "-region",
                 .synopsis = "{x0 y0 x1 y1}",
                 .help = "world window ({}: the lattice, else the elements)",
                 .kind = ValueKind::custom},
        .parse = [](Tcl_Interp* interp, Tcl_Obj* x,
                    ViewDraft& s) { return getOptionalDoubles(interp, x, "-region", s.v.region); },
        .show =
            [](const ViewDraft& s) {
              return s.v.region ? doubles(s.v.region->data(), 4) : Tcl_NewObj();
            }},
    Row{.info = {.name = "-offscreen",
                 .synopsis = "auto|osmesa|egl",
                 .help = "headless OpenGL back end (before the first picture)",
                 .kind = ValueKind::custom},
        .parse =
            [](Tcl_Interp* interp, Tcl_Obj* x, ViewDraft& s) {
              if (!s.withOffscreen)
                return reject(interp, "VALUE OPTION",
                              "-offscreen is set with view configure, before the first picture");
              int choice = 0;
              if (!getChoice(interp, x, "offscreen", kOffscreenNames, choice)) return false;
              s.offscreen = kOffscreenNames[choice];
              return true;
            },
        .show = [](const ViewDraft& s) { return newString(s.offscreen); }},
};
constexpr int kOffscreen = 15;

const ViewDraft& defaults() {
  static const ViewDraft d{render::ViewOptions{}, "auto", true};
  return d;
}

}  // namespace

bool parseViewOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], int first,
                      render::ViewOptions& v, std::string* offscreen) {
  // Stage into a copy: a refused option changes nothing.
  ViewDraft draft{v, offscreen ? *offscreen : std::string(), offscreen != nullptr};
  if (!kOptions.apply(interp, objc, objv, first, draft)) return false;
  const int code = guarded(interp, [&] {
    render::checkOptions(draft.v);
    return TCL_OK;
  });
  if (code != TCL_OK) return false;
  v = std::move(draft.v);
  if (offscreen) *offscreen = draft.offscreen;
  return true;
}

Tcl_Obj* viewOptionList(const render::ViewOptions& v, const std::string& offscreen) {
  return kOptions.all(ViewDraft{v, offscreen, true});
}

Tcl_Obj* viewOptionValue(Tcl_Interp* interp, Tcl_Obj* name, const render::ViewOptions& v,
                         const std::string& offscreen) {
  const int k = optionIndex(interp, name, kOptions.specs());
  if (k < 0) return nullptr;
  return kOptions.get(ViewDraft{v, offscreen, true}, k);
}

std::string viewOptionHelp(bool withOffscreen) {
  std::string text;
  for (int k = 0; k < kOptions.size(); ++k) {
    if (k == kOffscreen && !withOffscreen) continue;
    const OptionInfo& o = kOptions.info(k);
    text += std::string("  ") + o.name + " " + o.synopsis + "\n      " + o.help + "\n";
  }
  return text;
}

Tcl_Obj* viewOptionTable() {
  return kOptions.describe(defaults());
}

}  // namespace sf::tcl
