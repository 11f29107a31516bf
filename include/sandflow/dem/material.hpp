#pragma once
// Materials and the contact parameters of a pair of them.
#include <string>
#include <vector>

namespace sf::dem {

enum class ContactLaw { linear = 0, hertz = 1 };
inline constexpr const char* contactLawNames[] = {"linear", "hertz", nullptr};
// The normal force as spring and dashpot give it, pulling for a moment as a
// contact opens (LAMMPS gran/hooke), or clamped at 0: then the friction's
// impulse in sliding is exactly mu times the normal one (docs/dem.md).
enum class NormalForce { signedForce = 0, compressive = 1 };
inline constexpr const char* normalForceNames[] = {"signed", "compressive", nullptr};

struct Material {
  std::string name;
  ContactLaw law = ContactLaw::linear;
  double density = 2650.0;
  double kn = 1e5;           // normal contact stiffness (force per overlap, per unit thickness)
  double ks = 1e5;           // tangential stiffness
  double friction = 0.5;     // Coulomb coefficient
  double restitution = 0.5;  // target normal restitution (sets the damping ratio) ...
  double damping = -1.0;     // ... or a fixed normal damping coefficient when >= 0
  NormalForce normalForce = NormalForce::signedForce;
  double bondStiffness = 1e5;
  double bondStrength = 1e3;
  double youngs = 70e9;  // Hertz-Mindlin: Young's modulus ...
  double poisson = 0.3;  // ... and Poisson's ratio
};

// Throws sf::Error naming the field when a value is out of range (the same
// ranges as the material command's option rows).
void validate(const Material& m);

// Normal damping ratio zeta for a restitution coefficient e (physics.md §4):
// zeta = -ln e / sqrt(pi^2 + ln^2 e); e = 0 gives critical damping.
double dampingRatio(double restitution);

// Parameters of the contact between two materials: stiffnesses combine in
// series scaled so that equal materials keep their own value (2 k1 k2/(k1+k2)),
// friction takes the smaller, damping ratios the mean (restitution: the one
// the continuous linear law gives that mean; equal materials keep theirs), the
// normal force is compressive if either material's is.
// Hertz-Mindlin (either material hertz) uses the sphere law that 2D codes
// such as LAMMPS use: Fn = 4/3 E* sqrt(R* d) d, tangential stiffness
// 8 G* sqrt(R* d), with the effective moduli below.
struct PairLaw {
  double kn, ks, friction, zeta, damping;  // damping < 0: use restitution
  double restitution = 0;                  // the target the damping is solved for
  bool hertz = false, compressive = false;
  double effectiveYoungs = 0, effectiveShear = 0;
};
PairLaw combine(const Material& a, const Material& b);

class MaterialTable {
 public:
  MaterialTable();                           // holds "default"
  int find(const std::string& name) const;   // -1 if none
  int index(const std::string& name) const;  // throws if none
  const Material& operator[](int i) const { return materials_[i]; }
  int add(const Material& m);              // throws if the name is taken or invalid
  void replace(int i, const Material& m);  // validated
  std::vector<std::string> names() const;
  int size() const { return int(materials_.size()); }
  // Changes with every add or replace: what depends on the materials knows to
  // look again.
  std::uint64_t version() const { return version_; }

 private:
  std::vector<Material> materials_;
  std::uint64_t version_ = 0;
};

}  // namespace sf::dem
