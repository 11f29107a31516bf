#pragma once
// The assembly's bonds (bond.hpp): making them between elements, their forces
// in a step, and their breaks, which a step commits only once it cannot fail.
#include <string>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/bond.hpp"
#include "sandflow/dem/material.hpp"

namespace sf::dem {

class BondSet {
 public:
  const std::vector<Bond>& all() const { return bonds_; }
  const std::vector<BondBreak>& breaks() const { return breaks_; }
  bool empty() const { return bonds_.empty(); }
  const Bond& info(int bondId) const;  // throws if none

  // A bond between the elements at slots a and b, at their closest surface
  // points (stiffness/strength < 0: from the elements' materials).
  int make(const Bodies& b, const MaterialTable& materials, int slotA, int slotB, double stiffness,
           double strength, double shearStrength);
  // Bonds every pair among `slots` whose surfaces are closer than `gap`;
  // returns how many were made.
  int makeAll(const Bodies& b, const MaterialTable& materials, const std::vector<int>& slots,
              double gap);
  void remove(int bondId);
  void forget(int elementId);  // the element was deleted: its bonds go

  // A step: forces onto the elements (v, w: the velocities the dashpots see),
  // the bonds that hold and the breaks kept aside until commit().
  void beginStep() { pending_ = false; }
  void addForces(Bodies& b, double time, double dt, const std::vector<Vec2>& v,
                 const std::vector<double>& w);
  void commit();

  // Checkpoints ("BOND"); `load` fills an empty set.
  void save(ByteWriter& out) const;
  void load(ByteReader& in, const Bodies& b);
  // Ids once and below the next, live elements, one bond a pair, finite
  // values: what is wrong, in words.
  std::vector<std::string> validate(const Bodies& b) const;

 private:
  std::vector<Bond> bonds_;
  std::vector<BondBreak> breaks_;
  // A step's bonds and breaks, until the step is sure to succeed.
  std::vector<Bond> pendingBonds_;
  std::vector<BondBreak> pendingBreaks_;
  bool pending_ = false;
  int nextId_ = 0;
};

}  // namespace sf::dem
