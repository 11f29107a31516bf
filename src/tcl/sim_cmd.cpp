// sim configure|cget|info|help
#include <array>
#include <cmath>
#include <cstdio>

#include "sandflow/tcl/args.hpp"
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

enum Opt {
  kTimestep,
  kThreads,
  kGravity,
  kIntegrator,
  kMaxOverlap,
  kSolidRatio,
  kSubsteps,
  kBuoyancy,
  kShare,
  kInterior,
  kCoupling,
  kOptionCount
};

const OptionSpec kOptions[] = {
    {"-timestep", "dt", "fix the timestep (a lattice's tau then follows from it)"},
    {"-threads", "n", "threads for the step (results do not depend on it)"},
    {"-gravity", "{gx gy}", "gravitational acceleration on the elements (default {0 0})"},
    {"-integrator", "central|euler|verlet",
     "element integrator: central difference (default), the thesis's first-order scheme, "
     "velocity Verlet"},
    {"-maxoverlap", "f",
     "a contact overlapping more than f of the smaller element stops the run "
     "(default 0.5)"},
    {"-solidratio", "exact|1|2|4|8",
     "solid ratio of covered cells: exact areas (default), or n x n subcell centres per cell "
     "(1: the stair-step limit)"},
    {"-substeps", "n",
     "element steps per fluid step, each dt/n under the step's fluid force "
     "(default 1)"},
    {"-buoyancy", "0|1", "static buoyancy -rho_f A g on elements in the fluid (default 1)"},
    {"-share", "coverage|equal",
     "force of a cell covered by several solids: by coverage (default) or equal shares "
     "(the thesis's)"},
    {"-interior", "equilibrium|collide",
     "cells deep inside solids: set to the equilibrium at the solid velocity (default), or "
     "collided with the Noble-Torczynski operator like the rest"},
    {"-coupling", "explicit|implicit",
     "velocity the fluid sees: the element's at the start of the step (default, the thesis's), "
     "or solved with the force it causes (stable for light elements)"},
    {nullptr, nullptr, nullptr}};

const char* const kSolidRatioNames[] = {"exact", "1", "2", "4", "8", nullptr};
const int kSolidRatioSubcells[] = {coupling::kExact, 1, 2, 4, 8};
const char* const kInteriorNames[] = {"equilibrium", "collide", nullptr};
const char* const kCouplingNames[] = {"explicit", "implicit", nullptr};


Tcl_Obj* optionValue(const sim::Manager& m, int k) {
  switch (k) {
    case kTimestep:
      return newDouble(m.timestep());
    case kThreads:
      return Tcl_NewIntObj(m.threads());
    case kGravity:
      return newVec2(m.gravity());
    case kIntegrator:
      return Tcl_NewStringObj(dem::integratorNames[int(m.assembly().integrator)], -1);
    case kMaxOverlap:
      return newDouble(m.assembly().maxOverlap);
    case kSolidRatio:
      for (int i = 0; kSolidRatioNames[i]; ++i)
        if (kSolidRatioSubcells[i] == m.coupling().subcells)
          return Tcl_NewStringObj(kSolidRatioNames[i], -1);
      return Tcl_NewStringObj("exact", -1);
    case kSubsteps:
      return Tcl_NewIntObj(m.substeps());
    case kBuoyancy:
      return Tcl_NewBooleanObj(m.coupling().buoyancy);
    case kShare:
      return Tcl_NewStringObj(coupling::shareNames[int(m.coupling().share)], -1);
    case kInterior:
      return Tcl_NewStringObj(kInteriorNames[m.coupling().equilibriumInterior ? 0 : 1], -1);
    default:
      return Tcl_NewStringObj(kCouplingNames[m.coupling().implicit ? 1 : 0], -1);
  }
}

