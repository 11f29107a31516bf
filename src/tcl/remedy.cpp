#include "remedy.hpp"

namespace sf::tcl {

std::string withRemedy(const std::string& text, Remedy remedy) {
  switch (remedy) {
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
  }
  return text;
}

}  // namespace sf::tcl
