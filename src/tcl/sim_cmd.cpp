// sim configure|cget|info|hash|check|estimate|options|help
#include <array>
#include <cmath>
#include <cstdio>

#include "accuracy_preset.hpp"
#include "remedy.hpp"
#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/option_table.hpp"
#include "sandflow/tcl/session.hpp"
#include "sim_profile.hpp"

namespace sf::tcl {
namespace {

const char* const kSolidRatioNames[] = {"exact", "1", "2", "4", "8", nullptr};
const int kSolidRatioSubcells[] = {coupling::kExact, 1, 2, 4, 8};
const char* const kInteriorNames[] = {"equilibrium", "collide", nullptr};
const char* const kCouplingNames[] = {"explicit", "implicit", nullptr};

// What sim configure sets, staged: every value converted and checked before
// any reaches the Manager.
struct SimDraft {
  double timestep = 0;
  int threads = 1, integrator = 0, substeps = 1;
  Vec2 gravity = Vec2::Zero();
  double maxOverlap = 0.5;
  coupling::Settings coupled;
  int accuracy = kCustomAccuracy;

  static SimDraft of(const sim::Manager& m) {
    return {m.timestep(),         m.threads(),        int(m.assembly().integrator),
            m.substeps(),         m.gravity(),        m.assembly().maxOverlap(),
            m.couplingSettings(), matchingAccuracy(m)};
  }
};

int solidRatioChoice(int subcells) {
  for (int i = 0; kSolidRatioNames[i]; ++i)
    if (kSolidRatioSubcells[i] == subcells) return i;
  return 0;
}

using Row = Option<SimDraft>;
const OptionTable<SimDraft> kOptions{
    Row{.info = {.name = "-timestep",
                 .synopsis = "dt",
                 .help = "fix the timestep (a lattice's tau then follows from it)",
                 .unit = "time",
                 .range = {.min = 0, .minOpen = true}},
        .get = [](const SimDraft& s) { return realValue(s.timestep); },
        .set = [](SimDraft& s, const OptionValue& v) { s.timestep = v.real; }},
    Row{.info = {.name = "-threads",
                 .synopsis = "n",
                 .help = "threads for the step (results do not depend on it)",
                 .kind = ValueKind::integer,
                 .range = {.min = 1, .max = sim::Manager::kMaxThreads}},
        .get = [](const SimDraft& s) { return integerValue(s.threads); },
        .set = [](SimDraft& s, const OptionValue& v) { s.threads = v.integer; }},
    Row{.info = {.name = "-gravity",
                 .synopsis = "{gx gy}",
                 .help = "gravitational acceleration on the elements",
                 .kind = ValueKind::vec2,
                 .unit = "length/time^2"},
        .get = [](const SimDraft& s) { return vecValue(s.gravity); },
        .set = [](SimDraft& s, const OptionValue& v) { s.gravity = v.vec; }},
    Row{.info = {.name = "-integrator",
                 .synopsis = "central|euler|verlet",
                 .help = "element integrator: central difference, the thesis's first-order "
                         "scheme, velocity Verlet",
                 .kind = ValueKind::choice,
                 .choices = dem::integratorNames},
        .get = [](const SimDraft& s) { return choiceValue(s.integrator); },
        .set = [](SimDraft& s, const OptionValue& v) { s.integrator = v.choice; }},
    Row{.info = {.name = "-maxoverlap",
                 .synopsis = "f",
                 .help = "a contact overlapping more than f of the smaller element stops the run",
                 .range = {.min = 0, .max = dem::Assembly::kMaxOverlapLimit, .minOpen = true}},
        .get = [](const SimDraft& s) { return realValue(s.maxOverlap); },
        .set = [](SimDraft& s, const OptionValue& v) { s.maxOverlap = v.real; }},
    Row{.info = {.name = "-solidratio",
                 .synopsis = "exact|1|2|4|8",
                 .help = "solid ratio of covered cells: exact areas, or n x n subcell centres "
                         "per cell (1: the stair-step limit)",
                 .kind = ValueKind::choice,
                 .choices = kSolidRatioNames,
                 .what = "solid ratio"},
        .get = [](const SimDraft& s) { return choiceValue(solidRatioChoice(s.coupled.subcells)); },
        .set = [](SimDraft& s,
                  const OptionValue& v) { s.coupled.subcells = kSolidRatioSubcells[v.choice]; }},
    Row{.info = {.name = "-substeps",
                 .synopsis = "n",
                 .help = "element steps per fluid step, each dt/n under the step's fluid force",
                 .kind = ValueKind::integer,
                 .range = {.min = 1, .max = sim::Manager::kMaxSubsteps}},
        .get = [](const SimDraft& s) { return integerValue(s.substeps); },
        .set = [](SimDraft& s, const OptionValue& v) { s.substeps = v.integer; }},
    Row{.info = {.name = "-buoyancy",
                 .synopsis = "0|1",
                 .help = "static buoyancy -rho_f A g on elements in the fluid",
                 .kind = ValueKind::boolean},
        .get = [](const SimDraft& s) { return booleanValue(s.coupled.buoyancy); },
        .set = [](SimDraft& s, const OptionValue& v) { s.coupled.buoyancy = v.boolean; }},
    Row{.info = {.name = "-share",
                 .synopsis = "coverage|equal",
                 .help = "force of a cell covered by several solids: by coverage or equal "
                         "shares (the thesis's)",
                 .kind = ValueKind::choice,
                 .choices = coupling::shareNames},
        .get = [](const SimDraft& s) { return choiceValue(int(s.coupled.share)); },
        .set = [](SimDraft& s,
                  const OptionValue& v) { s.coupled.share = coupling::Share(v.choice); }},
    Row{.info = {.name = "-interior",
                 .synopsis = "equilibrium|collide",
                 .help = "cells deep inside solids: set to the equilibrium at the solid "
                         "velocity, or collided with the Noble-Torczynski operator like the rest",
                 .kind = ValueKind::choice,
                 .choices = kInteriorNames},
        .get = [](const SimDraft& s) { return choiceValue(s.coupled.equilibriumInterior ? 0 : 1); },
        .set = [](SimDraft& s,
                  const OptionValue& v) { s.coupled.equilibriumInterior = v.choice == 0; }},
    Row{.info = {.name = "-coupling",
                 .synopsis = "explicit|implicit",
                 .help = "velocity the fluid sees: the element's at the start of the step (the "
                         "thesis's), or solved with the force it causes (stable for light "
                         "elements)",
                 .kind = ValueKind::choice,
                 .choices = kCouplingNames},
        .get = [](const SimDraft& s) { return choiceValue(s.coupled.implicit ? 1 : 0); },
        .set = [](SimDraft& s, const OptionValue& v) { s.coupled.implicit = v.choice == 1; }},
    Row{.info = {.name = "-accuracy",
                 .synopsis = "draft|normal|fine",
                 .help = "a measured set of the accuracy knobs (docs/accuracy.md): the "
                         "lattice's tau (its viscosity kept), collision and forcing, and "
                         "-solidratio, -coupling, -integrator and -substeps; options given with "
                         "it win; custom: none of the three (setting it changes nothing)",
                 .kind = ValueKind::choice,
                 .choices = kAccuracyNames},
        .get = [](const SimDraft& s) { return choiceValue(s.accuracy); },
        .set = [](SimDraft& s, const OptionValue& v) { s.accuracy = v.choice; }},
};
// The rows whose presence the commands read (the table's own order aside).
const int kTimestep = kOptions.index("-timestep"), kThreads = kOptions.index("-threads"),
          kGravity = kOptions.index("-gravity"), kIntegrator = kOptions.index("-integrator"),
          kSolidRatio = kOptions.index("-solidratio"), kSubsteps = kOptions.index("-substeps"),
          kCoupling = kOptions.index("-coupling"), kAccuracy = kOptions.index("-accuracy");

// The preset's step settings onto the draft, except those given with it.
void draftPreset(SimDraft& draft, std::vector<bool>& given) {
  const AccuracyPreset& p = accuracyPreset(draft.accuracy);
  if (!given[kSolidRatio]) draft.coupled.subcells = p.subcells;
  if (!given[kCoupling]) draft.coupled.implicit = p.implicit;
  if (!given[kIntegrator]) draft.integrator = int(p.integrator);
  if (!given[kSubsteps]) draft.substeps = p.substeps, given[kSubsteps] = true;
}

// The settings of a new session, for help's and `sim options`' defaults.
const SimDraft& defaults() {
  static const SimDraft d = SimDraft::of(sim::Manager{});
  return d;
}

int SimConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  Session& s = sessionOf(data);
  sim::Manager& m = s.manager;
  SimDraft draft = SimDraft::of(m);
  if (objc == 1) {
    Tcl_SetObjResult(interp, kOptions.all(draft));
    return TCL_OK;
  }
  if (objc == 2) {
    const int k = optionIndex(interp, objv[1], kOptions.specs());
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, kOptions.get(draft, k));
    return TCL_OK;
  }
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "?-option value ...?");
    return TCL_ERROR;
  }
  // Stage every value, validate, then commit: a refused option changes nothing.
  std::vector<bool> given;
  if (!kOptions.apply(interp, objc, objv, 1, draft, &given)) return TCL_ERROR;
  const bool preset = given[kAccuracy] && draft.accuracy != kCustomAccuracy;
  if (preset) draftPreset(draft, given);
  const int code = guarded(interp, [&] {
    // The only settings that can refuse, all checked before anything changes:
    // the preset's lattice (its tau sets the timestep), then the stepping.
    std::optional<lb::LatticeDef> latticeDef;
    if (preset && m.hasLattice()) {
      latticeDef = presetLattice(m.lattice().params(), accuracyPreset(draft.accuracy));
      try {
        lb::resolve(*latticeDef);
      } catch (const Error& e) {
        fail(interp, e);
        noteOptionOnce(interp, "-accuracy");
        return TCL_ERROR;
      }
    }
    if (latticeDef || given[kTimestep] || given[kSubsteps]) {
      try {
        m.configureStep(latticeDef,
                        given[kTimestep] ? std::optional<double>(draft.timestep) : std::nullopt,
                        given[kSubsteps] ? std::optional<int>(draft.substeps) : std::nullopt);
      } catch (const Error& e) {
        fail(interp, e);
        noteOptionOnce(interp, given[kSubsteps] && !given[kTimestep] ? "-substeps" : "-timestep");
        return TCL_ERROR;
      }
    }
    m.setCouplingSettings(draft.coupled);
    if (given[kThreads]) m.setThreads(draft.threads);
    if (given[kGravity]) m.setGravity(draft.gravity);
    m.assembly().integrator = static_cast<dem::Integrator>(draft.integrator);
    m.assembly().setMaxOverlap(draft.maxOverlap);
    return TCL_OK;
  });
  flushWarnings(s);  // a preset's lattice warned of at once
  return code;
}

int SimCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "-option");
    return TCL_ERROR;
  }
  const int k = optionIndex(interp, objv[1], kOptions.specs());
  if (k < 0) return TCL_ERROR;
  Tcl_SetObjResult(interp, kOptions.get(SimDraft::of(sessionOf(data).manager), k));
  return TCL_OK;
}

int SimInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const Session& session = sessionOf(data);
  const sim::Manager& m = session.manager;
  const bool lattice = m.hasLattice();
  const double mach = lattice ? m.lattice().maxMach() : 0.0;
  const double tau = lattice ? m.lattice().params().tau : 0.0;
  Tcl_Obj* warnings = Tcl_NewListObj(0, nullptr);
  for (const sim::Warning& w : m.warnings())
    Tcl_ListObjAppendElement(nullptr, warnings, newString(withRemedy(w.text, w.remedy)));
  const bool stable =
      !lattice || (std::isfinite(mach) && mach <= m.machStopLimit() && tau > lb::kTauMin);
  // Whether the timestep was given rather than derived (with a lattice,
  // lattice info's "given" says, of its own settings).
  const bool givenTimestep = m.timestepFixed() && !lattice;
  // What the fluid exerted on all elements together in the last step.
  Vec2 fluidForce = Vec2::Zero();
  double fluidTorque = 0;
  const dem::Bodies& b = m.assembly().bodies();
  for (int s = 0; s < b.size(); ++s) fluidForce += b.fluidForce[s], fluidTorque += b.fluidTorque[s];
  // The covered cells by kind, read from the lattice's cells (which a
  // checkpoint keeps), and those the last step measured again
  // (docs/coupling.md).
  const coupling::Coupler::CellCounts counts =
      m.solidsCoverCells() ? m.coupler().cellCounts() : coupling::Coupler::CellCounts{};
  coupling::Coupler::CellCounts cells;
  if (m.solidsCoverCells())
    for (const lb::CoveredCell& c : m.lattice().coveredCells())
      cells.partial += c.eps < 1, cells.interior += c.interior;
  Tcl_SetObjResult(
      interp,
      newDict({{"time", newDouble(m.time())},
               {"step", Tcl_NewWideIntObj(m.stepCount())},
               {"timestep", newDouble(m.timestep())},
               {"tau", newDouble(tau)},
               {"mach", newDouble(mach)},
               {"elements", Tcl_NewIntObj(m.assembly().bodies().size())},
               {"contacts", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().touchingCount()))},
               {"bonds", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().bonds().size()))},
               {"broken", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().breaks().size()))},
               {"nodes", Tcl_NewWideIntObj(lattice ? Tcl_WideInt(m.lattice().nodes()) : 0)},
               {"mlups", newDouble(session.mlups)},
               {"stable", Tcl_NewBooleanObj(stable)},
               {"threads", Tcl_NewIntObj(m.threads())},
               {"warnings", warnings},
               {"kinetic", newDouble(m.assembly().kineticEnergy())},
               {"critical", newDouble(m.assembly().criticalTimestep())},
               {"stablestep", newDouble(m.assembly().timestepLimits().stable)},
               {"accuratestep", newDouble(m.assembly().timestepLimits().accurate)},
               {"covered", Tcl_NewWideIntObj(Tcl_WideInt(
                               m.solidsCoverCells() ? m.lattice().coveredCells().size() : 0))},
               {"coveredpartial", Tcl_NewWideIntObj(Tcl_WideInt(cells.partial))},
               {"coveredinterior", Tcl_NewWideIntObj(Tcl_WideInt(cells.interior))},
               {"remeasured", Tcl_NewWideIntObj(Tcl_WideInt(counts.remeasured))},
               {"fluidforce", newVec2(fluidForce)},
               {"fluidtorque", newDouble(fluidTorque)},
               {"substeps", Tcl_NewIntObj(m.substeps())},
               {"given", Tcl_NewStringObj(givenTimestep ? "-timestep" : "", -1)},
               {"passes", passesDict(session)}}));
  return TCL_OK;
}

