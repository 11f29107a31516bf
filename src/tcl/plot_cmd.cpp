// plot OUT.png CSVFILE ?options?: a PNG line plot of columns of a CSV file
// (what output csv and record write), drawn by gnuplot (pngcairo); -series
// adds columns of other files, -reference lines of a function of x.
//
// The data gnuplot plots is what this command read and checked: it goes into
// the script as one datablock per series, so gnuplot never opens a CSV file
// itself. A reference reaches gnuplot as numbers formatted here, in an
// expression this file writes (referenceExpression), never as user text. Text
// (titles, labels, column names, the output path) goes in single-quoted
// gnuplot strings, where neither backquotes nor macros are expanded (see
// gnuplotString). The PNG is written under a temporary
// name in OUT's folder and renamed into place only when gnuplot succeeded.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

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
     "-axis)"},
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
    {"-key", "topleft|topright|bottomleft|bottomright|off",
     "where the key goes, boxed (default top right, none for a single series)"},
    {"-size", "{W H}", "image size in pixels (default {640 480})"},
    {"-style", "lines|points|linespoints", "how each column is drawn (default lines)"},
    {nullptr, nullptr, nullptr}};

// Options of one -series value, after its column.
enum SeriesOpt { sFile, sX, sTitle, sStyle, sDash, sAxis };
const OptionSpec kSeriesOptions[] = {
    {"-file", "CSVFILE", "the CSV file it comes from (default the plot's CSVFILE)"},
    {"-x", "COL", "its horizontal column (default the one named like the plot's -x column)"},
    {"-title", "S", "its title in the key (default the column)"},
    {"-style", "lines|points|linespoints", "how it is drawn (default the plot's -style)"},
    {"-dash", "solid|dashed|dotted|dashdot", "its line (default solid)"},
    {"-axis", "y|y2", "the vertical axis it is plotted against (default y)"},
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
constexpr const char* kKeys[] = {"topleft",     "topright", "bottomleft",
                                 "bottomright", "off",      nullptr};
constexpr const char* kKeyPositions[] = {"top left", "top right", "bottom left", "bottom right"};
constexpr const char* kReferenceKinds[] = {"constant", "power", nullptr};
constexpr const char* kReferenceForms[] = {"constant C", "power C X0 P"};
constexpr int kReferenceNumbers[] = {1, 3};
constexpr int kMaxPixels = 20000;

// A series as the options give it: a column of a file, against another.
struct SeriesSpec {
  std::string y;
  std::optional<std::string> file, x, title;
  std::optional<int> style;
  int dash = 0, axis = 0;
};

// A function of x drawn as a reference line: only numbers go into gnuplot's
// expression, formatted here (see referenceExpression).
struct ReferenceSpec {
  int kind = 0;  // kReferenceKinds
  double c = 0, x0 = 1, p = 1;
  std::string text;  // as given, for messages
  std::optional<std::string> title;
  int dash = 1, axis = 0;
};

// An axis range; an empty bound is automatic.
struct Range {
  std::optional<double> lo, hi;
};

struct PlotOptions {
  std::optional<std::string> x, title, xlabel, ylabel, y2label;
  std::optional<std::vector<std::string>> y, y2;
  std::vector<SeriesSpec> series;
  std::vector<ReferenceSpec> references;
  bool logx = false, logy = false, xreverse = false;
  Range xrange, yrange;
  std::optional<int> key;
  int width = 640, height = 480;
  int style = 0;
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

// A CSV file as text: the header's names and each data row with its line number.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
};

Csv readCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("IO OPEN", "cannot read \"" + path + "\": " + std::strerror(errno));
  Csv csv;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty()) continue;
    std::vector<std::string> fields = splitFields(line);
    if (csv.names.empty()) {
      csv.names = std::move(fields);
      continue;
    }
    if (fields.size() != csv.names.size())
      throw Error("VALUE CSV", "line " + std::to_string(number) + " of \"" + path + "\" has " +
                                   std::to_string(fields.size()) + " values, the header " +
                                   std::to_string(csv.names.size()) + " columns");
    csv.rows.push_back(std::move(fields));
    csv.lines.push_back(number);
  }
  if (in.bad()) throw Error("IO READ", "reading \"" + path + "\" failed");
  if (csv.names.empty()) throw Error("VALUE CSV", "\"" + path + "\" is empty: no header line");
  if (csv.rows.empty()) throw Error("VALUE CSV", "\"" + path + "\" has a header but no data rows");
  return csv;
}

