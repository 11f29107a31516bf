// The scene's state in a checkpoint (Manager::saveState / loadState).
#include <cmath>

#include "sandflow/geometry/vec2_bytes.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::sim {

void Manager::saveState(ByteWriter& out) const {
  out.tag("SIM ");
  putVec2(out, gravity_);
  out.put(fixedTimestep_);
  out.put(time_), out.put(steps_);
  out.put(std::int32_t(substeps_));
  out.put(std::int32_t(coupling_.subcells)), out.put(std::int32_t(coupling_.share));
  out.put(coupling_.buoyancy), out.put(coupling_.equilibriumInterior), out.put(coupling_.implicit);
  out.put(coversCells_);
  watch_.save(out);
  out.put(lattice_ != nullptr);
  if (lattice_) lattice_->saveState(out);
  assembly_.saveState(out);
}

void Manager::loadState(ByteReader& in) {
  in.expectTag("SIM ");
  setGravity(getVec2(in, "gravity"));
  in.get(fixedTimestep_, "timestep");
  if (fixedTimestep_ && !(*fixedTimestep_ > 0 && std::isfinite(*fixedTimestep_)))
    ByteReader::fail("it holds a bad timestep");
  in.get(time_, "time"), in.get(steps_, "step");
  if (!std::isfinite(time_) || steps_ < 0) ByteReader::fail("it holds a bad time or step");
  const auto substeps = in.get<std::int32_t>("substeps");
  coupling::Settings c;
  c.subcells = in.get<std::int32_t>("coupling");
  const auto share = in.get<std::int32_t>("coupling");
  if (share < 0 || share > 1) ByteReader::fail("it holds an unknown force share");
  c.share = coupling::Share(share);
  c.buoyancy = in.getBool("coupling"), c.equilibriumInterior = in.getBool("coupling");
  c.implicit = in.getBool("coupling");
  setCouplingSettings(c);  // its own checks
  coversCells_ = in.getBool("flags");
  watch_.load(in);
  if (in.getBool("lattice")) lattice_ = lb::Lattice::loadState(in);
  attachParts();
  assembly_.loadState(in);
  // As it was, unchecked against the elements' critical step: the next step checks.
  if (substeps < 1 || substeps > kMaxSubsteps) ByteReader::fail("it holds a bad substep count");
  substeps_ = substeps;
}

}  // namespace sf::sim
