// The implicit coupling's solve for the velocity the fluid sees, and the
// explicit coupling's feedback ratio that decides when it is needed
// (docs/coupling.md, Stability).
#include <Eigen/Cholesky>
#include <algorithm>

#include "coupler_detail.hpp"
#include "sandflow/coupling/coupler.hpp"
#include "sandflow/dem/shape.hpp"

namespace sf::coupling {

// The implicit coupling. The momentum a cell gives the fluid is linear in the
// solid velocity, E = beta (rho u_s - j) with beta = B (1 for an equilibrium
// interior), so an element's fluid force is F(V) = -K V + F0 for its rigid
// velocity V = (vx, vy, w). Solving the element's update together with it,
//   M (V - V0) = c dt (F_other + F(V)),   c = 1/2 (central, verlet) or 1 (euler),
// gives the velocity the fluid sees. Its interior fluid then cannot feed the
// one-step oscillation that makes the explicit coupling of light elements
// unstable (|lambda| = r / (2 + r) < 1 for any fluid-to-solid mass ratio r).
// Cells shared with other solids count the others' velocities as given.
void Coupler::solveVelocities(const lb::Lattice& lattice, const dem::Assembly& assembly,
                              const Settings& settings, const std::vector<lb::CoveredCell>& cells,
                              const Vec2& gravity) {
  const lb::ResolvedLattice& p = lattice.params();
  const dem::Bodies& b = assembly.bodies();
  const double dt = p.dt, toLattice = dt / p.h, scale = p.h * p.h * p.h / (dt * dt);
  const double tau = p.tau;
  std::vector<double> rho;
  std::vector<Vec2> j;
  lattice.pulledMoments(cells, rho, j);
  // The explicit cell velocities, to take the other owners' part from.
  std::vector<lb::CoveredCell> given = cells;
  blendVelocities(lattice, lattice.circles(), given);

  const int n = b.size();
  std::vector<Eigen::Matrix3d> K(n, Eigen::Matrix3d::Zero());
  std::vector<Vec3> F0(n, Vec3::Zero());
  for (int o = 0; o < n; ++o)  // the elements' pieces (circles move as prescribed)
    for (std::size_t g = pieceStart_[o]; g < pieceStart_[o + 1]; ++g) {
      const CellCover& piece = elements_[o].cells[g - pieceStart_[o]];
      const std::int32_t c = pieceCell_[g];
      const lb::CoveredCell& cell = cells[c];
      const double beta = cell.interior && settings.equilibriumInterior
                              ? 1.0
                              : cell.eps * (tau - 0.5) / ((1.0 - cell.eps) + (tau - 0.5));
      const double share =
          settings.share == Share::equal ? 1.0 / sharing(c) : piece.eps / epsSum_[c];
      const double alpha = piece.eps / epsSum_[c];
      const double r = rho[c];
      const Vec2& arm = piece.arm;
      const Vec3& V = velocity_[o];
      // This owner's own part of the explicit cell velocity, and the others'.
      const Vec2 own = alpha * toLattice * (Vec2(V.x(), V.y()) + spin(V.z(), arm));
      const Vec2 others = Vec2(given[c].ux, given[c].uy) - own;
      const double gain = scale * toLattice * share * beta * r * alpha;
      Eigen::Matrix3d k;
      k << 1, 0, -arm.y(), 0, 1, arm.x(), -arm.y(), arm.x(), arm.squaredNorm();
      K[o] += gain * k;
      const Vec2 f = scale * share * beta * (j[c] - r * others);
      F0[o] += Vec3(f.x(), f.y(), cross(arm, f));
    }
  const double c = assembly.integrator == dem::Integrator::euler ? 1.0 : 0.5;
  for (int s = 0; s < n; ++s) {
    if (K[s].isZero()) continue;
    const bool central = assembly.integrator == dem::Integrator::central && b.started[s];
    const Vec3 base = central ? Vec3(b.vHalf[s].x(), b.vHalf[s].y(), b.wHalf[s]) : velocity_[s];
    // Every force but the fluid's, as the last step left it.
    Vec3 other;
    if (b.started[s]) {
      other << b.force[s].x() - b.fluidForce[s].x(), b.force[s].y() - b.fluidForce[s].y(),
          b.torque[s] - b.fluidTorque[s];
    } else {
      // A new element has no buoyancy yet (collect gives it after this
      // step): without it the fluid would be pushed as if the element fell
      // under its full weight, a kick of up to half the fluid's weight in
      // its area on a nearly neutrally buoyant one.
      double submerged = 0;  // summed as collect does: the same bits
      for (const CellCover& piece : elements_[s].cells) submerged += piece.eps;
      const Vec2 buoyancy =
          settings.buoyancy ? detail::buoyancyOf(b, s, submerged, lattice, gravity) : Vec2::Zero();
      const Vec2 f = b.appliedForce[s] + b.mass[s] * (gravity + b.acceleration[s]) + buoyancy;
      other << f.x(), f.y(), b.appliedTorque[s];
    }
    const Vec3 M(b.mass[s], b.mass[s], b.inertia[s]);
    Eigen::Matrix3d A = c * dt * K[s];
    A.diagonal() += M;
    Vec3 rhs = M.cwiseProduct(base) + c * dt * (other + F0[s]);
    // Held degrees of freedom keep their prescribed velocity.
    const std::uint8_t hold[3] = {dem::holdX, dem::holdY, dem::holdRotation};
    for (int d = 0; d < 3; ++d)
      if (b.hold[s] & hold[d]) {
        rhs -= A.col(d) * velocity_[s][d];
        A.row(d).setZero();
        A.col(d).setZero();
        A(d, d) = 1;
        rhs[d] = velocity_[s][d];
      }
    velocity_[s] = A.ldlt().solve(rhs);
  }
}

double Coupler::explicitFeedback(const lb::Lattice& lattice, const dem::Bodies& b, int s) const {
  const bool moves = (b.hold[s] & (dem::holdX | dem::holdY)) != (dem::holdX | dem::holdY);
  const bool turns = !(b.hold[s] & dem::holdRotation);
  if (std::size_t(s) >= elements_.size() || elements_[s].cells.empty() || (!moves && !turns))
    return 0;
  const double a = lattice.params().tau - 0.5, h2 = lattice.params().h * lattice.params().h;
  double area = 0, moment = 0;  // sums of B h^2 and B |arm|^2 h^2
  for (const CellCover& c : elements_[s].cells) {
    const double beta = c.eps >= 1 ? 1.0 : c.eps * a / ((1.0 - c.eps) + a);
    area += beta * h2;
    moment += beta * c.arm.squaredNorm() * h2;
  }
  const double rho = lattice.params().def.density;
  return std::max(moves ? rho * area / b.mass[s] : 0.0, turns ? rho * moment / b.inertia[s] : 0.0);
}

}  // namespace sf::coupling
