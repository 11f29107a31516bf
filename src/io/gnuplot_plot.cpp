// Drawing a plot: the CSV files read once each, the series resolved to their
// columns, gnuplot run on the script, the PNG renamed into place.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "sandflow/core/error.hpp"
#include "sandflow/io/csv_table.hpp"
#include "sandflow/io/gnuplot.hpp"
#include "sandflow/io/run_program.hpp"

namespace sf::io {
namespace {

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

// Runs gnuplot on the script and moves the image it wrote to `temporary` into `out`.
void drawInto(const std::string& program, const std::string& script, const std::string& temporary,
              const std::string& out) {
  const ProgramRun run = runProgram({program}, script);
  if (!run.ok) throw Error("IO GNUPLOT", "gnuplot failed: " + trim(run.output));
  struct stat st;
  if (::stat(temporary.c_str(), &st) != 0 || st.st_size == 0)
    throw Error("IO GNUPLOT", "gnuplot wrote no image: " + trim(run.output));
  if (std::rename(temporary.c_str(), out.c_str()) != 0)
    throw Error("IO WRITE", "cannot write \"" + out + "\": " + std::strerror(errno));
}

}  // namespace

void plotCsv(const std::string& program, const std::string& out, const std::string& path,
             const PlotOptions& o, const std::function<void(const std::string&)>& mayRead) {
  // Rows being recorded are in the file already: recorders flush each row.
  // Each file is read once, however many series it gives.
  std::map<std::string, CsvTable> files;
  files.emplace(path, readCsv(path));
  const CsvTable& csv = files.at(path);
  const bool hasTime = std::find(csv.names.begin(), csv.names.end(), "time") != csv.names.end();
  const int x = columnIndex(csv, o.x.value_or(hasTime ? "time" : csv.names[0]));
  std::vector<PlotSeries> series;
  auto add = [&](const CsvTable& from, const std::string& file, int xcol, int ycol,
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
  } else if (o.series.empty()) {  // all but step, x and the -y2 columns
    for (int k = 0; k < int(csv.names.size()); ++k)
      if (k != x && csv.names[k] != "step" && std::find(y2.begin(), y2.end(), k) == y2.end())
        add(csv, path, x, k, {}, {}, 0, 0);
  }
  for (int k : y2) add(csv, path, x, k, {}, {}, 0, 1);
  if (series.empty() && o.series.empty())
    throw Error("VALUE COLUMNS",
                "\"" + path + "\" has no column to plot against \"" + csv.names[x] + "\"");
  for (const PlotSeriesSpec& spec : o.series) {
    const std::string file = spec.file.value_or(path);
    auto found = files.find(file);
    if (found == files.end()) {
      mayRead(file);
      found = files.emplace(file, readCsv(file)).first;
    }
    const CsvTable& from = found->second;
    const int xcol = columnIndex(from, spec.x.value_or(csv.names[x]), file, path);
    const int ycol = columnIndex(from, spec.y, file, path);
    add(from, file, xcol, ycol, spec.title, spec.style, spec.dash, spec.axis);
    series.back().color = spec.color;
    series.back().mark = spec.mark;
    series.back().marksize = spec.marksize;
  }
  const std::string temporary = makeTemporary(out);
  try {
    drawInto(program, gnuplotScript(series, csv.names[x], o, temporary), temporary, out);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

}  // namespace sf::io
