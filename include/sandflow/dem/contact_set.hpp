#pragma once
// The assembly's contacts: the broad phase (DESS over boxes grown by a skin,
// rebuilt once something has moved half the skin), the contact list with its
// history, the pair-law table and the contacts' cached law parts, and the
// contact pass and its sums onto the elements. The elements themselves are
// the assembly's (Bodies); every call that needs them is given them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/contact_damping.hpp"
#include "sandflow/dem/contact_list.hpp"
#include "sandflow/dem/contacts_by_element.hpp"
#include "sandflow/dem/dess.hpp"
#include "sandflow/dem/material.hpp"

namespace sf::dem {

// A candidate pair from the broad phase and, while it touches, its contact: a
// copy made from the contact list (contact_list.hpp) for those who look.
struct Contact {
  int a, b;                   // slots, a < b
  int idA, idB;               // element ids (stable across deletions)
  Vec2 shear = Vec2::Zero();  // tangential spring force on b (history)
  bool touching = false;
  bool discs = false;
  double dampingPart = 0;  // the normal damping's cached part (see ContactList)
  Vec2 normal = Vec2::Zero(), point = Vec2::Zero();
  double overlap = 0.0;
  Vec2 force = Vec2::Zero();  // total contact force on b (on a: the opposite)
};

class ContactSet {
 public:
  const ContactList& list() const { return list_; }
  const std::vector<Contact>& view() const;  // made on demand
  std::size_t touchingCount() const;
  Vec2 forceOn(int slot) const;  // the sum of the contact forces on one element
  long long builds() const { return builds_; }

  // The elements changed by hand: the next step builds the pairs again.
  void invalidate() { dess_.reset(), pairsValid_ = false; }
  // Element `id` was deleted (its slot swap-removed): its contacts end here,
  // and the next build finds the others by id.
  void forget(int id);

  // The step's stages. `generation` changes with every change to masses,
  // holds or the element set (Assembly); the laws and caches follow it.
  // Candidate pairs, built again when something moved by half the skin.
  void update(const Bodies& b, const MaterialTable& materials, std::uint64_t generation,
              bool vectorPass);
  // Each contact's damping and normal-force mode for the step dt, done again
  // only after a pair build or a change of step (law_columns.cpp).
  void prepareDamping(const Bodies& b, const MaterialTable& materials, std::uint64_t generation,
                      double dt);
  // The next history and the results of every contact, on up to `threads`;
  // returns the first contact that stops the step, or the list's size.
  std::size_t evaluate(const Bodies& b, const std::vector<Vec2>& v, const std::vector<double>& w,
                       double dt, double maxOverlap, int threads);
  // Adds the evaluated forces and torques to the elements', in list order,
  // and marks the elements in contact in `touching` (one per slot): one
  // serial pass down the list, the reference for the step's gather.
  void sumOnto(Bodies& b, char* touching) const;
  // Each of n slots' contacts in list order (for the gather), indexed afresh
  // after each pair build or load.
  const ContactsByElement& byElement(int n);
  // The step succeeded: its history stands.
  void commit() { list_.current = 1 - list_.current, viewValid_ = false; }

  // Checkpoints: the list with its history and the broad phase's reference
  // poses ("CONT"). `load` checks the list against the elements and fills
  // the contacts' caches.
  void save(ByteWriter& out, const MaterialTable& materials, std::uint64_t generation) const;
  void load(ByteReader& in, const Bodies& b, const MaterialTable& materials,
            std::uint64_t generation);
  // Pairs of live slots named by their ids, each once and in order, columns
  // of one length, finite unit normals: what is wrong, in words.
  std::vector<std::string> validate(const Bodies& b) const;
  // Tests break the list on purpose to see validate() catch it.
  ContactList& listForTesting() { return ++listVersion_, list_; }

 private:
  // Fills contact k's cached law, damping part, size and radius.
  void prepareContact(const Bodies& b, ContactList& l, std::size_t k) const;
  double dampingPart(const Bodies& b, const ContactList& l, std::size_t k) const;
  // Whether the pair-law table or the contacts' caches are out of date.
  bool lawsStale(const MaterialTable& materials, std::uint64_t generation) const;
  void buildLaws(const MaterialTable& materials);

  Dess dess_;
  ContactList list_;
  struct PairBuild {  // update's buffers, kept from build to build
    struct Kept {
      int a, b;
      bool discs;
      bool swapped;        // that pair had a and b the other way round
      std::ptrdiff_t old;  // the same pair in the old list, if it touched (else -1)
    };
    std::vector<Box> boxes;
    std::vector<std::pair<int, int>> pairs;
    std::vector<Kept> kept[2];  // linear disc pairs, the others
    ContactList spare;          // the list before last, reused for the next one
  } build_;
  ContactsByElement byElement_;
  long long listVersion_ = 0, byElementVersion_ = -1;  // list_ replaced; byElement_ made for
  mutable std::vector<Contact> view_;                  // view(), made from list_
  mutable bool viewValid_ = false;
  std::vector<Vec2> builtAt_;
  std::vector<double> builtAngle_;
  bool pairsValid_ = false;
  bool slotsMoved_ = false;  // a deletion renumbered slots since the last pair build
  double skin_ = 0.0;
  long long builds_ = 0;
  std::vector<PairLaw> laws_;  // material pairs, i * lawMaterials_ + j
  int lawMaterials_ = 0;
  std::vector<double> lawKn_, lawKs_, lawFriction_;  // the same in columns
  // The damping solved for each restitution and step (contact_damping.hpp),
  // and the step, pair build, masses and materials the contacts' damping
  // parts hold for (dampingDt_ 0: none yet).
  mutable DampingRatios dampingRatios_;
  double dampingDt_ = 0;
  long long dampingBuild_ = -1;
  std::uint64_t dampingGeneration_ = 0, dampingMaterials_ = 0;
  // The contacts' caches (prepareContact) hold for these.
  std::uint64_t lawsAt_ = 0, lawsMaterials_ = 0;
};

}  // namespace sf::dem
