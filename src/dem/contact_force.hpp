#pragma once
// The force of one candidate pair (physics.md §4): narrow phase, spring-dashpot
// normal force, incremental shear spring turned with the contact, Coulomb cap.
// The step's contact loop runs it over every pair, on one thread or several.
// The inputs are raw pointers: the loop stores bytes (flags), which may alias
// anything, and would otherwise make the compiler reload every vector's data
// pointer after each store.
#include <algorithm>
#include <cmath>
#include <memory>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem::detail {

struct ContactInputs {
  const Vec2* x;
  const double* angle;
  const double* reach;  // a disc's radius
  const Vec2* v;        // the velocities the dashpots see
  const double* w;
  const std::unique_ptr<Shape>* shape;
  const PairLaw* laws;  // indexed by Contact::law
  double dt;
};

// Updates c for this step: touching, normal, point, overlap, force and the
// shear spring. The contact's cached law, size and damping must be current.
[[gnu::always_inline]] inline void evaluateContact(Contact& c, const ContactInputs& in) {
  const int i = c.a, j = c.b;
  Manifold m;
  // Disc pairs skip the dispatch (reach is a disc's radius).
  const bool hit = c.discs ? collideDiscs(in.x[i], in.reach[i], in.x[j], in.reach[j], m)
                           : collide(*in.shape[i], {in.x[i], in.angle[i]}, *in.shape[j],
                                     {in.x[j], in.angle[j]}, m);
  if (!hit) {
    c.touching = false;
    c.force = Vec2::Zero();
    c.shear = Vec2::Zero();
    return;
  }
  const PairLaw& law = in.laws[c.law];
  const Vec2 ri = m.point - in.x[i], rj = m.point - in.x[j];
  const Vec2 vrel = (in.v[j] + spin(in.w[j], rj)) - (in.v[i] + spin(in.w[i], ri));
  const Vec2& nrm = m.normal;
  const double vn = vrel.dot(nrm);
  const Vec2 vt = vrel - vn * nrm;
  double kn = law.kn, ks = law.ks, fElastic = law.kn * m.overlap;
  if (law.hertz) {  // stiffnesses grow with the contact radius sqrt(R* d)
    const double root = std::sqrt(c.radius * m.overlap);
    fElastic = 4.0 / 3.0 * law.effectiveYoungs * root * m.overlap;
    kn = 2.0 * law.effectiveYoungs * root;
    ks = 8.0 * law.effectiveShear * root;
  }
  const double cn = law.hertz && law.damping < 0 ? c.damping * std::sqrt(kn) : c.damping;
  const double fn = fElastic - cn * vn;  // along the normal, on j

  // Incremental shear spring, turned with the contact: by the rotation that
  // takes last step's normal to this one (the projection only sweeps up
  // round-off).
  Vec2 shear = Vec2::Zero();
  if (c.touching) {
    const double cs = c.normal.dot(nrm), sn = cross(c.normal, nrm);
    shear = Vec2(cs * c.shear.x() - sn * c.shear.y(), sn * c.shear.x() + cs * c.shear.y());
    shear -= shear.dot(nrm) * nrm;
  }
  shear -= ks * in.dt * vt;
  const double ct = 0.5 * cn;
  Vec2 ft = shear - ct * vt;
  // Friction bears on compression only: near separation the damping can make
  // fn tensile, and |fn| there would add friction impulse (5% too much spin
  // in an oblique impact).
  const double cap = law.friction * std::max(fn, 0.0), ftn2 = ft.squaredNorm();
  // Sliding: the spring holds what friction allows. Selected, not branched: a
  // bed's contacts stick and slip unpredictably, and a mispredicted branch
  // costs more than the square root.
  const bool sliding = ftn2 > cap * cap;
  const double scale = cap / std::sqrt(ftn2 > 0 ? ftn2 : 1.0);
  const double fx = ft.x() * scale, fy = ft.y() * scale;
  const double sx = fx + ct * vt.x(), sy = fy + ct * vt.y();
  ft = Vec2(sliding ? fx : ft.x(), sliding ? fy : ft.y());
  shear = Vec2(sliding ? sx : shear.x(), sliding ? sy : shear.y());
  c.touching = true;
  c.normal = nrm;
  c.point = m.point;
  c.overlap = m.overlap;
  c.force = fn * nrm + ft;
  c.shear = shear;
}

// The first pass over the candidates: whether a pair may touch. Disc pairs are
// tested here, without a branch (whether a bed's pairs touch is not
// predictable), and cleared when they part; other shapes always go on to
// evaluateContact.
[[gnu::always_inline]] inline bool mayTouch(Contact& c, const ContactInputs& in) {
  const Vec2 d = in.x[c.b] - in.x[c.a];
  const double reach = in.reach[c.a] + in.reach[c.b];
  const bool hit = !c.discs | (d.squaredNorm() < reach * reach);
  if (!hit & c.touching) {  // parted since the last step: rare, so predictable
    c.touching = false;
    c.force = Vec2::Zero();
    c.shear = Vec2::Zero();
  }
  return hit;
}

// Whether a touching contact stops the step: too deep, or a force that is not finite.
inline bool excessive(const Contact& c, double maxOverlap) {
  return c.touching && (c.overlap > maxOverlap * c.size || !c.force.allFinite());
}

}  // namespace sf::dem::detail
