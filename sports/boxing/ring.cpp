#include "boxing/ring.h"

#include <cmath>

namespace olympics::sports::boxing {

void Ring::build(core::PhysicsWorld& world) const {
  // Ropes just outside the ring's edge; padded, so little bounce and some grip.
  const double h = half() + kRopeRadius;
  const Eigen::Vector2d corners[4] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int side = 0; side < 4; ++side) {
    const Eigen::Vector2d a = corners[side], b = corners[(side + 1) % 4];
    for (double z : kRopeHeights)
      world.add_static_capsule({a.x(), a.y(), z}, {b.x(), b.y(), z}, kRopeRadius, 0.6, 0.3);
  }
  const double top = kRopeHeights[3] + 0.1;
  const double post = h + kPostRadius;
  for (const auto& c : corners) {
    const Eigen::Vector2d at = c.normalized() * post * std::sqrt(2.0);
    world.add_static_capsule({at.x(), at.y(), 0}, {at.x(), at.y(), top}, kPostRadius, 0.6, 0.1);
  }
}

}  // namespace olympics::sports::boxing
