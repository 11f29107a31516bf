// Lattice::validate: the invariants the step relies on, checked afresh.
#include <cmath>
#include <set>

#include "sandflow/lb/lattice.hpp"

namespace sf::lb {

std::vector<std::string> Lattice::validate() const {
  std::vector<std::string> problems;
  for (int j = 0; j < p_.ny && problems.empty(); ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (!holdsFluid(x)) continue;
      double rho, jx, jy;
      moments(f_, layout_, x, rho, jx, jy);
      if (!std::isfinite(rho + jx + jy) || !(rho > 0)) {
        problems.push_back("lattice node (" + std::to_string(i) + ", " + std::to_string(j) +
                           ") holds density " + formatNumber(rho));
        break;
      }
    }
  std::set<int> ids;
  for (int id : obstacleIds())
    if (!ids.insert(id).second) problems.push_back("obstacle id " + std::to_string(id) + " twice");
  const std::vector<CoveredCell>& cells = covered_.cells;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const CoveredCell& c = cells[k];
    const std::string which = "covered cell " + std::to_string(k);
    if (c.node < 0 || std::size_t(c.node) >= kind_.size() || kind_[c.node] != NodeKind::fluid)
      problems.push_back(which + " is not on a bulk-fluid node");
    if (!(c.eps > 0 && c.eps <= 1) || !std::isfinite(c.ux) || !std::isfinite(c.uy))
      problems.push_back(which + " has solid ratio " + formatNumber(c.eps) + " or a velocity " +
                         "that is not finite");
  }
  return problems;
}

}  // namespace sf::lb
