#include "collide.hpp"

namespace sf::dem {

bool collideDiscDisc(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Manifold& m) {
  return collideDiscs(pa.x, static_cast<const Disc&>(a).radius(), pb.x,
                      static_cast<const Disc&>(b).radius(), m);
}

}  // namespace sf::dem
