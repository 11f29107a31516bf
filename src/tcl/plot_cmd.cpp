// plot OUT.png CSVFILE ?options?: a PNG line plot of columns of a CSV file
// (what output csv and record write), drawn by gnuplot (pngcairo); -series
// adds columns of other files, -reference lines of a function of x. This file
// reads the options and checks what it can before any file is read; reading,
// the gnuplot script and running gnuplot are io::plotCsv's
// (include/sandflow/io/gnuplot.hpp).
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "sandflow/io/find_program.hpp"
#include "sandflow/io/gnuplot.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

enum Opt {
  oX,
  oY,
  oY2,
  oSeries,
  oReference,
  oTitle,
  oXlabel,
  oYlabel,
  oY2label,
  oLogx,
  oLogy,
  oXreverse,
  oXrange,
  oYrange,
  oKey,
  oSize,
  oStyle
};

const OptionSpec kPlotOptions[] = {
    {"-x", "COL", "column of the horizontal axis (default time if there is one, else the first)"},
    {"-y", "COLS",
     "columns to plot (default all but step, the -x and the -y2 columns; none with -series)"},
    {"-y2", "COLS", "columns to plot against a second vertical axis, on the right"},
    {"-series", "{YCOL ?-option value ...?}",
     "one more series, from this file or another (repeatable; -file -x -title -style -dash "
     "-axis -color -mark -marksize)"},
    {"-reference", "{constant C | power C X0 P ?-option value ...?}",
     "a reference line, C or C (x/X0)^P (repeatable; -title -dash -axis)"},
    {"-title", "S", "title above the plot (default none)"},
    {"-xlabel", "S", "label of the horizontal axis (default the -x column)"},
    {"-ylabel", "S", "label of the vertical axis (default the column, when there is one)"},
    {"-y2label", "S", "label of the right axis (default the column, when there is one)"},
    {"-logx", "0|1", "logarithmic horizontal axis (all its values must be > 0)"},
    {"-logy", "0|1", "logarithmic vertical axis (all plotted values must be > 0)"},
    {"-xreverse", "0|1", "horizontal axis from right to left"},
    {"-xrange", "{LO HI}", "range of the horizontal axis, * for automatic (default {* *})"},
    {"-yrange", "{LO HI}", "range of the vertical axis, * for automatic (default {* *})"},
    {"-key", "topleft|topright|bottomleft|bottomright|off|outside",
     "where the key goes, boxed (default top right, none for a single series; outside: right "
     "of the plot)"},
    {"-size", "{W H}", "image size in pixels (default {640 480})"},
    {"-style", "lines|points|linespoints", "how each column is drawn (default lines)"},
    {nullptr, nullptr, nullptr}};

// Options of one -series value, after its column.
enum SeriesOpt { sFile, sX, sTitle, sStyle, sDash, sAxis, sColor, sMark, sMarksize };
const OptionSpec kSeriesOptions[] = {
    {"-file", "CSVFILE", "the CSV file it comes from (default the plot's CSVFILE)"},
    {"-x", "COL", "its horizontal column (default the one named like the plot's -x column)"},
    {"-title", "S", "its title in the key (default the column)"},
    {"-style", "lines|points|linespoints", "how it is drawn (default the plot's -style)"},
    {"-dash", "solid|dashed|dotted|dashdot", "its line (default solid)"},
    {"-axis", "y|y2", "the vertical axis it is plotted against (default y)"},
    {"-color", "red|green|blue|orange|grey|black|purple|brown|cyan",
     "its colour (default the next of gnuplot's)"},
    {"-mark", "circle|square|triangle|downtriangle|diamond|open...|cross",
     "its mark when drawn with points (default the next: filled, then open)"},
    {"-marksize", "S", "its mark's size, 0 < S <= 10 (default 1.2 up to 50 rows, else 0.6)"},
    {nullptr, nullptr, nullptr}};

// Options of one -reference value, after its numbers.
enum ReferenceOpt { rTitle, rDash, rAxis };
const OptionSpec kReferenceOptions[] = {
    {"-title", "S", "its title in the key (default its formula)"},
    {"-dash", "solid|dashed|dotted|dashdot", "its line (default dashed)"},
    {"-axis", "y|y2", "the vertical axis it is drawn against (default y)"},
    {nullptr, nullptr, nullptr}};

constexpr const char* kStyles[] = {"lines", "points", "linespoints", nullptr};
constexpr const char* kDashes[] = {"solid", "dashed", "dotted", "dashdot", nullptr};
constexpr const char* kAxes[] = {"y", "y2", nullptr};
constexpr const char* kKeys[] = {"topleft", "topright", "bottomleft", "bottomright",
                                 "off",     "outside",  nullptr};
constexpr const char* kReferenceKinds[] = {"constant", "power", nullptr};
constexpr const char* kReferenceForms[] = {"constant C", "power C X0 P"};
constexpr int kReferenceNumbers[] = {1, 3};
constexpr int kMaxPixels = 20000;

