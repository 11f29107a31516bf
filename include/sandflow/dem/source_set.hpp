#pragma once
// The assembly's sources (physics.md §4): held elements that touch nothing
// and clone themselves whenever nothing overlaps them; each clone is free,
// starts at rest, inherits the applied force and gets the source's body
// acceleration.
#include <functional>
#include <string>
#include <vector>

#include "sandflow/core/byte_stream.hpp"
#include "sandflow/dem/bodies.hpp"
#include "sandflow/dem/element_def.hpp"

namespace sf::dem {

struct Source {
  int id;               // the template element
  Vec2 acceleration;    // given to each clone
  double interval = 0;  // least time between clones
  int limit = -1;       // clones to make (< 0: no limit)
  int made = 0;
  double last = -1e300;  // time of the last clone
  std::vector<int> clones;
};

class SourceSet {
 public:
  const std::vector<Source>& all() const { return sources_; }
  bool empty() const { return sources_.empty(); }

  // Makes the element at `slot` a source: checks, then turns it into a held
  // ghost at rest (the caller updates its mass and the pairs).
  void make(Bodies& b, int slot, const Vec2& acceleration, double interval, int limit);
  // Element `id` is a source no more (throws if it was not one): it touches
  // again.
  void remove(Bodies& b, int id);
  void forget(int id);  // the element was deleted: its source goes
  // Clones every due source that nothing overlaps, through `add`
  // (Assembly::add), in the order the sources were made.
  void spawn(const Bodies& b, double time, const std::function<int(ElementDef)>& add);

  // Checkpoints ("SRCS", less the clock that follows them); `load` fills an
  // empty set.
  void save(ByteWriter& out) const;
  void load(ByteReader& in, const Bodies& b);
  // Each source a ghost element, once, within its limit, and every ghost a
  // source: what is wrong, in words.
  std::vector<std::string> validate(const Bodies& b) const;

 private:
  std::vector<Source> sources_;
};

}  // namespace sf::dem