// The scene's state as 8 hex digits (CRC-32 of what a checkpoint holds of it):
// two runs that agree bit for bit have the same hash.
int SimHash(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", unsigned(sessionOf(data).manager.stateHash()));
  Tcl_SetObjResult(interp, newString(hex));
  return TCL_OK;
}

// The kernel's invariants checked afresh: a list of what is wrong, empty when
// all hold.
int SimCheck(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (const std::string& p : sessionOf(data).manager.validate())
    Tcl_ListObjAppendElement(nullptr, list, newString(p));
  Tcl_SetObjResult(interp, list);
  return TCL_OK;
}

}  // namespace

void registerSimCommands(Tcl_Interp* interp, Session* session) {
  makeEnsemble(interp, "::sf::sim",
               {{"configure", SimConfigure},
                {"cget", SimCget},
                {"info", SimInfo},
                {"hash", SimHash},
                {"check", SimCheck},
                {"estimate", SimEstimate}},
               session,
               kOptions.answers("sim",
                                {"configure ?-option value ...?", "cget -option",
                                 "info    -> dict time step timestep tau mach elements "
                                 "contacts bonds broken nodes mlups stable covered "
                                 "fluidforce ... passes",
                                 "hash    -> the state's CRC-32, 8 hex digits",
                                 "estimate ?N? -> dict steps seconds perstep basis "
                                 "basissteps passes: the next N steps' time (100)",
                                 "check   -> the invariants that fail (empty: all hold)",
                                 "options -> the options as dicts: name type unit min max "
                                 "choices default help ...",
                                 "help"},
                                defaults()));
}

}  // namespace sf::tcl
