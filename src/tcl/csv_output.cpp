// output csv FILE -elements IDS ?-every K?: an element time series; and the
// CSV recorder it shares with "record" (the file itself is io::CsvWriter's).
#include <set>
#include <string>
#include <vector>

#include "csv_recorder.hpp"
#include "output_verbs.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {

CsvRecorder::CsvRecorder(std::string path, int every, const std::vector<std::string>& columns)
    : Recorder(path, every), writer_(std::move(path), columns) {}

void CsvRecorder::record(const Session& s) {
  // The values first: a record that cannot be taken writes nothing.
  scratch_.clear();
  values(s, scratch_);
  // Only the first write resumes: later ones append to the file it opened.
  writer_.write(s.manager.stepCount(), s.manager.time(), scratch_, s.resumeStep);
  ++written_;
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

// What output csv is asked, besides the file; bodies: the scene's, for the
// check of the ids.
struct CsvDraft {
  std::vector<int> ids = {};  // empty: not given
  int every = 1;
  const dem::Bodies* bodies = nullptr;
};

// -elements IDS: each an element of the scene, once.
bool parseIds(Tcl_Interp* interp, Tcl_Obj* o, CsvDraft& d) {
  if (!getElementIds(interp, o, d.ids)) return false;
  std::set<int> seen;
  for (int id : d.ids) {
    if (d.bodies->slot(id) < 0)
      return reject(interp, "LOOKUP ELEMENT", "no element with id " + std::to_string(id));
    if (!seen.insert(id).second)
      return reject(interp, "VALUE ELEMENTS",
                    "-elements names element " + std::to_string(id) + " twice");
  }
  return true;
}

const OptionTable<CsvDraft> kCsvOptions{
    parsedRow<CsvDraft>({.name = "-elements",
                         .synopsis = "IDS",
                         .help = "the elements whose state each row holds",
                         .defaultText = "none: required"},
                        parseIds),
    everyRow("a row every K steps", &CsvDraft::every),
};

}  // namespace

int OutputCsv(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE -elements IDS ?-every K?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string path = Tcl_GetString(objv[1]);
  if (path.empty()) return fail(interp, "VALUE FILE", "FILE must not be empty");
  CsvDraft draft{.bodies = &s.manager.assembly().bodies()};
  if (!kCsvOptions.apply(interp, objc, objv, 2, draft)) return TCL_ERROR;
  if (draft.ids.empty()) return fail(interp, "VALUE ELEMENTS", "output csv needs -elements IDS");
  if (startRecorder(s, std::make_unique<ElementRecorder>(path, draft.every, std::move(draft.ids)),
                    objc, objv) != TCL_OK)
    return TCL_ERROR;
  Tcl_SetObjResult(interp, newString(path));
  return TCL_OK;
}

std::string outputCsvOptions() {
  return kCsvOptions.help("output csv", {}, CsvDraft{});
}

}  // namespace sf::tcl
