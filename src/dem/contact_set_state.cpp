// The contact set in a checkpoint ("CONT") and its invariants.
#include <cmath>
#include <set>

#include "column_bytes.hpp"
#include "sandflow/dem/contact_set.hpp"
#include "sandflow/dem/narrow_phase.hpp"
#include "sandflow/geometry/vec2_bytes.hpp"

namespace sf::dem {

using detail::getColumn;

void ContactSet::save(ByteWriter& out, const MaterialTable& materials,
                      std::uint64_t generation) const {
  out.tag("CONT");
  const ContactList& l = list_;
  const ContactHistory& h = l.now();
  out.put(l.a), out.put(l.b), out.put(l.idA), out.put(l.idB), out.put(l.discs);
  out.put(std::uint64_t(l.vectorCount));
  out.put(h.touching);
  for (const auto* c :
       {&h.nx, &h.ny, &h.sx, &h.sy, &l.fx, &l.fy, &l.px, &l.py, &l.overlap, &l.ta, &l.tb})
    out.put(*c);
  // The broad phase as it stands: the next step rebuilds when this one would.
  out.put(pairsValid_ && !lawsStale(materials, generation)), out.put(slotsMoved_), out.put(skin_);
  putVec2s(out, builtAt_);
  out.put(builtAngle_);
}

void ContactSet::load(ByteReader& in, const Bodies& b, const MaterialTable& materials,
                      std::uint64_t generation) {
  const std::size_t n = std::size_t(b.size());
  in.expectTag("CONT");
  ContactList& l = list_;
  ++listVersion_;
  std::vector<int> a, bb, idA, idB;
  std::vector<std::uint8_t> discs;
  in.get(a, "contacts"), in.get(bb, "contacts"), in.get(idA, "contacts"), in.get(idB, "contacts");
  in.get(discs, "contacts");
  const std::size_t nc = a.size();
  l.resize(nc);
  l.a = std::move(a), l.b = std::move(bb), l.idA = std::move(idA), l.idB = std::move(idB);
  l.discs = std::move(discs);
  l.current = 0;
  l.vectorCount = std::size_t(in.get<std::uint64_t>("contacts"));
  ContactHistory& h = l.history[0];
  getColumn(in, h.touching, nc, "contacts");
  for (auto* c : {&h.nx, &h.ny, &h.sx, &h.sy, &l.fx, &l.fy, &l.px, &l.py, &l.overlap, &l.ta, &l.tb})
    getColumn(in, *c, nc, "contacts");
  if (l.a.size() != nc || l.b.size() != nc || l.idA.size() != nc || l.idB.size() != nc ||
      l.discs.size() != nc || l.vectorCount > nc)
    ByteReader::fail("its contact list is inconsistent");
  pairsValid_ = in.getBool("broad phase");
  slotsMoved_ = in.getBool("broad phase");
  skin_ = in.get<double>("broad phase");
  getVec2s(in, builtAt_, "broad phase");
  in.get(builtAngle_, "broad phase");
  if (pairsValid_ && (builtAt_.size() != n || builtAngle_.size() != n))
    ByteReader::fail("its broad phase does not match its elements");
  // Saved after "element delete" and before the next step, the list holds
  // the slots of the last pair build (builtAt_'s, one per element then) and
  // may name deleted elements; the next step builds it again, carrying the
  // history over by ids (the pair build of the run that never stopped). Only
  // its shape can be checked, and nothing may use it before that build.
  if (slotsMoved_ && pairsValid_) ByteReader::fail("its broad phase does not match its elements");
  buildLaws(materials);
  for (std::size_t k = 0; k < nc; ++k) {
    const int i = l.a[k], j = l.b[k];
    if (h.touching[k] < 0 || h.touching[k] > 1 || l.discs[k] > 1)
      ByteReader::fail("its contact list does not match its elements");
    if (slotsMoved_) {
      if (i < 0 || i >= j || std::size_t(j) >= builtAt_.size() || l.idA[k] < 0 || l.idB[k] < 0 ||
          l.idA[k] == l.idB[k])
        ByteReader::fail("its contact list does not match its elements");
      continue;
    }
    if (i < 0 || i >= j || std::size_t(j) >= n || l.idA[k] != b.id[i] || l.idB[k] != b.id[j])
      ByteReader::fail("its contact list does not match its elements");
    const bool bothDiscs =
        b.shape[i]->type() == ShapeType::disc && b.shape[j]->type() == ShapeType::disc;
    if (l.discs[k] != bothDiscs || !canCollide(b.shape[i]->type(), b.shape[j]->type()))
      ByteReader::fail("its contact list does not match its elements");
    prepareContact(b, l, k);
    if (k < l.vectorCount && (!bothDiscs || laws_[l.law[k]].hertz))
      ByteReader::fail("its contact list does not match its elements");
  }
  lawsAt_ = generation;
  viewValid_ = false;
}

std::vector<std::string> ContactSet::validate(const Bodies& b) const {
  std::vector<std::string> problems;
  auto problem = [&](const std::string& p) { problems.push_back(p); };
  const ContactList& l = list_;
  const std::size_t nc = l.size(), n = std::size_t(b.size());
  bool columns = true;
  for (const auto* c : {&l.b, &l.idA, &l.idB, &l.law}) columns &= c->size() == nc;
  for (const auto* c : {&l.dampingPart, &l.minSize, &l.radius, &l.normalFloor, &l.fx, &l.fy, &l.px,
                        &l.py, &l.overlap, &l.ta, &l.tb})
    columns &= c->size() == nc;
  columns &= l.discs.size() == nc && l.spanned.size() == nc;
  for (const ContactHistory& h : l.history) {
    columns &= h.touching.size() == nc;
    for (const auto* c : {&h.nx, &h.ny, &h.sx, &h.sy}) columns &= c->size() == nc;
  }
  if (!columns) return {"the contact list's columns differ in length"};
  if (l.current != 0 && l.current != 1) return {"the contact list's history is neither copy"};
  if (l.vectorCount > nc) problem("the contact list's disc run is longer than the list");
  if (pairsValid_ && (builtAt_.size() != n || builtAngle_.size() != n))
    problem("the broad phase's reference poses do not match the elements");

  // Pairs of live slots, a < b, named by their ids, each once (never also as
  // b, a), in slot-pair order within each run; the vector run linear discs
  // only. After a deletion the list still holds the old slots until the next
  // step rebuilds it by id (slotsMoved_), so only then do its slots mean
  // anything.
  const ContactHistory& h = l.now();
  std::set<std::pair<int, int>> seen;
  for (std::size_t k = 0; k < (slotsMoved_ ? 0 : nc); ++k) {
    const int i = l.a[k], j = l.b[k];
    const std::string which = "contact " + std::to_string(k);
    if (i < 0 || i >= j || std::size_t(j) >= n) {
      problem(which + " joins slots " + std::to_string(i) + " and " + std::to_string(j));
      continue;
    }
    if (l.idA[k] != b.id[i] || l.idB[k] != b.id[j])
      problem(which + " names elements " + std::to_string(l.idA[k]) + " and " +
              std::to_string(l.idB[k]) + " that are not at its slots");
    if (!seen.insert({i, j}).second) problem(which + " is a second copy of its pair");
    if (k > 0 && k != l.vectorCount && std::pair(l.a[k - 1], l.b[k - 1]) >= std::pair(i, j))
      problem(which + " is out of slot-pair order");
    if (!b.shape[i] || !b.shape[j]) continue;  // Bodies::validate says so
    const bool discs =
        b.shape[i]->type() == ShapeType::disc && b.shape[j]->type() == ShapeType::disc;
    if (k < l.vectorCount && !discs) problem(which + " is in the disc run but is not two discs");
    if (l.discs[k] != discs) problem(which + "'s disc flag does not follow its shapes");
    if (l.law[k] < 0 || std::size_t(l.law[k]) >= laws_.size()) problem(which + " has no pair law");
  }
  for (std::size_t k = 0; k < nc; ++k) {
    const std::string which = "contact " + std::to_string(k);
    const int touching = h.touching[k];
    if (touching != 0 && touching != 1) problem(which + " has a bad touching flag");
    if (touching != 1) continue;
    // The shear spring turns from the last normal: it must be a unit vector.
    const double norm2 = h.nx[k] * h.nx[k] + h.ny[k] * h.ny[k];
    if (!(std::abs(norm2 - 1) <= 1e-6)) problem(which + "'s normal is not a unit vector");
    if (!std::isfinite(h.sx[k]) || !std::isfinite(h.sy[k]))
      problem(which + "'s shear spring is not finite");
  }
  return problems;
}

}  // namespace sf::dem
