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
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

using SeriesSpec = io::PlotSeriesSpec;
using ReferenceSpec = io::PlotReference;
using AxisRange = io::PlotRange;
using PlotOptions = io::PlotOptions;

constexpr const char* kStyles[] = {"lines", "points", "linespoints", nullptr};
constexpr const char* kDashes[] = {"solid", "dashed", "dotted", "dashdot", nullptr};
constexpr const char* kAxes[] = {"y", "y2", nullptr};
constexpr const char* kKeys[] = {"topleft", "topright", "bottomleft", "bottomright",
                                 "off",     "outside",  nullptr};
constexpr const char* kReferenceKinds[] = {"constant", "power", nullptr};
constexpr const char* kReferenceForms[] = {"constant C", "power C X0 P"};
constexpr int kReferenceNumbers[] = {1, 3};
constexpr int kMaxPixels = 20000;

// The option tables: the plot's, and those of one -series and one -reference
// value (after its column or numbers). Defined below the parsers they use.
const OptionTable<SeriesSpec>& seriesOptions();
const OptionTable<ReferenceSpec>& referenceOptions();
const OptionTable<PlotOptions>& plotOptions();

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
  return seriesOptions().apply(interp, n, items, 1, spec);
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
  return referenceOptions().apply(interp, n, items, 1 + numbers, spec);
}

// -xrange / -yrange {LO HI}: numbers or *, LO below HI.
bool parseRange(Tcl_Interp* interp, Tcl_Obj* v, const char* option, AxisRange& range) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  const std::string bad = std::string(option) + " must be {LO HI}, each a number or *, got \"" +
                          Tcl_GetString(v) + "\"";
  if (Tcl_ListObjGetElements(nullptr, v, &n, &items) != TCL_OK || n != 2)
    return reject(interp, "VALUE RANGE", bad);
  AxisRange r;
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

// A choice row over an int, or an optional<int> shown as {} until given.
template <class Draft, class Index>
Option<Draft> choiceRow(OptionInfo info, Index Draft::*member) {
  info.kind = ValueKind::choice;
  return {.info = info,
          .get =
              [member](const Draft& d) {
                if constexpr (std::is_same_v<Index, int>)
                  return choiceValue(d.*member);
                else
                  return d.*member ? choiceValue(*(d.*member)) : emptyValue();
              },
          .set = [member](Draft& d, const OptionValue& v) { d.*member = v.choice; }};
}

std::string markSizeRange(double size) {
  return "-marksize must be > 0 and at most 10, got \"" + formatNumber(size) + "\"";
}

const OptionTable<SeriesSpec>& seriesOptions() {
  static const OptionTable<SeriesSpec> table{
      parsedRow<SeriesSpec>({.name = "-file",
                             .synopsis = "CSVFILE",
                             .help = "the CSV file it comes from",
                             .defaultText = "the plot's CSVFILE"},
                            [](Tcl_Interp* interp, Tcl_Obj* v, SeriesSpec& spec) {
                              spec.file = Tcl_GetString(v);
                              return !spec.file->empty() ||
                                     reject(interp, "VALUE FILE", "-file must not be empty");
                            }),
      memberRow({.name = "-x",
                 .synopsis = "COL",
                 .help = "its horizontal column",
                 .defaultText = "the one named like the plot's -x column"},
                &SeriesSpec::x),
      memberRow({.name = "-title",
                 .synopsis = "S",
                 .help = "its title in the key",
                 .defaultText = "the column"},
                &SeriesSpec::title),
      choiceRow({.name = "-style",
                 .synopsis = "lines|points|linespoints",
                 .help = "how it is drawn",
                 .choices = kStyles,
                 .defaultText = "the plot's -style"},
                &SeriesSpec::style),
      choiceRow({.name = "-dash",
                 .synopsis = "solid|dashed|dotted|dashdot",
                 .help = "its line",
                 .choices = kDashes},
                &SeriesSpec::dash),
      choiceRow({.name = "-axis",
                 .synopsis = "y|y2",
                 .help = "the vertical axis it is plotted against",
                 .choices = kAxes},
                &SeriesSpec::axis),
      choiceRow({.name = "-color",
                 .synopsis = "red|green|blue|orange|grey|black|purple|brown|cyan",
                 .help = "its colour",
                 .choices = io::kPlotColors,
                 .defaultText = "the next of gnuplot's"},
                &SeriesSpec::color),
      choiceRow({.name = "-mark",
                 .synopsis = "circle|square|triangle|downtriangle|diamond|open...|cross",
                 .help = "its mark when drawn with points",
                 .choices = io::kPlotMarks,
                 .defaultText = "the next: filled, then open"},
                &SeriesSpec::mark),
      Option<SeriesSpec>{.info = {.name = "-marksize",
                                  .synopsis = "S",
                                  .help = "its mark's size, 0 < S <= 10",
                                  .range = {.min = 0, .max = 10, .minOpen = true},
                                  .outOfRange = markSizeRange,
                                  .defaultText = "1.2 up to 50 rows, else 0.6"},
                         .get =
                             [](const SeriesSpec& d) {
                               return d.marksize ? realValue(*d.marksize) : emptyValue();
                             },
                         .set = [](SeriesSpec& d, const OptionValue& v) { d.marksize = v.real; }},
  };
  return table;
}

