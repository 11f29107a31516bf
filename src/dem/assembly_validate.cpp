// Assembly::validate: the invariants the step relies on, each part's own,
// checked afresh.
#include <cmath>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {

std::vector<std::string> Assembly::validate() const {
  std::vector<std::string> problems = bodies_.validate(materials_);
  // The parts index the element columns: not when those are broken.
  if (!problems.empty() && problems.front() == "the element columns differ in length")
    return problems;
  for (auto&& part : {contacts_.validate(bodies_), bonds_.validate(bodies_),
                      sources_.validate(bodies_), PlateServo::validate(bodies_)})
    problems.insert(problems.end(), part.begin(), part.end());
  if (!std::isfinite(time_)) problems.push_back("the elements' clock is not finite");
  return problems;
}

}  // namespace sf::dem
