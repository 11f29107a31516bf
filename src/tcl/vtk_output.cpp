// output vtk PREFIX ?-every K?: the scene as VTK files for ParaView, once, or
// as a numbered series recorded while runs go on, listed with its times in
// PREFIX.pvd.
#include <cstdio>
#include <string>
#include <vector>

#include "output_verbs.hpp"
#include "sandflow/io/atomic_files.hpp"
#include "sandflow/io/vtk.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

// A file of one record, with its place in the collection.
struct Part {
  io::FileContent file;
  int part;
  const char* name;
};

// The files that show the scene under `stem`: STEM.vti (lattice), STEM.vtp
// (elements), STEM_bonds.vtp (bonds, made or broken). Once, only what the
// scene has is written. A series writes the elements and bonds files at every
// record, empty when there is nothing to show: ParaView's .pvd reader fixes
// its output type at the first time step (one data set, or blocks) and
// numbers blocks by their order within a time step, so a part that came and
// went would break the series or move the others. The writers read the
// Manager when called.
std::vector<Part> partsOf(const sim::Manager& m, const std::string& stem, bool series) {
  std::vector<Part> parts;
  const dem::Assembly& a = m.assembly();
  if (m.hasLattice())
    parts.push_back(
        {{stem + ".vti", [&m](std::ostream& out) { io::writeLatticeVti(m.lattice(), out); }},
         0,
         "lattice"});
  if (series || !a.empty())
    parts.push_back({{stem + ".vtp", [&a](std::ostream& out) { io::writeElementsVtp(a, out); }},
                     1,
                     "elements"});
  if (series || !a.bonds().empty() || !a.breaks().empty())
    parts.push_back({{stem + "_bonds.vtp", [&a](std::ostream& out) { io::writeBondsVtp(a, out); }},
                     2,
                     "bonds"});
  return parts;
}

std::string baseName(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A record every K steps: PREFIX_0000.vti, PREFIX_0000.vtp, ... and
// PREFIX.pvd rewritten with each record, in the one atomic write of its files,
// so that the collection is whole and lists only files that exist.
class VtkRecorder final : public Recorder {
 public:
  VtkRecorder(const std::string& prefix, int every)
      : Recorder(prefix + ".pvd", every), prefix_(prefix) {}
  const char* kind() const override { return "vtk"; }

  void record(const Session& s) override {
    char number[24];
    std::snprintf(number, sizeof number, "_%04lld", written_);
    const std::vector<Part> parts = partsOf(s.manager, prefix_ + number, true);
    std::vector<io::CollectionEntry> entries = entries_;
    std::vector<io::FileContent> files;
    for (const Part& p : parts) {
      entries.push_back({s.manager.time(), p.part, p.name, baseName(p.file.path)});
      files.push_back(p.file);
    }
    files.push_back(
        {path(), [&entries](std::ostream& out) { io::writeCollectionPvd(entries, out); }});
    io::writeAtomically(files);
    entries_ = std::move(entries);
    ++written_;
  }
  void finish() override {}  // the collection is complete after every record

 private:
  std::string prefix_;
  std::vector<io::CollectionEntry> entries_;
};

// What output vtk is asked, besides the prefix; every 0: write once.
struct VtkDraft {
  int every = 0;
};
const OptionTable<VtkDraft> kVtkOptions{
    everyRow("record the scene every K steps as a numbered series, listed in PREFIX.pvd",
             &VtkDraft::every, "none: written once"),
};

}  // namespace

int OutputVtk(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc < 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "PREFIX ?-every K?");
    return TCL_ERROR;
  }
  Session& s = *static_cast<Session*>(data);
  const std::string prefix = Tcl_GetString(objv[1]);
  if (prefix.empty()) return fail(interp, "VALUE PREFIX", "PREFIX must not be empty");
  VtkDraft draft;
  if (!kVtkOptions.apply(interp, objc, objv, 2, draft)) return TCL_ERROR;
  const int every = draft.every;
  if (!s.manager.hasLattice() && s.manager.assembly().empty())
    return fail(interp, "LOOKUP SCENE",
                "nothing to write: the scene has no lattice and no elements");
  if (every > 0) {
    if (startRecorder(s, std::make_unique<VtkRecorder>(prefix, every), objc, objv) != TCL_OK)
      return TCL_ERROR;
    Tcl_SetObjResult(interp, newString(prefix + ".pvd"));
    return TCL_OK;
  }
  std::vector<io::FileContent> files;
  for (const Part& p : partsOf(s.manager, prefix, false)) files.push_back(p.file);
  return guarded(interp, [&] {
    for (const io::FileContent& f : files) requireConfined(s, f.path);
    io::writeAtomically(files);  // all appear, or none
    Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
    for (const io::FileContent& f : files)
      Tcl_ListObjAppendElement(nullptr, list, newString(f.path));
    Tcl_SetObjResult(interp, list);
    return TCL_OK;
  });
}

std::string outputVtkOptions() {
  return kVtkOptions.help("output vtk", {}, VtkDraft{});
}

}  // namespace sf::tcl