// The Tcl-style message for a column that is not in the header.
std::string badColumn(const std::string& name, const std::vector<std::string>& names,
                      const std::string& file = "") {
  std::string message =
      "bad column \"" + name + "\"" + (file.empty() ? "" : " in \"" + file + "\"") + ": must be ";
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) message += names.size() > 2 ? ", " : " ";
    if (k > 0 && k + 1 == names.size()) message += "or ";
    message += names[k];
  }
  return message;
}

// A column's index; `file` is named in the message when it is not the plot's
// CSVFILE `main`.
int columnIndex(const Csv& csv, const std::string& name, const std::string& file = "",
                const std::string& main = "") {
  for (std::size_t k = 0; k < csv.names.size(); ++k)
    if (csv.names[k] == name) return int(k);
  if (file != main) throw Error("LOOKUP COLUMN", badColumn(name, csv.names, file));
  throw Error("LOOKUP COLUMN", badColumn(name, csv.names));
}

// A gnuplot string expression that stands for `text`: runs of other characters
// in single quotes (where nothing is expanded), joined by "." to a "'" piece
// for each quote and a "\n" piece for each line break (gnuplot reads a string
// that starts with '' as empty, so quotes are not doubled); other control
// characters become spaces.
std::string gnuplotString(const std::string& text) {
  std::vector<std::string> pieces;
  std::string run;
  auto endRun = [&] {
    if (!run.empty()) pieces.push_back("'" + run + "'");
    run.clear();
  };
  for (char c : text) {
    if (c == '\'' || c == '\n') {
      endRun();
      pieces.push_back(c == '\'' ? "\"'\"" : "\"\\n\"");
    } else {
      run += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  endRun();
  if (pieces.empty()) return "''";
  std::string out = pieces[0];
  for (std::size_t k = 1; k < pieces.size(); ++k) {
    out += '.';
    out += pieces[k];
  }
  return out;
}

// The full path of an executable on PATH, or "" when there is none.
std::string findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t start = 0;
  for (;;) {
    const std::size_t colon = dirs.find(':', start);
    std::string candidate = dirs.substr(start, colon - start);
    if (candidate.empty()) candidate += '.';
    candidate += '/';
    candidate += name;
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string::npos) return "";
    start = colon + 1;
  }
}

// A new, empty file beside `out` (same folder, so that rename is atomic).
std::string makeTemporary(const std::string& out) {
  const std::size_t slash = out.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : out.substr(0, slash + 1);
  const std::string tail = slash == std::string::npos ? out : out.substr(slash + 1);
  std::string name = dir + "." + tail + ".XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw Error("IO OPEN", "cannot write \"" + out + "\": " + std::strerror(errno));
  const mode_t mask = ::umask(0);  // the mode an ordinary new file gets
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  return name;
}

// One series resolved: its file read and its columns found.
struct Series {
  const Csv* csv;
  std::string path;
  int x, y;
  std::string title;
  int style, dash, axis;
};

// A number as gnuplot reads it: always a real (gnuplot's 1/2 is 0), in parentheses.
std::string gnuplotNumber(double v) {
  std::string text = formatNumber(v);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return "(" + text + ")";
}

// The reference's function of x, built from its numbers only.
std::string referenceExpression(const ReferenceSpec& r) {
  if (r.kind == 0) return gnuplotNumber(r.c);
  return gnuplotNumber(r.c) + "*(x/" + gnuplotNumber(r.x0) + ")**" + gnuplotNumber(r.p);
}

// Its default title: the formula, as a person writes it.
std::string referenceTitle(const ReferenceSpec& r) {
  if (r.kind == 0) return formatNumber(r.c);
  return formatNumber(r.c) + " (x / " + formatNumber(r.x0) + ")^" + formatNumber(r.p);
}

// Checks a series' columns and writes them as the gnuplot datablock $dK.
std::string dataBlock(const Series& s, std::size_t k, const PlotOptions& o) {
  std::string block = "$d" + std::to_string(k) + " << EOD\n";
  const Csv& csv = *s.csv;
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    for (int axis = 0; axis < 2; ++axis) {
      const int column = axis == 0 ? s.x : s.y;
      const std::string& text = csv.rows[r][column];
      const std::string where = "column \"" + csv.names[column] + "\", line " +
                                std::to_string(csv.lines[r]) + " of \"" + s.path + "\"";
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v))
        throw Error("VALUE CSV", "\"" + text + "\" in " + where + " is not a finite number");
      const bool log = axis == 0 ? o.logx : o.logy && s.axis == 0;
      if (log && v <= 0)
        throw Error("VALUE LOG", std::string(axis == 0 ? "-logx" : "-logy") +
                                     " needs values > 0, but " + where + " is " + text +
                                     " (gnuplot would leave it out)");
      if (axis > 0) block += ' ';
      block += formatNumber(v);
    }
    block += '\n';
  }
  return block + "EOD\n";
}

