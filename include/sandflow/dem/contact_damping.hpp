#pragma once
// The normal damping ratio that gives a contact the restitution its materials
// ask for (docs/dem.md, "How the damping is chosen").
//
// Linear law. The three integrators advance a contact by one map: the force
// at a position reads the half-step velocity that led to it (central and
// verlet: v(t - dt/2); euler's v is that same velocity). Per step,
//   u' = u - (dt/m*)(kn d + s cn u),   d' = d + dt u'   (d overlap, u = dd/dt),
// with s = min(1, d/(|u| dt)) the part of the step the contact spans (see
// contactLaw). The rebound over the approach speed depends only on the
// damping ratio zeta (cn = 2 zeta sqrt(m* kn)), on h = dt sqrt(kn/m*) and on
// where within a step the contact begins (the entry phase). zeta is solved,
// by bisection, for the mean rebound over entry phases to be e; one impact
// scatters about it (docs/dem.md gives how much).
#include <cstddef>
#include <vector>

namespace sf::dem {

// Mean over entry phases of the rebound speed of a linear contact stepped at
// h = dt sqrt(kn/m*) with damping ratio zeta, for a unit approach speed.
// compressive: the normal force is clamped at 0 (the contact then ends where
// it vanishes).
double discreteRestitution(double h, double zeta, bool compressive);
// The restitution of the continuous laws (speed-independent): linear, and
// Hertz with the damping 2 zeta sqrt(m* kn(d)).
double linearRestitution(double zeta, bool compressive);
double hertzRestitution(double zeta, bool compressive);

// Above this h (contacts under about 6 steps) the damped map stops being
// monotone in zeta: the continuous ratio is used there.
inline constexpr double largestSolvedStep = 0.5;
// Up to it the ratio is solved at nodes h = j stepNode and interpolated
// linearly between them; below the first node (contacts over about 160
// steps), between that node and the continuous ratio (h = 0). Either way the
// mean rebound is within 1.5e-4 of e (measured for e = 0.1 to 0.9).
inline constexpr double stepNode = 1.0 / 512;
inline constexpr int firstNode = 10;  // h = 0.0195

// The ratios, solved when first asked for and kept: per restitution and
// normal-force mode (a scene has a few), the linear law's continuous ratio and
// nodes in h, and the Hertz law's. A pure function of its arguments.
class DampingRatios {
 public:
  // Linear law at h = dt sqrt(kn/m*); h = 0 (or not finite) for the
  // continuous law.
  double linear(double e, bool compressive, double h);
  double hertz(double e, bool compressive);

 private:
  struct Table {
    double e;
    bool compressive;
    double continuous, hertz;   // NaN until solved
    std::vector<double> nodes;  // at h = j stepNode, NaN until solved
  };
  Table& table(double e, bool compressive);
  double continuous(Table& t);
  double node(Table& t, int j);
  std::vector<Table> tables_;
  std::size_t last_ = 0;  // the table asked for last
};

}  // namespace sf::dem
