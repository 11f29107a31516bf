#include "disc_contacts.hpp"

#include <cmath>

#include "sandflow/lb/kernel_isa.hpp"

namespace sf::dem::detail {

SF_KERNEL_CLONES
void linearDiscContacts(const DiscPairs& pairs, std::ptrdiff_t begin, std::ptrdiff_t end,
                        const ContactInputs& in, const DiscResults& out) {
  const int* __restrict pa = pairs.a, * __restrict pb = pairs.b;
  const double *__restrict kn = pairs.kn, *__restrict ks = pairs.ks,
               *__restrict friction = pairs.friction, *__restrict damping = pairs.damping,
               *__restrict history = pairs.touching, *__restrict oldNx = pairs.nx,
               *__restrict oldNy = pairs.ny, *__restrict oldSx = pairs.sx,
               *__restrict oldSy = pairs.sy;
  const double* __restrict x = in.x[0].data();  // Vec2 is two packed doubles
  const double* __restrict v = in.v[0].data();
  const double* __restrict w = in.w;
  const double* __restrict r = in.reach;
  const double dt = in.dt;
  double* __restrict nxOut = out.nx, * __restrict nyOut = out.ny, * __restrict pxOut = out.px, * __restrict pyOut = out.py, * __restrict overlapOut = out.overlap, * __restrict fxOut = out.fx, * __restrict fyOut = out.fy, * __restrict sxOut = out.sx, * __restrict syOut = out.sy;
#pragma omp simd
  for (std::ptrdiff_t q = begin; q < end; ++q) {
    const int i = pa[q], j = pb[q];
    // collideDiscs
    const double xi = x[2 * i], yi = x[2 * i + 1], xj = x[2 * j], yj = x[2 * j + 1];
    const double dx = xj - xi, dy = yj - yi;
    const double dist2 = dx * dx + dy * dy, ri = r[i], reach = ri + r[j];
    const double dist = std::sqrt(dist2);
    const double inv = 1.0 / (dist > 0 ? dist : 1.0);
    const double nx = dist > 0 ? dx * inv : 1.0, ny = dist > 0 ? dy * inv : 0.0;
    const double overlap = reach - dist;
    const double arm = ri - 0.5 * overlap;
    const double px = xi + nx * arm, py = yi + ny * arm;
    // relative velocity at the contact point
    const double rix = px - xi, riy = py - yi, rjx = px - xj, rjy = py - yj;
    const double wi = w[i], wj = w[j];
    const double vjx = v[2 * j] + -wj * rjy, vjy = v[2 * j + 1] + wj * rjx;
    const double vix = v[2 * i] + -wi * riy, viy = v[2 * i + 1] + wi * rix;
    const double vrx = vjx - vix, vry = vjy - viy;
    const double vn = vrx * nx + vry * ny;
    const double vtx = vrx - vn * nx, vty = vry - vn * ny;
    const double cn = damping[q];
    const double fn = kn[q] * overlap - cn * vn;
    // shear spring turned with the contact
    const double onx = oldNx[q], ony = oldNy[q], osx = oldSx[q], osy = oldSy[q];
    const double cs = onx * nx + ony * ny, sn = onx * ny - ony * nx;
    double sx = cs * osx - sn * osy, sy = sn * osx + cs * osy;
    const double along = sx * nx + sy * ny;
    const bool touching = history[q] != 0;
    sx = touching ? sx - along * nx : 0.0;
    sy = touching ? sy - along * ny : 0.0;
    const double ksdt = ks[q] * dt;
    sx -= ksdt * vtx;
    sy -= ksdt * vty;
    const double ct = 0.5 * cn;
    double ftx = sx - ct * vtx, fty = sy - ct * vty;
    const double cap = friction[q] * (fn < 0.0 ? 0.0 : fn), ftn2 = ftx * ftx + fty * fty;
    const bool sliding = ftn2 > cap * cap;
    const double scale = cap / std::sqrt(ftn2 > 0 ? ftn2 : 1.0);
    const double slidX = ftx * scale, slidY = fty * scale;
    const double keepX = slidX + ct * vtx, keepY = slidY + ct * vty;
    ftx = sliding ? slidX : ftx;
    fty = sliding ? slidY : fty;
    sx = sliding ? keepX : sx;
    sy = sliding ? keepY : sy;
    nxOut[q] = nx, nyOut[q] = ny, pxOut[q] = px, pyOut[q] = py, overlapOut[q] = overlap;
    fxOut[q] = fn * nx + ftx, fyOut[q] = fn * ny + fty;
    sxOut[q] = sx, syOut[q] = sy;
  }
}

}  // namespace sf::dem::detail