const OptionTable<ReferenceSpec>& referenceOptions() {
  static const OptionTable<ReferenceSpec> table{
      memberRow({.name = "-title",
                 .synopsis = "S",
                 .help = "its title in the key",
                 .defaultText = "its formula"},
                &ReferenceSpec::title),
      choiceRow({.name = "-dash",
                 .synopsis = "solid|dashed|dotted|dashdot",
                 .help = "its line",
                 .choices = kDashes},
                &ReferenceSpec::dash),
      choiceRow({.name = "-axis",
                 .synopsis = "y|y2",
                 .help = "the vertical axis it is drawn against",
                 .choices = kAxes},
                &ReferenceSpec::axis),
  };
  return table;
}

// -size {W H}: whole numbers of pixels, 1 to kMaxPixels each.
bool parseSize(Tcl_Interp* interp, Tcl_Obj* v, PlotOptions& o) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
  const std::string bad = std::string("-size must be {W H} with whole numbers of pixels 1 to ") +
                          std::to_string(kMaxPixels) + ", got \"" + Tcl_GetString(v) + "\"";
  if (n != 2) return reject(interp, "VALUE SIZE", bad);
  int w = 0, h = 0;
  if (!getInt(interp, items[0], "-size", w) || !getInt(interp, items[1], "-size", h)) return false;
  if (w < 1 || h < 1 || w > kMaxPixels || h > kMaxPixels) return reject(interp, "VALUE SIZE", bad);
  o.width = w, o.height = h;
  return true;
}

template <std::optional<std::vector<std::string>> PlotOptions::*member>
bool parseColumns(Tcl_Interp* interp, Tcl_Obj* v, PlotOptions& o) {
  return getColumns(interp, v, member == &PlotOptions::y ? "-y" : "-y2", o.*member);
}

template <AxisRange PlotOptions::*member>
bool parseAxisRange(Tcl_Interp* interp, Tcl_Obj* v, PlotOptions& o) {
  return parseRange(interp, v, member == &PlotOptions::xrange ? "-xrange" : "-yrange", o.*member);
}

