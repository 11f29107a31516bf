// record FILE ?-every K? ?-quantities LIST?: a time series of the whole scene
// (energy, counts, fluid totals) as CSV, one row per record.
#include <set>
#include <string>
#include <vector>

#include "csv_recorder.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

enum Quantity {
  qKinetic,
  qElements,
  qContacts,
  qBonds,
  qBroken,
  qFluidMass,
  qFluidPx,
  qFluidPy,
  qMach,
  qFluidFx,
  qFluidFy,
  qCount
};

// Null-terminated, in column order; from qFluidMass on they need a lattice.
constexpr const char* kQuantityNames[] = {"kinetic", "elements",  "contacts", "bonds",
                                          "broken",  "fluidmass", "fluidpx",  "fluidpy",
                                          "mach",    "fluidfx",   "fluidfy",  nullptr};

bool needsLattice(int q) {
  return q >= qFluidMass;
}

std::string needsLatticeMessage(int q) {
  return std::string("quantity \"") + kQuantityNames[q] +
         "\" needs a lattice and there is none: use \"lattice create\"";
}

Vec2 fluidForceOnElements(const dem::Bodies& b) {
  Vec2 f = Vec2::Zero();
  for (int s = 0; s < b.size(); ++s) f += b.fluidForce[s];
  return f;
}

class SceneRecorder final : public CsvRecorder {
 public:
  SceneRecorder(std::string path, int every, std::vector<int> quantities)
      : CsvRecorder(std::move(path), every, namesOf(quantities)),
        quantities_(std::move(quantities)) {}
  const char* kind() const override { return "record"; }

 protected:
  void values(const Session& s, std::vector<double>& out) const override {
    const sim::Manager& m = s.manager;
    const dem::Assembly& a = m.assembly();
    for (int q : quantities_) {
      if (needsLattice(q) && !m.hasLattice())
        throw Error("LOOKUP LATTICE", needsLatticeMessage(q) + " (it was deleted)");
      switch (q) {
        case qKinetic:
          out.push_back(a.kineticEnergy());
          break;
        case qElements:
          out.push_back(a.bodies().size());
          break;
        case qContacts:
          out.push_back(double(a.touchingCount()));
          break;
        case qBonds:
          out.push_back(double(a.bonds().size()));
          break;
        case qBroken:
          out.push_back(double(a.breaks().size()));
          break;
        case qFluidMass:
          out.push_back(m.lattice().mass());
          break;
        case qFluidPx:
          out.push_back(m.lattice().momentum().x());
          break;
        case qFluidPy:
          out.push_back(m.lattice().momentum().y());
          break;
        case qMach:
          out.push_back(m.lattice().maxMach());
          break;
        case qFluidFx:
          out.push_back(fluidForceOnElements(a.bodies()).x());
          break;
        case qFluidFy:
          out.push_back(fluidForceOnElements(a.bodies()).y());
          break;
      }
    }
  }

 private:
  static std::vector<std::string> namesOf(const std::vector<int>& quantities) {
    std::vector<std::string> names;
    for (int q : quantities) names.push_back(kQuantityNames[q]);
    return names;
  }
  std::vector<int> quantities_;
};

// What record is asked, besides the file; hasLattice is the scene's, for
// the check of the fluid's quantities.
struct RecordDraft {
  int every = 1;
  std::vector<int> quantities = {};  // empty: all that apply to the scene
  bool hasLattice = false;
};

bool parseQuantities(Tcl_Interp* interp, Tcl_Obj* o, RecordDraft& d) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(interp, o, &n, &items) != TCL_OK) return false;
  d.quantities.clear();
  std::set<int> seen;
  for (int i = 0; i < n; ++i) {
    int q = 0;
    if (!getChoice(interp, items[i], "quantity", kQuantityNames, q)) return false;
    if (needsLattice(q) && !d.hasLattice)
      return reject(interp, "LOOKUP LATTICE", needsLatticeMessage(q));
    if (!seen.insert(q).second)
      return reject(interp, "VALUE QUANTITIES",
                    std::string("-quantities names \"") + kQuantityNames[q] + "\" twice");
    d.quantities.push_back(q);
  }
  if (d.quantities.empty()) return reject(interp, "VALUE QUANTITIES", "-quantities is empty");
  return true;
}

const OptionTable<RecordDraft> kRecordOptions{
    everyRow("a row every K steps", &RecordDraft::every),
    parsedRow<RecordDraft>(
        {.name = "-quantities",
         .synopsis = "LIST",
         .help = "columns after step,time: kinetic elements contacts bonds broken "
                 "fluidmass fluidpx fluidpy mach fluidfx fluidfy",
         .defaultText = "all that apply to the scene"},
        parseQuantities),
};

int Record(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  static const std::string help = kRecordOptions.help(
      "record", {"FILE ?-every K? ?-quantities LIST?   -> FILE", "help"}, RecordDraft{});
  if (answerHelp(interp, objc, objv, help)) return TCL_OK;
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "FILE ?-every K? ?-quantities LIST?");
    return TCL_ERROR;
  }
  Session& s = sessionOf(data);
  const std::string path = Tcl_GetString(objv[1]);
  if (path.empty()) return fail(interp, "VALUE FILE", "FILE must not be empty");
  RecordDraft draft{.hasLattice = s.manager.hasLattice()};
  if (!kRecordOptions.apply(interp, objc, objv, 2, draft)) return TCL_ERROR;
  if (draft.quantities.empty())  // everything that applies: the fluid's quantities with a lattice
    for (int q = 0; q < qCount; ++q)
      if (!needsLattice(q) || draft.hasLattice) draft.quantities.push_back(q);
  if (startRecorder(s,
                    std::make_unique<SceneRecorder>(path, draft.every, std::move(draft.quantities)),
                    objc, objv) != TCL_OK)
    return TCL_ERROR;
  Tcl_SetObjResult(interp, newString(path));
  return TCL_OK;
}

}  // namespace

void registerRecordCommand(Tcl_Interp* interp, Session* session) {
  Tcl_CreateObjCommand(interp, "::sf::record", Record, session, nullptr);
}

}  // namespace sf::tcl
