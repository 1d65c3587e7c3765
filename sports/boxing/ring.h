// The boxing ring (SPORTS.md: 5 x 5 m, the seed's; AIBA's 6.10 m inside the ropes, professional
// rings 4.88-7.32 m),
// centred on the origin: four ropes a side at 0.4, 0.7, 1.0 and 1.3 m (AIBA's heights) and a
// post at each corner, as real (rigid) collision geometry. Boxer 0 starts at x = -start facing
// +x, boxer 1 at x = +start facing -x (combat/start_placement.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/humanoid.h"
#include "core/physics_world.h"
#include "framework/scene_view.h"

namespace olympics::sports::boxing {

struct Ring {
  double size = 5;     // m, inside the ropes
  double start = 1.0;  // each boxer's start, m from the centre

  double half() const { return size / 2; }
  // A rope or a post: a capsule from a to b.
  struct Bar {
    Eigen::Vector3d a, b;
    double radius, restitution;
    bool post;
  };
  std::vector<Bar> bars() const;
  // Ropes and posts into `world`.
  void build(core::PhysicsWorld& world) const;
  // The canvas, ropes and posts, for viewers.
  void describe(SceneBuilder& scene) const;

  static constexpr double kRopeHeights[4] = {0.4, 0.7, 1.0, 1.3};
  static constexpr double kRopeRadius = 0.02;
  static constexpr double kPostRadius = 0.08;
};

}  // namespace olympics::sports::boxing
