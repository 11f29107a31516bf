// output csv FILE -elements IDS ?-every K?: an element time series, and the
// CSV writing that it shares with "record".
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "csv_recorder.hpp"
#include "output_verbs.hpp"
#include "sandflow/tcl/args.hpp"

namespace sf::tcl {

CsvRecorder::CsvRecorder(std::string path, int every, std::vector<std::string> columns)
    : Recorder(std::move(path), every), columns_(std::move(columns)) {}

CsvRecorder::~CsvRecorder() {
  if (file_) std::fclose(file_);
}

void CsvRecorder::writeOrThrow(const std::string& text) {
  // One row at a time, flushed: a row is in the file, whole, once record() returns.
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
    throw Error("IO WRITE", std::string("writing failed: ") + std::strerror(errno));
}

void CsvRecorder::record(const Session& s) {
  // The values first: a record that cannot be taken writes nothing.
  scratch_.clear();
  values(s, scratch_);
  std::string row = std::to_string(s.manager.stepCount()) + "," + formatNumber(s.manager.time());
  for (double v : scratch_) {
    row += ',';  // (appending pieces: "," + s trips a false -Wrestrict of GCC 12)
    row += formatNumber(v);
  }
  row += "\n";
  const bool first = !file_;
  if (first && s.resumeStep >= 0 && resume(s.resumeStep)) {
    writeOrThrow(row);
    ++written_;
    return;
  }
  if (first) {
    file_ = std::fopen(path().c_str(), "we");  // close-on-exec: not for ffmpeg or gnuplot
    if (!file_)
      throw Error("IO OPEN", std::string("cannot open it for writing: ") + std::strerror(errno));
    std::string header = "step,time";
    for (const std::string& c : columns_) {
      header += ',';
      header += c;
    }
    row = header + "\n" + row;
  }
  try {
    writeOrThrow(row);
  } catch (const Error&) {
    if (first) {  // no half-made file
      std::fclose(file_);
      file_ = nullptr;
      std::remove(path().c_str());
    }
    throw;
  }
  ++written_;
}

bool CsvRecorder::resume(long long step) {
  std::FILE* f = std::fopen(path().c_str(), "r+e");
  if (!f) return false;  // nothing to continue: a fresh file
  std::string text;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
  std::string header = "step,time";
  for (const std::string& c : columns_) {
    header += ',';
    header += c;
  }
  header += '\n';
  if (std::ferror(f) || text.compare(0, header.size(), header) != 0) {
    std::fclose(f);  // another series, or unreadable: start afresh
    return false;
  }
  // Keep the rows before `step` (a run that went on past the checkpoint wrote
  // the rest); the row for `step` itself comes next.
  std::size_t keep = header.size();
  while (keep < text.size()) {
    const std::size_t end = text.find('\n', keep);
    if (end == std::string::npos || std::atoll(text.c_str() + keep) >= step) break;
    keep = end + 1;
  }
  if (std::fflush(f) != 0 || ftruncate(fileno(f), off_t(keep)) != 0 ||
      std::fseek(f, 0, SEEK_END) != 0) {
    std::fclose(f);
    throw Error("IO WRITE", std::string("cannot continue it: ") + std::strerror(errno));
  }
  file_ = f;
  return true;
}

void CsvRecorder::finish() {
  if (!file_) return;
  const bool flushed = std::fflush(file_) == 0;
  const int error = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed)
    throw Error("IO WRITE",
                std::string("closing failed: ") + std::strerror(flushed ? errno : error));
}

namespace {


// The columns of one element, in order (docs/output.md says what each is).
constexpr const char* kElementColumns[] = {
    "x", "y", "angle", "vx", "vy", "w", "fx", "fy", "torque", "fluidfx", "fluidfy", "fluidtorque"};

class ElementRecorder final : public CsvRecorder {
 public:
  ElementRecorder(std::string path, int every, std::vector<int> ids)
      : CsvRecorder(std::move(path), every, columnsFor(ids)), ids_(std::move(ids)) {}
  const char* kind() const override { return "csv"; }

 protected:
  void values(const Session& s, std::vector<double>& out) const override {
    const dem::Bodies& b = s.manager.assembly().bodies();
    for (int id : ids_) {
      const int k = b.slot(id);
      if (k < 0)
        throw Error("LOOKUP ELEMENT", "element " + std::to_string(id) +
                                          " was deleted: recording stopped (no row for step " +
                                          std::to_string(s.manager.stepCount()) + ")");
      out.insert(out.end(), {b.x[k].x(), b.x[k].y(), b.angle[k], b.v[k].x(), b.v[k].y(), b.w[k],
                             b.force[k].x(), b.force[k].y(), b.torque[k], b.fluidForce[k].x(),
                             b.fluidForce[k].y(), b.fluidTorque[k]});
    }
  }

 private:
  static std::vector<std::string> columnsFor(const std::vector<int>& ids) {
    std::vector<std::string> columns;
    for (int id : ids)
      for (const char* c : kElementColumns)
        columns.push_back(std::string(c) + "_" + std::to_string(id));
    return columns;
  }
  std::vector<int> ids_;
};

const OptionSpec kCsvOptions[] = {{"-elements", "IDS", "the elements whose state each row holds"},
                                  {"-every", "K", "a row every K steps (default 1)"},
                                  {nullptr, nullptr, nullptr}};

}  // namespace

int OutputCsv(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE -elements IDS ?-every K?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string path = Tcl_GetString(objv[1]);
  if (path.empty()) return fail(interp, "VALUE FILE", "FILE must not be empty");
  std::vector<int> ids;
  bool given = false;
  int every = 1;
  const dem::Bodies& bodies = s.manager.assembly().bodies();
  if (!parseOptions(interp, objc, objv, 2, kCsvOptions, [&](int k, Tcl_Obj* o) {
        if (k == 1) {
          return getEvery(interp, o, every);
        }
        int n = 0;
        Tcl_Obj** items = nullptr;
        if (Tcl_ListObjGetElements(interp, o, &n, &items) != TCL_OK) return false;
        ids.clear();
        std::set<int> seen;
        for (int i = 0; i < n; ++i) {
          int id = 0;
          if (!getInt(interp, items[i], "-elements", id)) return false;
          if (bodies.slot(id) < 0)
            return reject(interp, "LOOKUP ELEMENT", "no element with id " + std::to_string(id));
          if (!seen.insert(id).second)
            return reject(interp, "VALUE ELEMENTS",
                          "-elements names element " + std::to_string(id) + " twice");
          ids.push_back(id);
        }
        if (ids.empty()) return reject(interp, "VALUE ELEMENTS", "-elements is empty");
        given = true;
        return true;
      }))
    return TCL_ERROR;
  if (!given) return fail(interp, "VALUE ELEMENTS", "output csv needs -elements IDS");
  if (startRecorder(s, std::make_unique<ElementRecorder>(path, every, std::move(ids)), objc,
                    objv) != TCL_OK)
    return TCL_ERROR;
  Tcl_SetObjResult(interp, newString(path));
  return TCL_OK;
}

}  // namespace sf::tcl
