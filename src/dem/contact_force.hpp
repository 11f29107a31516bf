#pragma once
// The contact force law (physics.md §4): spring-dashpot normal force (linear
// or Hertz), incremental shear spring turned with the contact, Coulomb cap.
// Written once on plain doubles and without branches on the data, so that the
// vector pass over disc pairs (disc_contacts.cpp) and the one-by-one pass over
// the other pairs (contact_force.cpp) share it, and the compiler can run
// several contacts in one vector register.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>

#include "sandflow/dem/contact_list.hpp"
#include "sandflow/dem/material.hpp"
#include "sandflow/dem/shape.hpp"

namespace sf::dem::detail {

// The step's view of the elements, as raw arrays.
struct ContactInputs {
  const Vec2* x;
  const double* angle;
  const double* reach;  // a disc's radius
  const Vec2* v;        // the velocities the dashpots see
  const double* w;
  const std::unique_ptr<Shape>* shape;
  const PairLaw* laws;  // indexed by ContactList::law
  double dt, invDt;     // the step and its inverse (the spanned dashpot)
  double maxOverlap;    // a touching contact deeper than this x its minSize stops the step
};

// Whether a touching contact stops the step: too deep, or a force that is not
// finite (|f| <= max is false for infinities and NaN).
[[gnu::always_inline]] inline bool stops(double overlap, double minSize, double fx, double fy,
                                         double maxOverlap) {
  constexpr double big = 1.7976931348623157e308;
  return (overlap > maxOverlap * minSize) | !(std::abs(fx) <= big) | !(std::abs(fy) <= big);
}

// One touching contact: the manifold, the two bodies' centres and motion, the
// law and the history.
struct LawInput {
  double nx, ny, overlap, px, py;                   // unit normal a -> b, overlap > 0, point
  double xi, yi, vix, viy, wi;                      // body a
  double xj, yj, vjx, vjy, wj;                      // body b
  double kn, ks, friction, dampingPart, dt, invDt;  // dampingPart: see ContactList
  double normalFloor;  // the least normal force: 0 (compressive) or -infinity (signed)
  bool spanned;        // the normal dashpot acts over the part of a step the contact spans
  bool hertz;          // then: R*, E*, G* and whether the damping is fixed (else from zeta)
  double radius, youngs, shearModulus;
  bool fixedDamping;
  bool touching;              // had a history
  double onx, ony, osx, osy;  // the history: normal and shear spring
};

struct LawOutput {
  double fx, fy;  // total force on b
  double sx, sy;  // the new shear spring
};

[[gnu::always_inline]] inline LawOutput contactLaw(const LawInput& c) {
  const double rix = c.px - c.xi, riy = c.py - c.yi, rjx = c.px - c.xj, rjy = c.py - c.yj;
  // Relative velocity of b's surface against a's at the point (w x r).
  const double vrx = (c.vjx + -c.wj * rjy) - (c.vix + -c.wi * riy);
  const double vry = (c.vjy + c.wj * rjx) - (c.viy + c.wi * rix);
  const double vn = vrx * c.nx + vry * c.ny;
  const double vtx = vrx - vn * c.nx, vty = vry - vn * c.ny;
  double kn = c.kn, ks = c.ks, fElastic = c.kn * c.overlap, cn = c.dampingPart;
  if (c.hertz) {  // stiffnesses grow with the contact radius sqrt(R* d)
    const double root = std::sqrt(c.radius * c.overlap);
    fElastic = 4.0 / 3.0 * c.youngs * root * c.overlap;
    kn = 2.0 * c.youngs * root;
    ks = 8.0 * c.shearModulus * root;
    if (!c.fixedDamping) cn = c.dampingPart * std::sqrt(kn);  // 2 zeta sqrt(m* kn)
  }
  // A normal dashpot solved for the step (ContactSet::prepareDamping says
  // which) acts over the part s of the step the contact spans: where it
  // begins, overlap / |vn| is the time since; where it ends, the time left.
  // Otherwise its force jumps by cn vn there,
  // and an impact's rebound depends on where in a step it began: by -51% to
  // -26% at e = 0.1 and dt_crit/10, +-3% with the span (docs/dem.md).
  // cn vn s = cn sign(vn) overlap / dt: no division. contact_damping.cpp
  // solves the damping for this law.
  const bool partial = c.spanned & (std::abs(vn) * c.dt > c.overlap);
  const double dashpot = partial ? cn * std::copysign(c.overlap, vn) * c.invDt : cn * vn;
  // Along the normal, on b. Clamped or not, selected, not branched (a NaN
  // stays a NaN for the watch).
  const double fn = std::max(fElastic - dashpot, c.normalFloor);

  // Incremental shear spring, turned with the contact: by the rotation that
  // takes last step's normal to this one (the projection only sweeps up
  // round-off). A new contact starts from zero.
  const double cs = c.onx * c.nx + c.ony * c.ny, sn = c.onx * c.ny - c.ony * c.nx;
  const double tx = cs * c.osx - sn * c.osy, ty = sn * c.osx + cs * c.osy;
  const double along = tx * c.nx + ty * c.ny;
  const double turnedX = tx - along * c.nx, turnedY = ty - along * c.ny;
  const double ksdt = ks * c.dt;
  double sx = (c.touching ? turnedX : 0.0) - ksdt * vtx;
  double sy = (c.touching ? turnedY : 0.0) - ksdt * vty;
  const double ct = 0.5 * cn;
  double ftx = sx - ct * vtx, fty = sy - ct * vty;
  // Friction bears on compression only: near separation the damping can make
  // a signed fn tensile, and |fn| there would add friction impulse (5% too
  // much spin in an oblique impact; still 3% with the cap at 0, since the pull
  // lowers the normal impulse: the compressive mode clamps fn itself).
  // Sliding: the spring holds what friction allows;
  // selected, not branched, since contacts stick and slip unpredictably.
  const double cap = c.friction * (fn < 0.0 ? 0.0 : fn), ftn2 = ftx * ftx + fty * fty;
  const bool sliding = ftn2 > cap * cap;
  const double scale = cap / std::sqrt(ftn2 > 0 ? ftn2 : 1.0);
  const double slidX = ftx * scale, slidY = fty * scale;
  const double heldX = slidX + ct * vtx, heldY = slidY + ct * vty;
  ftx = sliding ? slidX : ftx;
  fty = sliding ? slidY : fty;
  sx = sliding ? heldX : sx;
  sy = sliding ? heldY : sy;
  return {fn * c.nx + ftx, fn * c.ny + fty, sx, sy};
}

// The radius of curvature the Hertz law sees: a wall is flat.
inline double curvatureRadius(const Shape& shape) {
  return shape.type() == ShapeType::wall ? std::numeric_limits<double>::infinity()
                                         : shape.contactSize();
}

inline double normalFloor(const PairLaw& law) {
  return law.compressive ? 0.0 : -std::numeric_limits<double>::infinity();
}

// The law's inputs of contact k from the list, the elements and the pair's law
// (the manifold is filled by the caller).
[[gnu::always_inline]] inline LawInput lawInput(const ContactList& l, std::size_t k,
                                                const ContactInputs& in) {
  const int i = l.a[k], j = l.b[k];
  const PairLaw& law = in.laws[l.law[k]];
  const ContactHistory& h = l.now();
  LawInput c;
  c.xi = in.x[i].x(), c.yi = in.x[i].y(), c.vix = in.v[i].x(), c.viy = in.v[i].y(), c.wi = in.w[i];
  c.xj = in.x[j].x(), c.yj = in.x[j].y(), c.vjx = in.v[j].x(), c.vjy = in.v[j].y(), c.wj = in.w[j];
  c.kn = law.kn, c.ks = law.ks, c.friction = law.friction, c.dampingPart = l.dampingPart[k],
  c.dt = in.dt, c.invDt = in.invDt;
  c.normalFloor = l.normalFloor[k], c.spanned = l.spanned[k] != 0;
  c.hertz = law.hertz, c.radius = l.radius[k], c.youngs = law.effectiveYoungs;
  c.shearModulus = law.effectiveShear, c.fixedDamping = law.damping >= 0;
  c.touching = h.touching[k] != 0;
  c.onx = h.nx[k], c.ony = h.ny[k], c.osx = h.sx[k], c.osy = h.sy[k];
  return c;
}

// Contacts [begin, end) of the list that are not linear disc pairs, one by one
// through the narrow-phase table: the next history and the results. Returns
// the first that stops the step (see stops), or `end`.
std::size_t evaluateOthers(ContactList& l, std::size_t begin, std::size_t end,
                           const ContactInputs& in);

}  // namespace sf::dem::detail
