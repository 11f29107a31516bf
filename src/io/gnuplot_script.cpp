// The gnuplot script of a plot: text quoted so that nothing in it is
// expanded, numbers formatted here.
#include <cmath>
#include <cstdlib>
#include <iterator>

#include "sandflow/core/error.hpp"
#include "sandflow/io/gnuplot.hpp"

namespace sf::io {
namespace {

constexpr const char* kKeyPositions[] = {"top left", "top right", "bottom left", "bottom right"};
constexpr int kKeyOff = 4, kKeyOutside = 5;
// Filled circle, square, triangles, diamond, then the same open: a series
// drawn with points can be told apart without colour. A -mark names one of
// these (kPlotMarks' order), or a cross (2).
constexpr int kPointTypes[] = {7, 5, 9, 11, 13, 6, 4, 8, 10, 12, 2};
constexpr int kDefaultMarks = 10;
// kPlotColors' colours.
constexpr const char* kColorValues[] = {"#d62728", "#2ca02c", "#1f77b4", "#ff7f0e", "#8c8c8c",
                                        "#000000", "#9467bd", "#8c564b", "#17becf"};
// Reference lines are grey, so that they read as guides, not data.
constexpr const char* kReferenceGreys[] = {"gray40", "gray65", "gray25", "gray80"};

// A number as gnuplot reads it: always a real (gnuplot's 1/2 is 0), in parentheses.
std::string gnuplotNumber(double v) {
  std::string text = formatNumber(v);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return "(" + text + ")";
}

// The reference's function of x, built from its numbers only.
std::string referenceExpression(const PlotReference& r) {
  if (r.kind == 0) return gnuplotNumber(r.c);
  return gnuplotNumber(r.c) + "*(x/" + gnuplotNumber(r.x0) + ")**" + gnuplotNumber(r.p);
}

// Its default title: the formula, as a person writes it.
std::string referenceTitle(const PlotReference& r) {
  if (r.kind == 0) return formatNumber(r.c);
  return formatNumber(r.c) + " (x / " + formatNumber(r.x0) + ")^" + formatNumber(r.p);
}

// Checks a series' columns and writes them as the gnuplot datablock $dK.
std::string dataBlock(const PlotSeries& s, std::size_t k, const PlotOptions& o) {
  std::string block = "$d" + std::to_string(k) + " << EOD\n";
  const CsvTable& csv = *s.csv;
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

std::string rangeText(const PlotRange& r, bool reverse) {
  auto bound = [](const std::optional<double>& b) { return b ? formatNumber(*b) : "*"; };
  const bool swap = reverse && r.lo && r.hi;  // a reversed range is written high to low
  // (appended piece by piece: "[" + s trips a false -Wrestrict of GCC 12)
  std::string text = "[";
  text += bound(swap ? r.hi : r.lo);
  text += ':';
  text += bound(swap ? r.lo : r.hi);
  text += ']';
  if (reverse && !swap) text += " reverse";
  return text;
}

}  // namespace

// Runs of other characters in single quotes (where nothing is expanded),
// joined by "." to a "'" piece for each quote and a "\n" piece for each line
// break (gnuplot reads a string that starts with '' as empty, so quotes are
// not doubled); other control characters become spaces.
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

std::string gnuplotScript(const std::vector<PlotSeries>& series, const std::string& xname,
                          const PlotOptions& o, const std::string& output) {
  // Enhanced text for the numbers only (1×10^6 on a log axis): every text item
  // is noenhanced, so that ^ _ @ { } in titles are drawn as they are.
  std::string s = "set terminal pngcairo enhanced size " + std::to_string(o.width) + "," +
                  std::to_string(o.height) + "\n";
  s += "set output " + gnuplotString(output) + "\n";
  for (std::size_t k = 0; k < series.size(); ++k) s += dataBlock(series[k], k, o);
  if (o.title) s += "set title " + gnuplotString(*o.title) + " noenhanced\n";
  s += "set xlabel " + gnuplotString(o.xlabel.value_or(xname)) + " noenhanced\n";
  // An axis's default label is its column when only one series uses it.
  const std::string* only[2] = {nullptr, nullptr};
  int count[2] = {0, 0};
  for (const PlotSeries& one : series)
    if (++count[one.axis] == 1) only[one.axis] = &one.csv->names[one.y];
  if (o.ylabel)
    s += "set ylabel " + gnuplotString(*o.ylabel) + " noenhanced\n";
  else if (count[0] == 1)
    s += "set ylabel " + gnuplotString(*only[0]) + " noenhanced\n";
  bool y2 = count[1] > 0;
  for (const PlotReference& r : o.references) y2 = y2 || r.axis == 1;
  if (y2) {
    s += "set y2tics\nset ytics nomirror\n";
    if (o.y2label)
      s += "set y2label " + gnuplotString(*o.y2label) + " noenhanced\n";
    else if (count[1] == 1)
      s += "set y2label " + gnuplotString(*only[1]) + " noenhanced\n";
  }
  s += "set key noenhanced\n";
  if (o.key && *o.key < kKeyOff)
    s += std::string("set key ") + kKeyPositions[*o.key] + " box opaque\n";
  else if (o.key && *o.key == kKeyOutside)
    s += "set key outside right top box\n";
  else if (o.key || series.size() + o.references.size() == 1)
    s += "set key off\n";
  // A log axis's numbers as %g writes them, 1×10^6 typeset (gnuplot's default
  // "% h" writes every tic of a wide log axis with the most decimals, 0.00010).
  if (o.logx) s += "set logscale x\nset format x '%h'\n";
  if (o.logy) s += "set logscale y\nset format y '%h'\n";
  if (o.xreverse || o.xrange.lo || o.xrange.hi)
    s += "set xrange " + rangeText(o.xrange, o.xreverse) + "\n";
  if (o.yrange.lo || o.yrange.hi) s += "set yrange " + rangeText(o.yrange, false) + "\n";
  s += "set grid\n";
  s += "plot ";
  auto axes = [](int axis) { return axis == 1 ? " axes x1y2" : ""; };
  auto dash = [](int d) { return " dt " + std::to_string(d + 1); };
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& one = series[k];
    if (k > 0) s += ", \\\n     ";
    // Few points get larger marks: a convergence study has five, a time series hundreds.
    const double size = one.marksize.value_or(one.csv->rows.size() <= 50 ? 1.2 : 0.6);
    std::string mark = " pt " +
                       std::to_string(kPointTypes[one.mark.value_or(int(k % kDefaultMarks))]) +
                       " ps " + formatNumber(size);
    if (one.color) mark += std::string(" lc rgb '") + kColorValues[*one.color] + "'";
    s += "$d" + std::to_string(k) + " using 1:2" + axes(one.axis) + " with ";
    const std::string color =
        one.color ? std::string(" lc rgb '") + kColorValues[*one.color] + "'" : std::string();
    if (one.style == 0) s += "lines lw 1.5" + dash(one.dash) + color;
    if (one.style == 1) s += "points" + mark;
    if (one.style == 2) s += "linespoints lw 1.5" + dash(one.dash) + mark;  // mark has the colour
    s += " title " + gnuplotString(one.title) + " noenhanced";
  }
  for (std::size_t k = 0; k < o.references.size(); ++k) {
    const PlotReference& r = o.references[k];
    s += ", \\\n     " + referenceExpression(r) + axes(r.axis) + " with lines lw 1.5" +
         dash(r.dash) + " lc rgb '" + kReferenceGreys[k % std::size(kReferenceGreys)] + "' title " +
         gnuplotString(r.title.value_or(referenceTitle(r))) + " noenhanced";
  }
  return s + "\n";
}

}  // namespace sf::io