std::string rangeText(const Range& r, bool reverse) {
  auto bound = [](const std::optional<double>& b) { return b ? formatNumber(*b) : "*"; };
  if (reverse && r.lo && r.hi) return "[" + bound(r.hi) + ":" + bound(r.lo) + "]";
  return "[" + bound(r.lo) + ":" + bound(r.hi) + "]" + (reverse ? " reverse" : "");
}

// Filled circle, square, triangles, diamond, then the same open: a series
// drawn with points can be told apart without colour.
constexpr int kPointTypes[] = {7, 5, 9, 11, 13, 6, 4, 8, 10, 12};
// Reference lines are grey, so that they read as guides, not data.
constexpr const char* kReferenceGreys[] = {"gray40", "gray65", "gray25", "gray80"};

std::string gnuplotScript(const std::vector<Series>& series, const std::string& xname,
                          const PlotOptions& o, const std::string& temporary) {
  // Enhanced text for the numbers only (1×10^6 on a log axis): every text item
  // is noenhanced, so that ^ _ @ { } in titles are drawn as they are.
  std::string s = "set terminal pngcairo enhanced size " + std::to_string(o.width) + "," +
                  std::to_string(o.height) + "\n";
  s += "set output " + gnuplotString(temporary) + "\n";
  for (std::size_t k = 0; k < series.size(); ++k) s += dataBlock(series[k], k, o);
  if (o.title) s += "set title " + gnuplotString(*o.title) + " noenhanced\n";
  s += "set xlabel " + gnuplotString(o.xlabel.value_or(xname)) + " noenhanced\n";
  // An axis's default label is its column when only one series uses it.
  const std::string* only[2] = {nullptr, nullptr};
  int count[2] = {0, 0};
  for (const Series& one : series)
    if (++count[one.axis] == 1) only[one.axis] = &one.csv->names[one.y];
  if (o.ylabel)
    s += "set ylabel " + gnuplotString(*o.ylabel) + " noenhanced\n";
  else if (count[0] == 1)
    s += "set ylabel " + gnuplotString(*only[0]) + " noenhanced\n";
  bool y2 = count[1] > 0;
  for (const ReferenceSpec& r : o.references) y2 = y2 || r.axis == 1;
  if (y2) {
    s += "set y2tics\nset ytics nomirror\n";
    if (o.y2label)
      s += "set y2label " + gnuplotString(*o.y2label) + " noenhanced\n";
    else if (count[1] == 1)
      s += "set y2label " + gnuplotString(*only[1]) + " noenhanced\n";
  }
  s += "set key noenhanced\n";
  if (o.key && *o.key < 4)
    s += std::string("set key ") + kKeyPositions[*o.key] + " box opaque\n";
  else if (o.key || series.size() + o.references.size() == 1)
    s += "set key off\n";
  if (o.logx) s += "set logscale x\n";
  if (o.logy) s += "set logscale y\n";
  if (o.xreverse || o.xrange.lo || o.xrange.hi)
    s += "set xrange " + rangeText(o.xrange, o.xreverse) + "\n";
  if (o.yrange.lo || o.yrange.hi) s += "set yrange " + rangeText(o.yrange, false) + "\n";
  s += "set grid\n";
  s += "plot ";
  auto axes = [](int axis) { return axis == 1 ? " axes x1y2" : ""; };
  auto dash = [](int d) { return " dt " + std::to_string(d + 1); };
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& one = series[k];
    if (k > 0) s += ", \\\n     ";
    // Few points get larger marks: a convergence study has five, a time series hundreds.
    const std::string mark = " pt " + std::to_string(kPointTypes[k % std::size(kPointTypes)]) +
                             (one.csv->rows.size() <= 50 ? " ps 1.2" : " ps 0.6");
    s += "$d" + std::to_string(k) + " using 1:2" + axes(one.axis) + " with ";
    if (one.style == 0) s += "lines lw 1.5" + dash(one.dash);
    if (one.style == 1) s += "points" + mark;
    if (one.style == 2) s += "linespoints lw 1.5" + dash(one.dash) + mark;
    s += " title " + gnuplotString(one.title) + " noenhanced";
  }
  for (std::size_t k = 0; k < o.references.size(); ++k) {
    const ReferenceSpec& r = o.references[k];
    s += ", \\\n     " + referenceExpression(r) + axes(r.axis) + " with lines lw 1.5" +
         dash(r.dash) + " lc rgb '" + kReferenceGreys[k % std::size(kReferenceGreys)] + "' title " +
         gnuplotString(r.title.value_or(referenceTitle(r))) + " noenhanced";
  }
  return s + "\n";
}

