#include "boxing/ring.h"

#include <cmath>

namespace olympics::sports::boxing {

std::vector<Ring::Bar> Ring::bars() const {
  // Ropes just outside the ring's edge; padded, so little bounce and some grip.
  std::vector<Bar> out;
  const double h = half() + kRopeRadius;
  const Eigen::Vector2d corners[4] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int side = 0; side < 4; ++side) {
    const Eigen::Vector2d a = corners[side], b = corners[(side + 1) % 4];
    for (double z : kRopeHeights)
      out.push_back({{a.x(), a.y(), z}, {b.x(), b.y(), z}, kRopeRadius, 0.3, false});
  }
  const double top = kRopeHeights[3] + 0.1;
  const double post = h + kPostRadius;
  for (const auto& c : corners) {
    const Eigen::Vector2d at = c.normalized() * post * std::sqrt(2.0);
    out.push_back({{at.x(), at.y(), 0}, {at.x(), at.y(), top}, kPostRadius, 0.1, true});
  }
  return out;
}

void Ring::build(core::PhysicsWorld& world) const {
  for (const Bar& bar : bars())
    world.add_static_capsule(bar.a, bar.b, bar.radius, 0.6, bar.restitution);
}

void Ring::describe(SceneBuilder& scene) const {
  scene.set_ground(half() + 3, half() + 3, "#4a4a52");
  scene.add_box(-1, {0, 0, -0.01}, {half() + 0.5, half() + 0.5, 0.012}, "arena", "#d8d0b8");
  for (const Bar& bar : bars())
    scene.add_segment(-1, "capsule", bar.a, bar.b, bar.radius, "arena",
                      bar.post ? "#303030" : "#c0392b");
}

}  // namespace olympics::sports::boxing