int SimConfigure(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  sim::Manager& m = sessionOf(data).manager;
  if (objc == 1) {
    Tcl_Obj* all = Tcl_NewListObj(0, nullptr);
    for (int k = 0; k < kOptionCount; ++k) {
      Tcl_ListObjAppendElement(nullptr, all, Tcl_NewStringObj(kOptions[k].name, -1));
      Tcl_ListObjAppendElement(nullptr, all, optionValue(m, k));
    }
    Tcl_SetObjResult(interp, all);
    return TCL_OK;
  }
  if (objc == 2) {
    const int k = optionIndex(interp, objv[1], kOptions);
    if (k < 0) return TCL_ERROR;
    Tcl_SetObjResult(interp, optionValue(m, k));
    return TCL_OK;
  }
  if (objc % 2 == 0) {
    Tcl_WrongNumArgs(interp, 1, objv, "?-option value ...?");
    return TCL_ERROR;
  }
  // Stage every value, validate, then commit: a refused option changes nothing.
  std::optional<double> timestep, maxOverlap;
  std::optional<int> threads, integrator, substeps;
  std::optional<Vec2> gravity;
  coupling::Settings coupled = m.coupling();
  if (!parseOptions(interp, objc, objv, 1, kOptions, [&](int k, Tcl_Obj* v) {
        int choice = 0;
        switch (k) {
          case kSolidRatio:
            if (!getChoice(interp, v, "solid ratio", kSolidRatioNames, choice)) return false;
            coupled.subcells = kSolidRatioSubcells[choice];
            return true;
          case kSubsteps: {
            int n = 0;
            if (!getInt(interp, v, "-substeps", n)) return false;
            if (n < 1 || n > 1000)
              return reject(interp, "VALUE SUBSTEPS",
                            "-substeps must be 1 to 1000, got " + std::to_string(n));
            substeps = n;
            return true;
          }
          case kBuoyancy:
            return getBool(interp, v, "-buoyancy", coupled.buoyancy);
          case kShare:
            if (!getChoice(interp, v, "share", coupling::shareNames, choice)) return false;
            coupled.share = static_cast<coupling::Share>(choice);
            return true;
          case kInterior:
            if (!getChoice(interp, v, "interior", kInteriorNames, choice)) return false;
            coupled.equilibriumInterior = choice == 0;
            return true;
          case kCoupling:
            if (!getChoice(interp, v, "coupling", kCouplingNames, choice)) return false;
            coupled.implicit = choice == 1;
            return true;
          default:
            break;
        }
        if (k == kGravity) {
          Vec2 g;
          if (!getVec2(interp, v, "-gravity", g)) return false;
          gravity = g;
        } else if (k == kIntegrator) {
          int i = 0;
          if (!getChoice(interp, v, "integrator", dem::integratorNames, i)) return false;
          integrator = i;
        } else if (k == kMaxOverlap) {
          double f = 0;
          if (!getDouble(interp, v, "-maxoverlap", f)) return false;
          if (!(f > 0 && f <= 2))
            return reject(interp, "VALUE MAXOVERLAP",
                          "-maxoverlap must be > 0 and <= 2, got " + formatNumber(f));
          maxOverlap = f;
        } else if (k == kTimestep) {
          double dt = 0;
          if (!getDouble(interp, v, "-timestep", dt)) return false;
          if (!(dt > 0))
            return reject(interp, "VALUE TIMESTEP",
                          "-timestep must be > 0, got " + formatNumber(dt));
          timestep = dt;
        } else {
          int n = 0;
          if (!getInt(interp, v, "-threads", n)) return false;
          if (n < 1 || n > sim::Manager::kMaxThreads)
            return reject(interp, "VALUE THREADS",
                          "-threads must be 1 to " + std::to_string(sim::Manager::kMaxThreads) +
                              ", got " + std::to_string(n));
          threads = n;
        }
        return true;
      }))
    return TCL_ERROR;
  return guarded(interp, [&] {
    // The only step that can refuse, before anything changes.
    if (timestep || substeps) {
      try {
        m.setStepping(timestep, substeps);
      } catch (const Error& e) {
        fail(interp, e);
        noteOptionOnce(interp, substeps && !timestep ? "-substeps" : "-timestep");
        return TCL_ERROR;
      }
    }
    m.setCoupling(coupled);
    if (threads) m.setThreads(*threads);
    if (gravity) m.setGravity(*gravity);
    if (integrator) m.assembly().integrator = static_cast<dem::Integrator>(*integrator);
    if (maxOverlap) m.assembly().maxOverlap = *maxOverlap;
    return TCL_OK;
  });
}

