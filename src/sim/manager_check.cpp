// Manager::validate and Manager::stateHash: what tests, the fuzzer and
// "sim check" / "sim hash" ask of a scene.
#include <cmath>

#include "sandflow/core/checksum.hpp"
#include "sandflow/sim/manager.hpp"

namespace sf::sim {

std::vector<std::string> Manager::validate() const {
  std::vector<std::string> problems;
  if (!std::isfinite(time_) || steps_ < 0)
    problems.push_back("the clock reads t = " + formatNumber(time_) + " at step " +
                       std::to_string(steps_));
  if (!gravity_.allFinite()) problems.push_back("gravity is not finite");
  if (lattice_) {
    for (std::string& p : lattice_->validate()) problems.push_back(std::move(p));
    // A changed topology (an obstacle, new walls) drops the covered cells
    // until the coupling measures them again before the next step, and a
    // loaded scene's coupling has measured nothing yet: compare only when
    // both hold cells.
    if (coversCells_ && !lattice_->coveredCells().empty() && coupler_.coveredCells() > 0 &&
        lattice_->coveredCells().size() != coupler_.coveredCells())
      problems.push_back("the lattice's covered cells are not the coupling's");
  }
  for (std::string& p : assembly_.validate()) problems.push_back(std::move(p));
  return problems;
}

std::uint32_t Manager::stateHash() const {
  ByteWriter bytes;
  saveState(bytes);
  return crc32Of(bytes.bytes().data(), bytes.bytes().size());
}

}  // namespace sf::sim