const OptionTable<PlotOptions>& plotOptions() {
  static const OptionTable<PlotOptions> table{
      memberRow({.name = "-x",
                 .synopsis = "COL",
                 .help = "column of the horizontal axis",
                 .defaultText = "time if there is one, else the first"},
                &PlotOptions::x),
      parsedRow<PlotOptions>(
          {.name = "-y",
           .synopsis = "COLS",
           .help = "columns to plot",
           .defaultText = "all but step, the -x and the -y2 columns; none with -series"},
          parseColumns<&PlotOptions::y>),
      parsedRow<PlotOptions>(
          {.name = "-y2",
           .synopsis = "COLS",
           .help = "columns to plot against a second vertical axis, on the right"},
          parseColumns<&PlotOptions::y2>),
      parsedRow<PlotOptions>(
          {.name = "-series",
           .synopsis = "{YCOL ?-option value ...?}",
           .help = "one more series, from this file or another (repeatable; -file -x "
                   "-title -style -dash -axis -color -mark -marksize)"},
          [](Tcl_Interp* interp, Tcl_Obj* v, PlotOptions& o) {
            return parseSeries(interp, v, o.series.emplace_back());
          }),
      parsedRow<PlotOptions>(
          {.name = "-reference",
           .synopsis = "{constant C | power C X0 P ?-option value ...?}",
           .help = "a reference line, C or C (x/X0)^P (repeatable; -title -dash -axis)"},
          [](Tcl_Interp* interp, Tcl_Obj* v, PlotOptions& o) {
            return parseReference(interp, v, o.references.emplace_back());
          }),
      memberRow({.name = "-title", .synopsis = "S", .help = "title above the plot"},
                &PlotOptions::title),
      memberRow({.name = "-xlabel",
                 .synopsis = "S",
                 .help = "label of the horizontal axis",
                 .defaultText = "the -x column"},
                &PlotOptions::xlabel),
      memberRow({.name = "-ylabel",
                 .synopsis = "S",
                 .help = "label of the vertical axis",
                 .defaultText = "the column, when there is one"},
                &PlotOptions::ylabel),
      memberRow({.name = "-y2label",
                 .synopsis = "S",
                 .help = "label of the right axis",
                 .defaultText = "the column, when there is one"},
                &PlotOptions::y2label),
      memberRow({.name = "-logx",
                 .synopsis = "0|1",
                 .help = "logarithmic horizontal axis (all its values must be > 0)"},
                &PlotOptions::logx),
      memberRow({.name = "-logy",
                 .synopsis = "0|1",
                 .help = "logarithmic vertical axis (all plotted values must be > 0)"},
                &PlotOptions::logy),
      memberRow(
          {.name = "-xreverse", .synopsis = "0|1", .help = "horizontal axis from right to left"},
          &PlotOptions::xreverse),
      parsedRow<PlotOptions>({.name = "-xrange",
                              .synopsis = "{LO HI}",
                              .help = "range of the horizontal axis, * for automatic",
                              .defaultText = "{* *}"},
                             parseAxisRange<&PlotOptions::xrange>),
      parsedRow<PlotOptions>({.name = "-yrange",
                              .synopsis = "{LO HI}",
                              .help = "range of the vertical axis, * for automatic",
                              .defaultText = "{* *}"},
                             parseAxisRange<&PlotOptions::yrange>),
      choiceRow({.name = "-key",
                 .synopsis = "topleft|topright|bottomleft|bottomright|off|outside",
                 .help = "where the key goes, boxed",
                 .choices = kKeys,
                 .defaultText = "top right, none for a single series; outside: right of the plot"},
                &PlotOptions::key),
      parsedRow<PlotOptions>({.name = "-size",
                              .synopsis = "{W H}",
                              .help = "image size in pixels",
                              .defaultText = "{640 480}"},
                             parseSize),
      choiceRow({.name = "-style",
                 .synopsis = "lines|points|linespoints",
                 .help = "how each column is drawn",
                 .choices = kStyles},
                &PlotOptions::style),
  };
  return table;
}

// What a log axis refuses before any file is read: a range or a reference
// that reaches 0 or below.
int checkLogAxes(Tcl_Interp* interp, const PlotOptions& o) {
  const struct {
    bool log;
    const AxisRange& range;
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
  static const std::string help = plotOptions().help(
      "plot", {"OUT.png CSVFILE ?-option value ...?   -> OUT.png", "help"}, PlotOptions{});
  if (answerHelp(interp, objc, objv, help)) return TCL_OK;
  if (objc < 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "OUT.png CSVFILE ?-option value ...?");
    return TCL_ERROR;
  }
  const std::string out = Tcl_GetString(objv[1]);
  const std::string path = Tcl_GetString(objv[2]);
  if (out.empty()) return fail(interp, "VALUE FILE", "OUT.png must not be empty");
  PlotOptions o;
  if (!plotOptions().apply(interp, objc, objv, 3, o)) return TCL_ERROR;
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
