#include "sandflow/sim/manager.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "sandflow/core/error.hpp"

namespace sf::sim {

Manager::Manager() : threads_(std::max(1, omp_get_num_procs())) {
  assembly_.threads = threads_;
}

lb::Lattice& Manager::lattice() {
  if (!lattice_) throw Error("LOOKUP LATTICE", "there is no lattice: use \"lattice create\"");
  return *lattice_;
}

const lb::Lattice& Manager::lattice() const {
  if (!lattice_) throw Error("LOOKUP LATTICE", "there is no lattice: use \"lattice create\"");
  return *lattice_;
}

void Manager::createLattice(lb::LatticeDef def) {
  if (lattice_) throw Error("EXISTS LATTICE", "a lattice exists: \"lattice delete\" it first");
  // A fixed timestep gives tau (with a viscosity) or the viscosity (with tau).
  if (fixedTimestep_ && (!def.tau || !def.viscosity)) def.timestep = fixedTimestep_;
  auto lattice = std::make_unique<lb::Lattice>(lb::resolve(def));
  lattice->setThreads(threads_);
  lattice_ = std::move(lattice);
  machWarned_ = false;
}

void Manager::reconfigureLattice(const lb::LatticeDef& def) {
  lattice().reconfigure(lb::resolve(def));
  if (fixedTimestep_) fixedTimestep_ = lattice_->params().dt;
}

void Manager::deleteLattice() {
  lattice();  // throws if none
  lattice_.reset();
}

double Manager::timestep() const {
  if (lattice_) return lattice_->params().dt;
  if (fixedTimestep_) return *fixedTimestep_;
  const double critical = assembly_.criticalTimestep();
  return std::isfinite(critical) ? critical / 10 : 0.0;
}

void Manager::setGravity(const Vec2& g) {
  if (!g.allFinite()) throw Error("VALUE GRAVITY", "-gravity must be finite");
  gravity_ = g;
}

void Manager::checkDemTimestep(double dt) const {
  const double critical = assembly_.criticalTimestep();
  if (dt > critical)
    throw Error("VALUE TIMESTEP",
                "timestep " + formatNumber(dt) + " exceeds the elements' critical timestep " +
                    formatNumber(critical) + " (2 sqrt(m/k), lightest element, stiffest material)");
}

void Manager::setTimestep(double dt) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw Error("VALUE TIMESTEP", "-timestep must be > 0, got " + formatNumber(dt));
  checkDemTimestep(dt);
  if (lattice_) {
    lb::LatticeDef def = lattice_->params().def;
    def.viscosity = lattice_->params().viscosity;
    def.tau.reset();
    def.timestep = dt;
    lattice_->reconfigure(lb::resolve(def));
  }
  fixedTimestep_ = dt;
}

void Manager::setThreads(int threads) {
  if (threads < 1)
    throw Error("VALUE THREADS", "-threads must be >= 1, got " + std::to_string(threads));
  threads_ = threads;
  if (lattice_) lattice_->setThreads(threads);
}

void Manager::step() {
  const double dt = timestep();
  if (!assembly_.empty()) {
    if (!(dt > 0))
      throw Error(
          "VALUE TIMESTEP",
          "no timestep: the elements are all held; set one with \"sim configure -timestep\"");
    checkDemTimestep(dt);
  }
  if (lattice_) {
    try {
      lattice_->step(machStopLimit());
    } catch (const Error& e) {
      throw Error(e.code(), "step " + std::to_string(steps_ + 1) +
                                " (t = " + formatNumber(time_ + timestep()) + "): " + e.what());
    }
    if (!machWarned_ && lattice_->lastStepMach() > machWarnLimit()) {
      machWarned_ = true;
      warn("Mach number " + formatNumber(lattice_->lastStepMach()) + " at step " +
           std::to_string(steps_ + 1) + " exceeds " + formatNumber(machWarnLimit()) +
           ": the flow is no longer nearly incompressible (reduce the timestep or the forcing)");
    }
  }
  try {
    assembly_.step(dt, gravity_);
  } catch (const Error& e) {
    throw Error(e.code(), "step " + std::to_string(steps_ + 1) +
                              " (t = " + formatNumber(time_ + dt) + "): " + e.what());
  }
  time_ += dt;
  ++steps_;
}

void Manager::reset() {
  lattice_.reset();
  assembly_ = dem::Assembly();
  assembly_.threads = threads_;
  gravity_ = Vec2::Zero();
  fixedTimestep_.reset();
  time_ = 0.0;
  steps_ = 0;
  mlups_ = 0.0;
  machWarned_ = false;
  pendingWarnings_.clear();
  warningLog_.clear();
}

void Manager::warn(const std::string& message) {
  pendingWarnings_.push_back(message);
  warningLog_.push_back(message);
}

std::vector<std::string> Manager::takeWarnings() {
  std::vector<std::string> out;
  out.swap(pendingWarnings_);
  return out;
}

}  // namespace sf::sim
