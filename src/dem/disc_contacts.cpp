#include "disc_contacts.hpp"

#include <cmath>

#include "sandflow/core/kernel_isa.hpp"

namespace sf::dem::detail {

SF_KERNEL_CLONES
std::size_t linearDiscContacts(ContactList& l, std::size_t begin, std::size_t end,
                               const ContactInputs& in, const LawColumns& laws) {
  const double* __restrict x = in.x[0].data();  // Vec2 is two packed doubles
  const double* __restrict v = in.v[0].data();
  const double* __restrict w = in.w;
  const double* __restrict r = in.reach;
  const double* __restrict kn = laws.kn, * __restrict ks = laws.ks, * __restrict friction = laws.friction;
  const double* __restrict normalFloor = l.normalFloor.data();
  const std::int32_t* __restrict spanned = l.spanned.data();
  const int* __restrict pa = l.a.data(), * __restrict pb = l.b.data(), * __restrict law = l.law.data();
  const double* __restrict dampingPart = l.dampingPart.data();
  const ContactHistory& h = l.history[l.current];
  ContactHistory& next = l.history[1 - l.current];
  const std::int32_t* __restrict touching = h.touching.data();
  const double* __restrict onx = h.nx.data(), * __restrict ony = h.ny.data(), * __restrict osx = h.sx.data(), * __restrict osy = h.sy.data();
  std::int32_t* __restrict touchingOut = next.touching.data();
  double *__restrict nxOut = next.nx.data(), *__restrict nyOut = next.ny.data(),
                     *__restrict sxOut = next.sx.data(), *__restrict syOut = next.sy.data();
  double *__restrict fxOut = l.fx.data(), *__restrict fyOut = l.fy.data(),
                     *__restrict pxOut = l.px.data(), *__restrict pyOut = l.py.data(),
                     *__restrict overlapOut = l.overlap.data(), *__restrict taOut = l.ta.data(),
                     *__restrict tbOut = l.tb.data();
  const double* __restrict minSize = l.minSize.data();
  const double dt = in.dt, invDt = in.invDt, maxOverlap = in.maxOverlap;
  std::size_t first = end;
#pragma omp simd reduction(min : first)
  for (std::size_t k = begin; k < end; ++k) {
    const int i = pa[k], j = pb[k];
    LawInput c;
    c.xi = x[2 * i], c.yi = x[2 * i + 1], c.xj = x[2 * j], c.yj = x[2 * j + 1];
    // The narrow phase (collideDiscs): normal, overlap, point midway in the overlap.
    const double dx = c.xj - c.xi, dy = c.yj - c.yi;
    const double dist2 = dx * dx + dy * dy, ri = r[i], reach = ri + r[j];
    const bool hit = dist2 < reach * reach;
    const double dist = std::sqrt(dist2);
    const double inv = 1.0 / (dist > 0 ? dist : 1.0);
    c.nx = dist > 0 ? dx * inv : 1.0, c.ny = dist > 0 ? dy * inv : 0.0;
    c.overlap = reach - dist;
    const double arm = ri - 0.5 * c.overlap;
    c.px = c.xi + c.nx * arm, c.py = c.yi + c.ny * arm;
    c.vix = v[2 * i], c.viy = v[2 * i + 1], c.wi = w[i];
    c.vjx = v[2 * j], c.vjy = v[2 * j + 1], c.wj = w[j];
    const int lk = law[k];
    c.kn = kn[lk], c.ks = ks[lk], c.friction = friction[lk], c.dampingPart = dampingPart[k],
    c.dt = dt, c.invDt = invDt, c.normalFloor = normalFloor[k], c.spanned = spanned[k] != 0;
    c.hertz = false, c.radius = 0, c.youngs = 0, c.shearModulus = 0, c.fixedDamping = true;
    c.touching = touching[k] != 0;
    c.onx = onx[k], c.ony = ony[k], c.osx = osx[k], c.osy = osy[k];
    const LawOutput f = contactLaw(c);
    touchingOut[k] = hit;
    nxOut[k] = c.nx, nyOut[k] = c.ny;
    sxOut[k] = hit ? f.sx : 0.0, syOut[k] = hit ? f.sy : 0.0;
    fxOut[k] = hit ? f.fx : 0.0, fyOut[k] = hit ? f.fy : 0.0;
    pxOut[k] = c.px, pyOut[k] = c.py, overlapOut[k] = c.overlap;
    // cross(point - centre, force), about each centre
    const double ta = (c.px - c.xi) * f.fy - (c.py - c.yi) * f.fx;
    const double tb = (c.px - c.xj) * f.fy - (c.py - c.yj) * f.fx;
    taOut[k] = hit ? ta : 0.0, tbOut[k] = hit ? tb : 0.0;
    const bool stop = hit & stops(c.overlap, minSize[k], f.fx, f.fy, maxOverlap);
    first = stop && k < first ? k : first;
  }
  return first;
}

}  // namespace sf::dem::detail