using SeriesSpec = io::PlotSeriesSpec;
using ReferenceSpec = io::PlotReference;
using Range = io::PlotRange;
using PlotOptions = io::PlotOptions;

bool getColumns(Tcl_Interp* interp, Tcl_Obj* v, const char* option,
                std::optional<std::vector<std::string>>& out) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
  if (n == 0) return reject(interp, "VALUE COLUMNS", std::string(option) + " is empty");
  out.emplace();
  for (int i = 0; i < n; ++i) out->push_back(Tcl_GetString(items[i]));
  return true;
}

// -series {YCOL ?-option value ...?}
bool parseSeries(Tcl_Interp* interp, Tcl_Obj* v, SeriesSpec& spec) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
  if (n == 0)
    return reject(interp, "VALUE SERIES",
                  "-series must be {YCOL ?-option value ...?}, got \"" +
                      std::string(Tcl_GetString(v)) + "\"");
  spec.y = Tcl_GetString(items[0]);
  return parseOptions(interp, n, items, 1, kSeriesOptions, [&](int k, Tcl_Obj* value) {
    int index = 0;
    switch (k) {
      case sFile:
        spec.file = Tcl_GetString(value);
        if (spec.file->empty()) return reject(interp, "VALUE FILE", "-file must not be empty");
        return true;
      case sX:
        spec.x = Tcl_GetString(value);
        return true;
      case sTitle:
        spec.title = Tcl_GetString(value);
        return true;
      case sStyle:
        if (!getChoice(interp, value, "style", kStyles, index)) return false;
        spec.style = index;
        return true;
      case sDash:
        return getChoice(interp, value, "dash", kDashes, spec.dash);
      case sAxis:
        return getChoice(interp, value, "axis", kAxes, spec.axis);
      case sColor:
        if (!getChoice(interp, value, "color", io::kPlotColors, index)) return false;
        spec.color = index;
        return true;
      case sMark:
        if (!getChoice(interp, value, "mark", io::kPlotMarks, index)) return false;
        spec.mark = index;
        return true;
      case sMarksize: {
        double size = 0;
        if (!getDouble(interp, value, "-marksize", size)) return false;
        if (!(size > 0 && size <= 10))
          return reject(interp, "VALUE MARKSIZE",
                        "-marksize must be > 0 and at most 10, got \"" +
                            std::string(Tcl_GetString(value)) + "\"");
        spec.marksize = size;
        return true;
      }
    }
    return false;
  });
}

// -reference {constant C ?-option value ...?} or {power C X0 P ?-option value ...?}
bool parseReference(Tcl_Interp* interp, Tcl_Obj* v, ReferenceSpec& spec) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
  spec.text = Tcl_GetString(v);
  const std::string forms =
      "-reference must be {constant C ?-option value ...?} or {power C X0 "
      "P ?-option value ...?}, got \"" +
      spec.text + "\"";
  if (n == 0) return reject(interp, "VALUE REFERENCE", forms);
  if (!getChoice(interp, items[0], "reference", kReferenceKinds, spec.kind)) return false;
  const int numbers = kReferenceNumbers[spec.kind];
  if (n < 1 + numbers) return reject(interp, "VALUE REFERENCE", forms);
  double* slots[] = {&spec.c, &spec.x0, &spec.p};
  for (int i = 0; i < numbers; ++i)
    if (!getDouble(interp, items[1 + i], "-reference", *slots[i])) return false;
  if (spec.kind == 1 && spec.x0 <= 0)
    return reject(interp, "VALUE REFERENCE",
                  "-reference " + std::string(kReferenceForms[1]) + " needs X0 > 0, got \"" +
                      spec.text + "\"");
  return parseOptions(interp, n, items, 1 + numbers, kReferenceOptions, [&](int k, Tcl_Obj* value) {
    switch (k) {
      case rTitle:
        spec.title = Tcl_GetString(value);
        return true;
      case rDash:
        return getChoice(interp, value, "dash", kDashes, spec.dash);
      case rAxis:
        return getChoice(interp, value, "axis", kAxes, spec.axis);
    }
    return false;
  });
}

// -xrange / -yrange {LO HI}: numbers or *, LO below HI.
bool parseRange(Tcl_Interp* interp, Tcl_Obj* v, const char* option, Range& range) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  const std::string bad = std::string(option) + " must be {LO HI}, each a number or *, got \"" +
                          Tcl_GetString(v) + "\"";
  if (Tcl_ListObjGetElements(nullptr, v, &n, &items) != TCL_OK || n != 2)
    return reject(interp, "VALUE RANGE", bad);
  Range r;
  for (int i = 0; i < 2; ++i) {
    if (std::strcmp(Tcl_GetString(items[i]), "*") == 0) continue;
    double b = 0;
    if (Tcl_GetDoubleFromObj(nullptr, items[i], &b) != TCL_OK || !std::isfinite(b))
      return reject(interp, "VALUE RANGE", bad);
    (i == 0 ? r.lo : r.hi) = b;
  }
  if (r.lo && r.hi && !(*r.lo < *r.hi))
    return reject(interp, "VALUE RANGE",
                  std::string(option) + " needs LO < HI, got \"" + Tcl_GetString(v) + "\"");
  range = r;
  return true;
}

