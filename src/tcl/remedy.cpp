#include "remedy.hpp"

namespace sf::tcl {

std::string withRemedy(const std::string& text, const Advice& advice) {
  switch (advice.remedy) {
    case Remedy::none:
      return text;
    case Remedy::createLattice:
      return text + ": use \"lattice create\"";
    case Remedy::deleteLattice:
      return text + ": \"lattice delete\" it first";
    case Remedy::viscosityOrTimestep:
      return text + ": give -viscosity (or a timestep with \"sim configure -timestep\")";
    case Remedy::setTimestep:
      return text + "; set one with \"sim configure -timestep\"";
    case Remedy::implicitCoupling:
      return text + ": use \"sim configure -coupling implicit\" (stable at any density)";
    case Remedy::trtCollision:
      return text + ", or use \"-collision trt\" (exact walls at any tau)";
    case Remedy::elementSubsteps: {
      // No count: more substeps than a step may take; only a smaller timestep helps.
      const std::string smaller = "a timestep under the critical one";
      if (advice.count < 1) return text + ": use " + smaller + " (\"sim configure -timestep\")";
      return text + ": use \"sim configure -substeps " + std::to_string(advice.count) +
             "\" with this timestep (or " + smaller + ")";
    }
  }
  return text;
}

}  // namespace sf::tcl
