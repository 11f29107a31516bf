// A lattice's state in a checkpoint (Lattice::saveState / loadState).
#include <cstring>

#include "sandflow/geometry/vec2_bytes.hpp"
#include "sandflow/lb/lattice.hpp"

namespace sf::lb {
namespace {

void putDef(ByteWriter& out, const LatticeDef& d) {
  putVec2(out, d.origin), putVec2(out, d.size);
  out.put(std::int32_t(d.cells)), out.put(d.spacing);
  out.put(d.viscosity), out.put(d.tau), out.put(d.timestep);  // optional<double>: bytes
  out.put(d.density), putVec2(out, d.forcing);
  out.put(std::int32_t(d.collision)), out.put(std::int32_t(d.forceScheme)), out.put(d.magic);
  for (const SideDef& side : d.sides) {
    out.put(std::int32_t(side.kind)), putVec2(out, side.velocity), out.put(side.pressure);
  }
  // Version 5: velocity sides' profile, ramp and expressions (text and values).
  for (const SideDef& side : d.sides) {
    out.put(std::int32_t(side.profile)), out.put(side.ramp);
    out.put(side.expr[0]), out.put(side.expr[1]), out.put(side.timed);
    out.put(std::uint64_t(side.values.size()));
    for (const Vec2& v : side.values) putVec2(out, v);
  }
}

template <class Enum>
Enum getEnum(ByteReader& in, int count, const char* what) {
  const auto v = in.get<std::int32_t>(what);
  if (v < 0 || v >= count) ByteReader::fail(std::string("it holds an unknown ") + what);
  return Enum(v);
}

LatticeDef getDef(ByteReader& in) {
  LatticeDef d;
  d.origin = getVec2(in, "lattice origin"), d.size = getVec2(in, "lattice size");
  d.cells = in.get<std::int32_t>("lattice cells"), d.spacing = in.get<double>("lattice spacing");
  in.get(d.viscosity, "viscosity"), in.get(d.tau, "tau"), in.get(d.timestep, "timestep");
  d.density = in.get<double>("density"), d.forcing = getVec2(in, "forcing");
  d.collision = getEnum<Collision>(in, 2, "collision");
  d.forceScheme = getEnum<ForceScheme>(in, 2, "forcing scheme");
  d.magic = in.get<double>("TRT magic");
  // An outflow side arrived with version 5.
  const int kinds = in.version < 5 ? int(SideKind::outflow) : int(sideKindNames.size());
  for (SideDef& side : d.sides) {
    side.kind = getEnum<SideKind>(in, kinds, "side kind");
    side.velocity = getVec2(in, "side velocity"), side.pressure = in.get<double>("side pressure");
  }
  if (in.version < 5) return d;
  for (SideDef& side : d.sides) {
    side.profile = getEnum<SideProfile>(in, int(sideProfileNames.size()), "side profile");
    side.ramp = in.get<double>("side ramp");
    in.get(side.expr[0], "side expression"), in.get(side.expr[1], "side expression");
    side.timed = in.getBool("side expression");
    const std::size_t n = in.count(2 * sizeof(double), "side values");
    side.values.resize(n);
    for (Vec2& v : side.values) v = getVec2(in, "side values");
  }
  return d;
}

}  // namespace

void Lattice::saveState(ByteWriter& out) const {
  out.tag("LATT");
  putDef(out, p_.def);
  out.put(std::int32_t(p_.nx)), out.put(std::int32_t(p_.ny));
  out.put(p_.h), out.put(p_.dt), out.put(p_.tau), out.put(p_.viscosity);
  out.put(std::uint64_t(obstacles_.size()));
  for (const RectObstacle& r : obstacles_)
    out.put(std::int32_t(r.id)), putVec2(out, r.lo), putVec2(out, r.hi), out.put(r.slip);
  out.put(std::uint64_t(circles_.size()));
  for (const CircleObstacle& c : circles_) {
    out.put(std::int32_t(c.id)), putVec2(out, c.centre), out.put(c.radius), out.put(c.outside);
    putVec2(out, c.velocity), out.put(c.spin);
    putVec2(out, c.force), out.put(c.torque), out.put(std::uint64_t(c.cells));
  }
  // The post-collision populations of the nodes that hold fluid, in the
  // layout of the two-array step that wrote versions 1 to 3 (f*_d in slot d at
  // its node), 0 in every other slot: the same bytes whichever layout the
  // array is in, and all a step needs (the walls' slots follow by the links).
  const std::size_t count = populationSlots();
  std::vector<double> post(count, 0.0);
  const Slots s = slots();
  for (int j = 0; j < p_.ny; ++j)
    for (int i = 0; i < p_.nx; ++i) {
      const std::int64_t x = index(i, j);
      if (holdsFluid(x))
        for (int d = 0; d < 9; ++d) post[d * stride_ + x] = f_[s.post(layout_, d, x)];
    }
  out.put(std::uint64_t(count));
  out.putRaw(post.data(), count * sizeof(double));
  // The cells as their struct's bytes (the format), with the padding after
  // `interior` zeroed: it is never written, and would make equal scenes'
  // checkpoints and hashes differ.
  std::vector<CoveredCell> cells(covered_.cells.size());
  if (!cells.empty())  // data() may be null
    std::memset(static_cast<void*>(cells.data()), 0, cells.size() * sizeof(CoveredCell));
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const CoveredCell& c = covered_.cells[k];
    cells[k].node = c.node, cells[k].interior = c.interior, cells[k].eps = c.eps;
    cells[k].ux = c.ux, cells[k].uy = c.uy;
  }
  out.put(cells);
  out.put(covered_.equilibriumInterior);
  out.put(lastMach_);
}

