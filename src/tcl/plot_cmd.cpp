// plot OUT.png CSVFILE ?options?: a PNG line plot of columns of a CSV file
// (what output csv and record write), drawn by gnuplot (pngcairo).
//
// The data gnuplot plots is what this command read and checked: it goes into
// the script as a datablock, so gnuplot never opens the CSV file itself. Text
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
#include <optional>
#include <string>
#include <vector>

#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

enum Opt { oX, oY, oTitle, oXlabel, oYlabel, oLogx, oLogy, oSize, oStyle };

const OptionSpec kPlotOptions[] = {
    {"-x", "COL", "column of the horizontal axis (default time if there is one, else the first)"},
    {"-y", "COLS", "columns to plot (default all but step and the -x column)"},
    {"-title", "S", "title above the plot (default none)"},
    {"-xlabel", "S", "label of the horizontal axis (default the -x column)"},
    {"-ylabel", "S", "label of the vertical axis (default the column, when there is one)"},
    {"-logx", "0|1", "logarithmic horizontal axis (all its values must be > 0)"},
    {"-logy", "0|1", "logarithmic vertical axis (all plotted values must be > 0)"},
    {"-size", "{W H}", "image size in pixels (default {640 480})"},
    {"-style", "lines|points|linespoints", "how each column is drawn (default lines)"},
    {nullptr, nullptr, nullptr}};

constexpr const char* kStyles[] = {"lines", "points", "linespoints", nullptr};
constexpr int kMaxPixels = 20000;

struct PlotOptions {
  std::optional<std::string> x, title, xlabel, ylabel;
  std::optional<std::vector<std::string>> y;
  bool logx = false, logy = false;
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
std::string badColumn(const std::string& name, const std::vector<std::string>& names) {
  std::string message = "bad column \"" + name + "\": must be ";
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) message += names.size() > 2 ? ", " : " ";
    if (k > 0 && k + 1 == names.size()) message += "or ";
    message += names[k];
  }
  return message;
}

int columnIndex(const Csv& csv, const std::string& name) {
  for (std::size_t k = 0; k < csv.names.size(); ++k)
    if (csv.names[k] == name) return int(k);
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

// Checks the plotted columns and writes them as a gnuplot datablock.
std::string dataBlock(const Csv& csv, const std::string& path, const std::vector<int>& columns,
                      const PlotOptions& o) {
  std::string block = "$data << EOD\n";
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const std::string& text = csv.rows[r][columns[k]];
      const std::string& name = csv.names[columns[k]];
      const std::string where =
          "column \"" + name + "\", line " + std::to_string(csv.lines[r]) + " of \"" + path + "\"";
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v))
        throw Error("VALUE CSV", "\"" + text + "\" in " + where + " is not a finite number");
      const bool log = k == 0 ? o.logx : o.logy;
      if (log && v <= 0)
        throw Error("VALUE LOG", std::string(k == 0 ? "-logx" : "-logy") +
                                     " needs values > 0, but " + where + " is " + text +
                                     " (gnuplot would leave it out)");
      if (k > 0) block += ' ';
      block += formatNumber(v);
    }
    block += '\n';
  }
  return block + "EOD\n";
}

std::string gnuplotScript(const Csv& csv, const std::string& path, const std::vector<int>& columns,
                          const PlotOptions& o, const std::string& temporary) {
  std::string s = "set terminal pngcairo noenhanced size " + std::to_string(o.width) + "," +
                  std::to_string(o.height) + "\n";
  s += "set output " + gnuplotString(temporary) + "\n";
  s += dataBlock(csv, path, columns, o);
  if (o.title) s += "set title " + gnuplotString(*o.title) + "\n";
  s += "set xlabel " + gnuplotString(o.xlabel.value_or(csv.names[columns[0]])) + "\n";
  if (o.ylabel)
    s += "set ylabel " + gnuplotString(*o.ylabel) + "\n";
  else if (columns.size() == 2)
    s += "set ylabel " + gnuplotString(csv.names[columns[1]]) + "\n";
  if (columns.size() == 2) s += "set key off\n";
  if (o.logx) s += "set logscale x\n";
  if (o.logy) s += "set logscale y\n";
  s += "set grid\n";
  static const char* const styles[] = {"lines lw 1.5", "points pt 7 ps 0.6",
                                       "linespoints lw 1.5 pt 7 ps 0.6"};
  s += "plot ";
  for (std::size_t k = 1; k < columns.size(); ++k) {
    if (k > 1) s += ", \\\n     ";
    s += "$data using 1:" + std::to_string(k + 1) + " with " + styles[o.style] + " title " +
         gnuplotString(csv.names[columns[k]]);
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
      case oLogx:
        return getBool(interp, v, "-logx", o.logx);
      case oLogy:
        return getBool(interp, v, "-logy", o.logy);
      case oStyle:
        return getChoice(interp, v, "style", kStyles, o.style);
      case oY: {
        int n = 0;
        Tcl_Obj** items = nullptr;
        if (Tcl_ListObjGetElements(interp, v, &n, &items) != TCL_OK) return false;
        if (n == 0) return reject(interp, "VALUE COLUMNS", "-y is empty");
        o.y.emplace();
        for (int i = 0; i < n; ++i) o.y->push_back(Tcl_GetString(items[i]));
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

int Plot(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 3) {
    Tcl_WrongNumArgs(interp, 1, objv, "OUT.png CSVFILE ?-option value ...?");
    return TCL_ERROR;
  }
  const std::string out = Tcl_GetString(objv[1]);
  const std::string path = Tcl_GetString(objv[2]);
  if (out.empty()) return fail(interp, "VALUE FILE", "OUT.png must not be empty");
  PlotOptions o;
  if (!parsePlotOptions(interp, objc, objv, o)) return TCL_ERROR;
  const std::string program = findProgram("gnuplot");
  if (program.empty())
    return fail(interp, "RESOURCE GNUPLOT",
                "plot needs gnuplot, which is not on the PATH: install it (Debian package "
                "gnuplot-nox)");
  return guarded(interp, [&] {
    // Rows being recorded are in the file already: recorders flush each row.
    const Csv csv = readCsv(path);
    std::vector<int> columns;  // x first, then the y columns
    const bool hasTime = std::find(csv.names.begin(), csv.names.end(), "time") != csv.names.end();
    columns.push_back(columnIndex(csv, o.x.value_or(hasTime ? "time" : csv.names[0])));
    if (o.y) {
      for (const std::string& name : *o.y) columns.push_back(columnIndex(csv, name));
    } else {
      for (int k = 0; k < int(csv.names.size()); ++k)
        if (k != columns[0] && csv.names[k] != "step") columns.push_back(k);
      if (columns.size() == 1)
        throw Error("VALUE COLUMNS", "\"" + path + "\" has no column to plot against \"" +
                                         csv.names[columns[0]] + "\"");
    }
    const std::string temporary = makeTemporary(out);
    std::string messages;
    try {
      const std::string script = gnuplotScript(csv, path, columns, o, temporary);
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
