// The step's watch (step_watch.hpp): each check, its sentence, and the log.
#include "sandflow/sim/step_watch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "sandflow/sim/manager.hpp"

namespace sf::sim {
namespace {

// A measured number for a message, to `digits` significant digits (a box's
// width is 1.2000000000000002).
std::string rounded(double value, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

// What the sentences of files before version 4 say, to know them by.
struct Marker {
  WarningCode code;
  std::string_view text;
};
constexpr Marker kMarkers[] = {
    {WarningCode::bgkWallSlip, "with the BGK collision: its bounce-back walls slip"},
    {WarningCode::lightElement, "too light for the explicit coupling"},
    {WarningCode::selfOverlap, "its own periodic image"},
    {WarningCode::cellReynolds, "cell Reynolds number"},
    {WarningCode::demAccuracy, "over its accurate step"},
    {WarningCode::outrun, "faster than anything that drives it"},
    {WarningCode::solidMach, "over the lattice, beyond"},
    {WarningCode::underResolved, "across, under two lattice cells"},
    {WarningCode::mach, "Mach number"},
};

}  // namespace

void StepWatch::warn(WarningCode code, const std::string& text, Remedy remedy, int subject) {
  given_.insert({std::uint8_t(code), subject});
  const Warning w{text, remedy, code, subject};
  pending_.push_back(w);
  log_.push_back(w);
}

std::vector<Warning> StepWatch::take() {
  std::vector<Warning> out;
  out.swap(pending_);
  return out;
}

void StepWatch::checkCollision(const Manager& m) {
  const lb::Lattice& l = m.lattice();
  const lb::ResolvedLattice& p = l.params();
  if (p.def.collision != lb::Collision::bgk || !(p.tau > kBgkTauLimit) || !l.hasNoSlipSurfaces() ||
      given(WarningCode::bgkWallSlip))
    return;
  warn(WarningCode::bgkWallSlip,
       "tau " + rounded(p.tau, 6) +
           " with the BGK collision: its bounce-back walls slip, an error that grows as tau "
           "squared (channel flow 16 cells across is 5% off at tau 2, 15% at 3, 54% at 5, 250% "
           "at 10): keep tau at " +
           formatNumber(kBgkTauLimit) + " or less",
       Remedy::trtCollision);
}

void StepWatch::checkCoverage(const Manager& m) {
  const lb::Lattice& l = m.lattice();
  const lb::ResolvedLattice& p = l.params();
  const dem::Bodies& b = m.assembly().bodies();
  const coupling::Coupler& coupler = m.coupler();
  const coupling::SolidSpeed& fast = coupler.fastest();
  if (fast.mach > kMachWarnLimit && !given(WarningCode::solidMach))
    warn(WarningCode::solidMach,
         "the surface of " +
             (fast.element >= 0 ? "element " + std::to_string(fast.element)
                                : "obstacle " + std::to_string(fast.obstacle)) +
             " moves at Mach " + formatNumber(fast.mach) + " over the lattice, beyond " +
             formatNumber(kMachWarnLimit) +
             ": the fluid near it is no longer nearly incompressible");
  for (int s = 0; s < b.size(); ++s) {
    if (b.ghost[s] || b.shape[s]->type() == dem::ShapeType::wall) continue;
    const double size = 2 * b.extent[s];
    if (size >= 2 * p.h || given(WarningCode::underResolved, b.id[s])) continue;
    warn(WarningCode::underResolved,
         "element " + std::to_string(b.id[s]) + " is " + formatNumber(size) +
             " across, under two lattice cells (h = " + formatNumber(p.h) +
             "): the fluid does not resolve it",
         Remedy::none, b.id[s]);
  }
  const coupling::SelfOverlap& o = coupler.selfOverlapping();
  if (o.count > 0 && !given(WarningCode::selfOverlap)) {
    double wide = 0;  // the first one's extent along (the first of) its axes
    const int axis = o.axes & 1 ? 0 : 1;
    if (o.element >= 0) {
      for (int s = 0; s < b.size(); ++s)
        if (b.id[s] == o.element) {
          const dem::Box box = b.shape[s]->bounds(b.x[s], b.angle[s]);
          wide = box.hi[axis] - box.lo[axis];
        }
    } else {
      for (const lb::CircleObstacle& c : l.circles())
        if (c.id == o.obstacle) wide = 2 * c.radius;
    }
    const double length = (axis == 0 ? p.nx : p.ny) * p.h;
    const std::string more = o.count > 1 ? " (and " + std::to_string(o.count - 1) + " more)" : "";
    warn(WarningCode::selfOverlap,
         (o.element >= 0 ? "element " + std::to_string(o.element)
                         : "obstacle " + std::to_string(o.obstacle)) +
             more + " is " + rounded(wide, 6) + " wide along " + (axis == 0 ? "x" : "y") +
             (wide >= length
                  ? ", as wide as the periodic lattice (" + rounded(length, 6) + ") or wider"
                  : ", within a cell of the periodic lattice's " + rounded(length, 6)) +
             ": it meets its own periodic image, and the cells there get wrong solid ratios "
             "(fluid flows through it); make the lattice wider than the element by a cell or "
             "more");
  }
  if (m.couplingSettings().implicit || given(WarningCode::lightElement)) return;
  // |lambda| reaches 1 at r = 1 with the first-order integrator, at 1/2 with
  // the others (docs/coupling.md, Stability).
  const double limit = m.assembly().integrator == dem::Integrator::euler ? 1.0 : 0.5;
  const double rho = p.def.density;
  int first = -1, count = 0;
  double feedback = 0;
  for (int s = 0; s < b.size(); ++s) {
    if (b.ghost[s] || b.shape[s]->type() == dem::ShapeType::wall) continue;
    // r is at most rho A / m (B <= eps), a quarter more for the stair-step
    // and subcell ratios: most elements are heavier and need no sum.
    if (1.25 * rho * b.shape[s]->area() < limit * b.mass[s]) continue;
    const double r = coupler.explicitFeedback(l, b, s);
    if (!(r >= limit) || count++ > 0) continue;
    first = s, feedback = r;
  }
  if (count == 0) return;
  warn(WarningCode::lightElement,
       "element " + std::to_string(b.id[first]) +
           (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") + ", of density " +
           rounded(b.mass[first] / (b.shape[first]->area() * rho), 3) +
           " times the fluid's, is too light for the explicit coupling: the fluid inside it "
           "feeds back " +
           rounded(feedback, 3) + " of its motion each step, at or over the limit " +
           formatNumber(limit) + ", so its velocity will flip sign from step to step and grow",
       Remedy::implicitCoupling);
}

// Over the accurate step, impacts rebound off their set restitution (by
// 20% or more at twice it, docs/stability.md) and can gain energy; over the
// stable step a lasting contact grows. The critical step (refused before)
// is the undamped single element's, so both can lie under it.
void StepWatch::checkDemAccuracy(const Manager& m, double dt) {
  const dem::Assembly::TimestepLimits limits = m.assembly().timestepLimits();
  if (!(dt > limits.accurate) || given(WarningCode::demAccuracy)) return;
  const int more = int(std::ceil(m.substeps() * dt / limits.accurate));
  const bool unstable = dt > limits.stable;
  warn(WarningCode::demAccuracy,
       "the element step " + formatNumber(dt) + " is " + rounded(dt / limits.accurate, 3) +
           " times over its accurate step " + formatNumber(limits.accurate) +
           " (0.5 sqrt(m*/k), effective mass m* " + formatNumber(limits.effectiveMass) +
           ", stiffness k " + formatNumber(limits.stiffness) + ")" +
           (unstable ? " and over its stable step " + formatNumber(limits.stable) +
                           " (2 sqrt(m*/k) (sqrt(1 + zeta^2) - zeta), damping ratio zeta " +
                           rounded(limits.zeta, 3) + "): a lasting contact will grow without bound"
                     : ": a contact spans under 6 steps, so impacts rebound off their set "
                       "restitution and can gain energy") +
           "; take " + std::to_string(more) + " element substeps per step, or a timestep " +
           std::to_string(more) + " times smaller");
}

void StepWatch::checkFluid(const Manager& m, long long age) {
  const lb::Lattice& l = m.lattice();
  const lb::ResolvedLattice& p = l.params();
  const double mach = l.lastStepMach();
  const std::string step = std::to_string(m.stepCount() + 1);
  if (mach > kMachWarnLimit && !given(WarningCode::mach))
    warn(WarningCode::mach,
         "Mach number " + formatNumber(mach) + " at step " + step + " exceeds " +
             formatNumber(kMachWarnLimit) +
             ": the flow is no longer nearly incompressible (reduce the timestep or the forcing)");
  // Near tau 0.5 the viscosity is too small for the grid: grid-scale
  // oscillations grow, unseen by the Mach check until the flow is several
  // times faster than anything drives it (docs/stability.md, tau).
  const double re = mach / ((p.tau - 0.5) / 3);  // nu in lattice units, as the speed
  if (re > kCellReynoldsLimit && !given(WarningCode::cellReynolds))
    warn(WarningCode::cellReynolds,
         "the cell Reynolds number u h / nu is " + rounded(re, 3) + " at step " + step +
             " (fastest fluid " + formatNumber(mach) + " of the lattice speed, tau " +
             rounded(p.tau, 6) + "), over " + formatNumber(kCellReynoldsLimit) +
             ": with tau this near 0.5 grid-scale oscillations can grow unseen; refine the "
             "lattice or raise tau (more viscosity or a smaller timestep)");
  // A flow driven only by its walls and held solids (no forcing, no inlet, no
  // pressure side, no free element) stays about as slow as they are; twice
  // the fastest of them is going unstable (TRT at tau 10, lid 0.04 c:
  // docs/stability.md, problem 6). A free element's wake can outlive its
  // motion, so scenes with one are not judged; nor is a lattice's start,
  // whose sound waves can outrun an impulsively started wall (Couette at 320
  // cells: 2.3 times at step 2) until they have crossed it twice.
  if (given(WarningCode::outrun) || !p.def.forcing.isZero() || age < 4LL * std::max(p.nx, p.ny))
    return;
  const dem::Bodies& b = m.assembly().bodies();
  if (m.solidsCoverCells())
    for (int s = 0; s < b.size(); ++s)
      if (b.invMass[s] > 0 || b.invInertia[s] > 0) return;
  double driver = m.solidsCoverCells() ? m.coupler().fastest().mach : 0.0;
  for (const lb::SideDef& side : p.def.sides) {
    if (side.kind == lb::SideKind::velocity || side.kind == lb::SideKind::pressure) return;
    if (side.kind == lb::SideKind::noslip)
      driver = std::max(driver, p.velocityToLattice(side.velocity.norm()));
  }
  // A circular wall's solid turns rigidly: out to its rim, or, for one that
  // holds the fluid inside it, out to the lattice's farthest corner (the
  // covered nodes there move with it, and the fastest fluid counts them).
  const Vec2 lo = p.def.origin, hi = lo + Vec2(p.nx * p.h, p.ny * p.h);
  for (const lb::CircleObstacle& c : l.circles()) {
    double reach = c.radius;
    if (c.outside)
      for (const Vec2& corner : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())})
        reach = std::max(reach, (corner - c.centre).norm());
    driver = std::max(driver, p.velocityToLattice(c.velocity.norm() + std::abs(c.spin) * reach));
  }
  // Under a billionth of the lattice speed both are rounding noise.
  if (!(driver > 1e-9) || !(mach > 2 * driver)) return;
  warn(WarningCode::outrun,
       "the fluid moves at " + rounded(mach / driver, 3) +
           " times the fastest wall or solid at "
           "step " +
           step + " (" + formatNumber(mach) + " against " + formatNumber(driver) +
           " of the lattice speed), faster than anything that drives it: the flow is going "
           "unstable (tau " +
           rounded(p.tau, 6) + "; a smaller tau, a finer lattice or a smaller timestep)");
}

void StepWatch::save(ByteWriter& out) const {
  out.put(std::uint64_t(log_.size()));
  for (const Warning& w : log_)
    out.put(std::uint8_t(w.code)), out.put(std::int32_t(w.subject)), out.put(w.text),
        out.put(std::uint8_t(w.remedy));
  out.put(std::uint64_t(given_.size()));
  for (const auto& [code, subject] : given_) out.put(code), out.put(std::int32_t(subject));
}

void StepWatch::load(ByteReader& in) {
  *this = StepWatch();
  const auto remedyOf = [&](std::uint8_t r) {
    if (r >= kRemedyCount) ByteReader::fail("it holds an unknown remedy");
    return Remedy(r);
  };
  const auto codeOf = [&](std::uint8_t c) {
    if (c >= kWarningCodeCount) ByteReader::fail("it holds an unknown warning");
    return WarningCode(c);
  };
  if (in.version >= 4) {
    log_.resize(in.count(14, "warnings"));
    for (Warning& w : log_) {
      w.code = codeOf(in.get<std::uint8_t>("warnings"));
      w.subject = in.get<std::int32_t>("warnings");
      in.get(w.text, "warnings");
      w.remedy = remedyOf(in.get<std::uint8_t>("warnings"));
    }
    const std::size_t given = in.count(5, "warnings");
    for (std::size_t k = 0; k < given; ++k) {
      const std::uint8_t code = std::uint8_t(codeOf(in.get<std::uint8_t>("warnings")));
      given_.insert({code, in.get<std::int32_t>("warnings")});
    }
    return;
  }
  // Before version 4: the Mach flags, the elements warned of their size,
  // then the sentences (version 2 on with their remedies), known by their words.
  const bool mach = in.getBool("flags"), solidMach = in.getBool("flags");
  std::vector<int> small;
  in.get(small, "warnings");
  log_.resize(in.count(8, "warnings"));
  for (Warning& w : log_) {
    in.get(w.text, "warnings");
    if (in.version >= 2) w.remedy = remedyOf(in.get<std::uint8_t>("warnings"));
    for (const Marker& k : kMarkers)
      if (w.text.find(k.text) != std::string::npos) {
        w.code = k.code;
        break;
      }
    if (w.code != WarningCode::mach && w.code != WarningCode::solidMach &&
        w.code != WarningCode::underResolved)
      given_.insert({std::uint8_t(w.code), -1});
  }
  if (mach) given_.insert({std::uint8_t(WarningCode::mach), -1});
  if (solidMach) given_.insert({std::uint8_t(WarningCode::solidMach), -1});
  for (const int id : small) given_.insert({std::uint8_t(WarningCode::underResolved), id});
}

}  // namespace sf::sim