// Runs gnuplot on the script through Tcl's exec; on failure returns gnuplot's
// messages.
bool runGnuplot(Tcl_Interp* interp, const std::string& program, const std::string& script,
                std::string& messages) {
  Tcl_Obj* words[] = {Tcl_NewStringObj("::exec", -1), newString(program),
                      Tcl_NewStringObj("<<", -1), newString(script), Tcl_NewStringObj("2>@1", -1)};
  for (Tcl_Obj* w : words) Tcl_IncrRefCount(w);
  const int code = Tcl_EvalObjv(interp, 5, words, TCL_EVAL_GLOBAL);
  for (Tcl_Obj* w : words) Tcl_DecrRefCount(w);
  messages = Tcl_GetStringResult(interp);
  Tcl_ResetResult(interp);
  return code == TCL_OK;
}

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
  const std::string program = findProgram("gnuplot");
  if (program.empty())
    return fail(interp, "RESOURCE GNUPLOT",
                "plot needs gnuplot, which is not on the PATH: install it (Debian package "
                "gnuplot-nox)");
  const Session& s = sessionOf(data);
  return guarded(interp, [&] {
    requireConfined(s, out);
    requireConfined(s, path);
    // Rows being recorded are in the file already: recorders flush each row.
    // Each file is read once, however many series it gives.
    std::map<std::string, Csv> files;
    files.emplace(path, readCsv(path));
    const Csv& csv = files.at(path);
    const bool hasTime = std::find(csv.names.begin(), csv.names.end(), "time") != csv.names.end();
    const int x = columnIndex(csv, o.x.value_or(hasTime ? "time" : csv.names[0]));
    std::vector<Series> series;
    auto add = [&](const Csv& from, const std::string& file, int xcol, int ycol,
                   const std::optional<std::string>& title, std::optional<int> style, int dash,
                   int axis) {
      series.push_back({&from, file, xcol, ycol, title.value_or(from.names[ycol]),
                        style.value_or(o.style), dash, axis});
    };
    std::vector<int> y2;
    if (o.y2)
      for (const std::string& name : *o.y2) y2.push_back(columnIndex(csv, name));
    if (o.y) {
      for (const std::string& name : *o.y) add(csv, path, x, columnIndex(csv, name), {}, {}, 0, 0);
    } else if (o.series.empty()) {
      for (int k = 0; k < int(csv.names.size()); ++k)
        if (k != x && csv.names[k] != "step" && std::find(y2.begin(), y2.end(), k) == y2.end())
          add(csv, path, x, k, {}, {}, 0, 0);
    }
    for (int k : y2) add(csv, path, x, k, {}, {}, 0, 1);
    if (series.empty() && o.series.empty())
      throw Error("VALUE COLUMNS",
                  "\"" + path + "\" has no column to plot against \"" + csv.names[x] + "\"");
    for (const SeriesSpec& spec : o.series) {
      const std::string file = spec.file.value_or(path);
      auto found = files.find(file);
      if (found == files.end()) {
        requireConfined(s, file);
        found = files.emplace(file, readCsv(file)).first;
      }
      const Csv& from = found->second;
      const int xcol = columnIndex(from, spec.x.value_or(csv.names[x]), file, path);
      const int ycol = columnIndex(from, spec.y, file, path);
      add(from, file, xcol, ycol, spec.title, spec.style, spec.dash, spec.axis);
    }
    const std::string temporary = makeTemporary(out);
    std::string messages;
    try {
      const std::string script = gnuplotScript(series, csv.names[x], o, temporary);
      if (!runGnuplot(interp, program, script, messages))
        throw Error("IO GNUPLOT", "gnuplot failed: " + trim(messages));
      struct stat st;
      if (::stat(temporary.c_str(), &st) != 0 || st.st_size == 0)
        throw Error("IO GNUPLOT", "gnuplot wrote no image: " + trim(messages));
      if (std::rename(temporary.c_str(), out.c_str()) != 0)
        throw Error("IO WRITE", "cannot write \"" + out + "\": " + std::strerror(errno));
    } catch (...) {
      std::remove(temporary.c_str());
      throw;
    }
    Tcl_SetObjResult(interp, newString(out));
    return TCL_OK;
  });
}

}  // namespace

void registerPlotCommand(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::plot", Plot, session, nullptr);
}

}  // namespace sf::tcl