bool parsePlotOptions(Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], PlotOptions& o) {
  return parseOptions(interp, objc, objv, 3, kPlotOptions, [&](int k, Tcl_Obj* v) {
    switch (k) {
      case oX:
        o.x = Tcl_GetString(v);
        return true;
      case oTitle:
        o.title = Tcl_GetString(v);
        return true;
      case oXlabel:
        o.xlabel = Tcl_GetString(v);
        return true;
      case oYlabel:
        o.ylabel = Tcl_GetString(v);
        return true;
      case oY2label:
        o.y2label = Tcl_GetString(v);
        return true;
      case oLogx:
        return getBool(interp, v, "-logx", o.logx);
      case oLogy:
        return getBool(interp, v, "-logy", o.logy);
      case oXreverse:
        return getBool(interp, v, "-xreverse", o.xreverse);
      case oStyle:
        return getChoice(interp, v, "style", kStyles, o.style);
      case oY:
        return getColumns(interp, v, "-y", o.y);
      case oY2:
        return getColumns(interp, v, "-y2", o.y2);
      case oSeries:
        return parseSeries(interp, v, o.series.emplace_back());
      case oReference:
        return parseReference(interp, v, o.references.emplace_back());
      case oXrange:
        return parseRange(interp, v, "-xrange", o.xrange);
      case oYrange:
        return parseRange(interp, v, "-yrange", o.yrange);
      case oKey: {
        int index = 0;
        if (!getChoice(interp, v, "key", kKeys, index)) return false;
        o.key = index;
        return true;
      }
      case oSize: {
        int n = 0;
        Tcl_Obj** items = nullptr;
        if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
        const std::string bad =
            std::string("-size must be {W H} with whole numbers of pixels 1 to ") +
            std::to_string(kMaxPixels) + ", got \"" + Tcl_GetString(v) + "\"";
        if (n != 2) return reject(interp, "VALUE SIZE", bad);
        int w = 0, h = 0;
        if (!getInt(interp, items[0], "-size", w) || !getInt(interp, items[1], "-size", h))
          return false;
        if (w < 1 || h < 1 || w > kMaxPixels || h > kMaxPixels)
          return reject(interp, "VALUE SIZE", bad);
        o.width = w, o.height = h;
        return true;
      }
    }
    return false;
  });
}

// What a log axis refuses before any file is read: a range or a reference
// that reaches 0 or below.
int checkLogAxes(Tcl_Interp* interp, const PlotOptions& o) {
  const struct {
    bool log;
    const Range& range;
    const char *name, *option;
  } axes[] = {{o.logx, o.xrange, "-logx", "-xrange"}, {o.logy, o.yrange, "-logy", "-yrange"}};
  for (const auto& a : axes) {
    if (!a.log) continue;
    for (const std::optional<double>& b : {a.range.lo, a.range.hi})
      if (b && *b <= 0)
        return fail(interp, "VALUE LOG",
                    std::string(a.name) + " needs values > 0, but " + a.option + " reaches " +
                        formatNumber(*b));
  }
  if (o.logy)
    for (const ReferenceSpec& r : o.references)
      if (r.axis == 0 && r.c <= 0)
        return fail(
            interp, "VALUE LOG",
            "-logy needs values > 0, but reference \"" + r.text + "\" is not (its C must be > 0)");
  return TCL_OK;
}

int Plot(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (answerHelp(interp, objc, objv, "plot", {"OUT.png CSVFILE ?-option value ...?   -> OUT.png"},
                 kPlotOptions))
    return TCL_OK;
  if (objc < 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "OUT.png CSVFILE ?-option value ...?");
    return TCL_ERROR;
  }
  const std::string out = Tcl_GetString(objv[1]);
  const std::string path = Tcl_GetString(objv[2]);
  if (out.empty()) return fail(interp, "VALUE FILE", "OUT.png must not be empty");
  PlotOptions o;
  if (!parsePlotOptions(interp, objc, objv, o)) return TCL_ERROR;
  if (checkLogAxes(interp, o) != TCL_OK) return TCL_ERROR;
  const std::string program = io::findProgram("gnuplot");
  if (program.empty())
    return fail(interp, "RESOURCE GNUPLOT",
                "plot needs gnuplot, which is not on the PATH: install it (Debian package "
                "gnuplot-nox)");
  const Session& s = sessionOf(data);
  return guarded(interp, [&] {
    requireConfined(s, out);
    requireConfined(s, path);
    io::plotCsv(program, out, path, o, [&](const std::string& file) { requireConfined(s, file); });
    Tcl_SetObjResult(interp, newString(out));
    return TCL_OK;
  });
}

}  // namespace

void registerPlotCommand(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::plot", Plot, session, nullptr);
}

}  // namespace sf::tcl
