// Each contact law against its reference data (tests/fixtures/contact-laws):
// the normal force of a head-on impact of two equal discs, integrated by
// make_reference.tcl independently of sandflow (RK4, 200,000 steps), with a
// fixed damping coefficient so that the law is the textbook one. sandflow
// steps the same impact 4,000 times over the contact; its force, taken at
// the reference's times, must agree to 0.1% of the peak force (measured:
// 0.01% for both laws; a dashpot 10% off is 1.6% off, a law off by a factor
// or a term far more).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "sandflow/dem/assembly.hpp"

namespace sf::dem {
namespace {

struct Row {
  double t, overlap, rate, force;
};

std::vector<Row> readReference(const std::string& name) {
  std::ifstream in(std::string(SANDFLOW_FIXTURES_DIR) + "/contact-laws/" + name);
  EXPECT_TRUE(in) << "no reference " << name;
  std::vector<Row> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    Row r{};
    char comma;
    std::istringstream fields(line);
    fields >> r.t >> comma >> r.overlap >> comma >> r.rate >> comma >> r.force;
    rows.push_back(r);
  }
  return rows;
}

// The impact of make_reference.tcl stepped by sandflow: the force on the
// right disc along x at each step, with the step's time since contact began.
struct Series {
  std::vector<double> t, force;
};

Series impact(ContactLaw law, double dt) {
  Assembly a;
  Material m{"grain"};
  m.law = law;
  m.density = 1000;
  m.kn = m.ks = 1e5;
  m.friction = 0;
  m.damping = 20;
  m.youngs = 1e8;
  m.poisson = 0.3;
  a.materials().add(m);
  const double r = 0.01;
  auto add = [&](double x, double v) {
    ElementDef d;
    d.shape = std::make_unique<Disc>(r);
    d.material = 1;
    d.x = Vec2(x, 0);
    d.v = Vec2(v, 0);
    return a.add(std::move(d));
  };
  // Touching at t = 0 exactly, closing at 1 m/s (the reference's v0).
  add(-r, 0.5);
  const int right = add(r, -0.5);
  a.integrator = Integrator::verlet;
  Series s;
  for (int n = 0; n < 100000; ++n) {
    a.step(dt, Vec2::Zero());
    const double f = a.contactForce(a.slot(right)).x();
    if (n > 0 && f == 0.0) break;  // apart
    s.t.push_back((n + 1) * dt);
    s.force.push_back(f);
  }
  return s;
}

// The largest difference between the series and the reference at the
// reference's times (linear interpolation in the series), over the peak.
double worstDifference(const Series& s, const std::vector<Row>& ref) {
  double peak = 0, worst = 0;
  for (const Row& r : ref) peak = std::max(peak, std::abs(r.force));
  for (const Row& r : ref) {
    if (r.t < s.t.front() || r.t > s.t.back()) continue;
    std::size_t k = 0;
    while (s.t[k + 1] < r.t) ++k;
    const double w = (r.t - s.t[k]) / (s.t[k + 1] - s.t[k]);
    const double f = (1 - w) * s.force[k] + w * s.force[k + 1];
    worst = std::max(worst, std::abs(f - r.force));
  }
  return worst / peak;
}

// The impact at a 4000th of the reference's contact time: it lasts as long,
// and its force stays within 1e-3 of the peak of the reference's.
void expectMatchesReference(ContactLaw law, const char* file) {
  const std::vector<Row> ref = readReference(file);
  ASSERT_GT(ref.size(), 300u);
  const double duration = ref.back().t;
  const Series s = impact(law, duration / 4000);
  EXPECT_NEAR(s.t.back(), duration, 2 * duration / 4000);
  EXPECT_LT(worstDifference(s, ref), 1e-3);
}

TEST(ContactLawReference, LinearSpringDashpotMatchesItsReference) {
  expectMatchesReference(ContactLaw::linear, "linear.csv");
}

TEST(ContactLawReference, HertzMatchesItsReference) {
  expectMatchesReference(ContactLaw::hertz, "hertz.csv");
}

}  // namespace
}  // namespace sf::dem
