#pragma once
// A PNG line plot of CSV columns, drawn by gnuplot (pngcairo): what `plot`
// draws, without Tcl.
//
// The data gnuplot plots is what was read and checked here: it goes into the
// script as one datablock per series, so gnuplot never opens a CSV file
// itself. A reference reaches gnuplot as numbers formatted here, never as
// user text. Text (titles, labels, column names, the output path) goes in
// single-quoted gnuplot strings, where neither backquotes nor macros are
// expanded (gnuplotString). Errors are sf::Error.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sandflow/io/csv_table.hpp"

namespace sf::io {

// Choices are indices, in the order the plot command lists them:
// style lines|points|linespoints, dash solid|dashed|dotted|dashdot, axis y|y2,
// key topleft|topright|bottomleft|bottomright|off|outside, reference
// constant|power, colour and mark as kPlotColors and kPlotMarks list them.

// A series' colour and mark by name (the names the plot command takes).
inline constexpr const char* kPlotColors[] = {"red",   "green",  "blue",  "orange", "grey",
                                              "black", "purple", "brown", "cyan",   nullptr};
inline constexpr const char* kPlotMarks[] = {
    "circle",     "square",       "triangle",         "downtriangle", "diamond", "opencircle",
    "opensquare", "opentriangle", "opendowntriangle", "opendiamond",  "cross",   nullptr};

// An axis range; an empty bound is automatic.
struct PlotRange {
  std::optional<double> lo, hi;
};

// A series as the options give it: a column of a file, against another.
struct PlotSeriesSpec {
  std::string y;
  std::optional<std::string> file, x, title;
  std::optional<int> style, color, mark;
  std::optional<double> marksize;
  int dash = 0, axis = 0;
};

// A reference line: C (kind 0) or C (x/X0)^P (kind 1).
struct PlotReference {
  int kind = 0;
  double c = 0, x0 = 1, p = 1;
  std::string text;  // as given, for messages
  std::optional<std::string> title;
  int dash = 1, axis = 0;
};

struct PlotOptions {
  std::optional<std::string> x, title, xlabel, ylabel, y2label;
  std::optional<std::vector<std::string>> y, y2;
  std::vector<PlotSeriesSpec> series;
  std::vector<PlotReference> references;
  bool logx = false, logy = false, xreverse = false;
  PlotRange xrange, yrange;
  std::optional<int> key;
  int width = 640, height = 480;
  int style = 0;
};

// One series resolved: its file read and its columns found.
struct PlotSeries {
  const CsvTable* csv;
  std::string path;
  int x, y;
  std::string title;
  int style, dash, axis;
  std::optional<int> color = {}, mark = {};  // kPlotColors, kPlotMarks; default by order
  std::optional<double> marksize = {};       // default by the number of rows
};

// A gnuplot string expression that stands for `text`, expanding nothing.
std::string gnuplotString(const std::string& text);

// The whole script: terminal, output `output`, one datablock per series (its
// values checked: finite, > 0 on a log axis), labels, key, ranges, plot.
std::string gnuplotScript(const std::vector<PlotSeries>& series, const std::string& xname,
                          const PlotOptions& o, const std::string& output);

// Draws the plot of CSV file `path` into `out` with the gnuplot at `program`.
// `mayRead` is called with each other file a -series names before it is
// read, and may throw. The PNG is written under a temporary name in out's
// folder and renamed into place only when gnuplot succeeded.
void plotCsv(const std::string& program, const std::string& out, const std::string& path,
             const PlotOptions& o, const std::function<void(const std::string&)>& mayRead);

}  // namespace sf::io