std::unique_ptr<Lattice> Lattice::loadState(ByteReader& in) {
  in.expectTag("LATT");
  const LatticeDef def = getDef(in);
  const ResolvedLattice params = resolve(def);  // the definition's own checks
  const int nx = in.get<std::int32_t>("nx"), ny = in.get<std::int32_t>("ny");
  const double h = in.get<double>("h"), dt = in.get<double>("dt");
  const double tau = in.get<double>("tau"), viscosity = in.get<double>("viscosity");
  // The definition in force resolves to the lattice in force (a -timestep
  // rewrites the definition it applies).
  if (nx != params.nx || ny != params.ny || h != params.h || dt != params.dt || tau != params.tau ||
      viscosity != params.viscosity)
    ByteReader::fail("its lattice does not match its definition");
  auto lattice = std::make_unique<Lattice>(params);
  const std::size_t rects = in.count(1, "obstacles");
  for (std::size_t k = 0; k < rects; ++k) {
    RectObstacle r;
    r.id = in.get<std::int32_t>("obstacle id");
    if (r.id < 0) ByteReader::fail("it holds a negative obstacle id");
    r.lo = getVec2(in, "obstacle"), r.hi = getVec2(in, "obstacle");
    r.slip = in.getBool("obstacle slip");
    lattice->addObstacle(r);
  }
  const std::size_t circles = in.count(1, "circles");
  for (std::size_t k = 0; k < circles; ++k) {
    CircleObstacle c;
    c.id = in.get<std::int32_t>("circle id");
    if (c.id < 0) ByteReader::fail("it holds a negative obstacle id");
    c.centre = getVec2(in, "circle"), c.radius = in.get<double>("circle radius");
    c.outside = in.getBool("circle");
    c.velocity = getVec2(in, "circle velocity"), c.spin = in.get<double>("circle spin");
    const Vec2 force = getVec2(in, "circle load");
    const double torque = in.get<double>("circle load");
    const auto cells = in.get<std::uint64_t>("circle load");
    lattice->addCircle(c);
    lattice->setCircleLoad(k, force, torque, std::size_t(cells));
  }
  const auto count = in.get<std::uint64_t>("populations");
  if (count != lattice->populationSlots())
    ByteReader::fail("its populations do not fit its lattice");
  std::vector<double> post(count);
  in.getRaw(post.data(), count * sizeof(double), "populations");
  // Versions 1 to 3 hold the two-array step's second array too, unread.
  if (in.version < 4) in.skip(count * sizeof(double), "populations");
  const Slots s = lattice->slots();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::int64_t x = lattice->index(i, j);
      if (lattice->holdsFluid(x))
        for (int d = 0; d < 9; ++d)
          lattice->f_[s.post(Layout::collided, d, x)] = post[d * lattice->stride_ + x];
    }
  lattice->layout_ = Layout::collided;
  lattice->fill();
  std::vector<CoveredCell> cells;
  in.get(cells, "covered cells");
  const bool equilibriumInterior = in.getBool("covered cells");
  for (const CoveredCell& c : cells) {
    if (*reinterpret_cast<const unsigned char*>(&c.interior) > 1)
      ByteReader::fail("it holds a bad flag in the covered cells");
    const int i = c.node % lattice->rowStride_ - 1, j = c.node / lattice->rowStride_ - 1;
    if (c.node < 0 || i < 0 || i >= nx || j < 0 || j >= ny || !(c.eps > 0 && c.eps <= 1))
      ByteReader::fail("it holds a covered cell off the lattice");
  }
  lattice->setCoveredCells(std::move(cells), equilibriumInterior);
  lattice->lastMach_ = in.get<double>("Mach number");
  lattice->canUndo_ = false;
  return lattice;
}

}  // namespace sf::lb