int SimCget(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 2) {
    Tcl_WrongNumArgs(interp, 1, objv, "-option");
    return TCL_ERROR;
  }
  const int k = optionIndex(interp, objv[1], kOptions);
  if (k < 0) return TCL_ERROR;
  Tcl_SetObjResult(interp, optionValue(sessionOf(data).manager, k));
  return TCL_OK;
}

int SimInfo(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  const sim::Manager& m = sessionOf(data).manager;
  const bool lattice = m.hasLattice();
  const double mach = lattice ? m.lattice().maxMach() : 0.0;
  const double tau = lattice ? m.lattice().params().tau : 0.0;
  Tcl_Obj* warnings = Tcl_NewListObj(0, nullptr);
  for (const std::string& w : m.warnings())
    Tcl_ListObjAppendElement(nullptr, warnings, newString(w));
  const bool stable = !lattice || (std::isfinite(mach) && mach <= m.machStopLimit() && tau > 0.5);
  // What the fluid exerted on all elements together in the last step.
  Vec2 fluidForce = Vec2::Zero();
  double fluidTorque = 0;
  const dem::Bodies& b = m.assembly().bodies();
  for (int s = 0; s < b.size(); ++s) fluidForce += b.fluidForce[s], fluidTorque += b.fluidTorque[s];
  Tcl_SetObjResult(
      interp, newDict({{"time", newDouble(m.time())},
                       {"step", Tcl_NewWideIntObj(m.stepCount())},
                       {"timestep", newDouble(m.timestep())},
                       {"tau", newDouble(tau)},
                       {"mach", newDouble(mach)},
                       {"elements", Tcl_NewIntObj(m.assembly().bodies().size())},
                       {"contacts", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().touchingCount()))},
                       {"bonds", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().bonds().size()))},
                       {"broken", Tcl_NewWideIntObj(Tcl_WideInt(m.assembly().breaks().size()))},
                       {"nodes", Tcl_NewWideIntObj(lattice ? Tcl_WideInt(m.lattice().nodes()) : 0)},
                       {"mlups", newDouble(m.mlups())},
                       {"stable", Tcl_NewBooleanObj(stable)},
                       {"threads", Tcl_NewIntObj(m.threads())},
                       {"warnings", warnings},
                       {"kinetic", newDouble(m.assembly().kineticEnergy())},
                       {"critical", newDouble(m.assembly().criticalTimestep())},
                       {"covered", Tcl_NewWideIntObj(Tcl_WideInt(
                                       m.coupled() ? m.lattice().coveredCells().size() : 0))},
                       {"fluidforce", newVec2(fluidForce)},
                       {"fluidtorque", newDouble(fluidTorque)},
                       {"substeps", Tcl_NewIntObj(m.substeps())}}));
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

int SimHelp(ClientData, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  if (objc != 1) {
    Tcl_WrongNumArgs(interp, 1, objv, nullptr);
    return TCL_ERROR;
  }
  Tcl_SetObjResult(
      interp, newString(helpText("sim",
                                 {"configure ?-option value ...?", "cget -option",
                                  "info    -> dict time step timestep tau mach elements contacts "
                                  "bonds broken nodes mlups stable covered fluidforce ...",
                                  "hash    -> the state's CRC-32, 8 hex digits",
                                  "check   -> the invariants that fail (empty: all hold)", "help"},
                                 kOptions)));
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
                {"help", SimHelp}},
               session);
}

}  // namespace sf::tcl
