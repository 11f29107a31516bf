#include "sandflow/dem/superquadric.hpp"

#include <cmath>
#include <numbers>

#include "sandflow/core/error.hpp"
#include "sandflow/dem/shape_checks.hpp"

namespace sf::dem {
namespace {

// Integral of u^p v^q over the quarter region u^m + v^n <= 1, u, v >= 0.
double moment(double p, double q, double m, double n) {
  const double s = (p + 1) / m, t = (q + 1) / n;
  return std::tgamma(s) * std::tgamma(t) / (m * n * std::tgamma(s + t + 1));
}

// |u|^e, with the common exponents done without pow().
double powAbs(double u, double e) {
  u = std::abs(u);
  if (e == 2) return u * u;
  if (e == 4) return (u * u) * (u * u);
  if (e == 1) return u;
  return std::pow(u, e);
}

}  // namespace

Superquadric::Superquadric(double a, double b, double m, double n, int samples)
    : a_(a), b_(b), m_(m), n_(n) {
  checkSemiAxes(a, b, "superquadric");
  checkExponents(m, n);
  if (samples < 8 || samples > 10000)  // the superquadric command's -sides range too
    throw Error("VALUE SIDES",
                "superquadric samples must be 8 to 10000, got " + std::to_string(samples));
  // Exact mass properties (beta-function integrals over the four quadrants).
  area_ = 4 * a * b * moment(0, 0, m, n);
  const double ixx = 4 * a * a * a * b * moment(2, 0, m, n);
  const double iyy = 4 * a * b * b * b * moment(0, 2, m, n);
  inertiaPerMass_ = (ixx + iyy) / area_;
  radius_ = 0;
  for (int k = 0; k < samples; ++k) {
    const double t = 2 * std::numbers::pi * k / samples;
    const double c = std::cos(t), s = std::sin(t);
    const Vec2 p(a * std::copysign(std::pow(std::abs(c), 2 / m), c),
                 b * std::copysign(std::pow(std::abs(s), 2 / n), s));
    outline_.push_back(p);
    radius_ = std::max(radius_, p.norm());
  }
}

std::vector<Vec2> Superquadric::world(const Vec2& x, double angle) const {
  std::vector<Vec2> out;
  out.reserve(outline_.size());
  for (const Vec2& p : outline_) out.push_back(x + rotated(p, angle));
  return out;
}

double Superquadric::implicit(const Vec2& p) const {
  return powAbs(p.x() / a_, m_) + powAbs(p.y() / b_, n_) - 1;
}

Vec2 Superquadric::gradient(const Vec2& p) const {
  auto part = [](double v, double axis, double e) {
    const double u = std::abs(v / axis);
    return u == 0 ? 0.0 : std::copysign(e * powAbs(u, e - 1) / axis, v);
  };
  return Vec2(part(p.x(), a_, m_), part(p.y(), b_, n_));
}

bool Superquadric::penetration(const Vec2& x, double angle, const Vec2& point, double& depth,
                               Vec2& normal) const {
  if ((point - x).squaredNorm() >= radius_ * radius_) return false;  // cheap rejection
  const Vec2 local = rotated(point - x, -angle);
  if (implicit(local) >= 0) return false;
  // Walk out along the gradient to the outline (Newton on F along the normal).
  Vec2 q = local;
  for (int it = 0; it < 8; ++it) {
    const Vec2 g = gradient(q);
    const double g2 = g.squaredNorm();
    if (g2 == 0) {  // the centre: leave along the shorter axis
      q = a_ < b_ ? Vec2(a_, 0) : Vec2(0, b_);
      break;
    }
    const double f = implicit(q);
    q -= f / g2 * g;
    if (std::abs(f) < 1e-12) break;
  }
  const Vec2 g = gradient(q);
  const Vec2 nLocal = g.norm() > 0 ? Vec2(g.normalized()) : Vec2(1, 0);
  depth = std::max(0.0, (q - local).dot(nLocal));
  normal = rotated(nLocal, angle);
  return depth > 0;
}

Box Superquadric::bounds(const Vec2& x, double angle) const {
  const double c = std::abs(std::cos(angle)), s = std::abs(std::sin(angle));
  const Vec2 half(c * a_ + s * b_, s * a_ + c * b_);
  return {x - half, x + half};
}

}  // namespace sf::dem
