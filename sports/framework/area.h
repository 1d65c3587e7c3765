// A rule piece: a rectangle on the ground (a piste, a ring, a field), and whether a player has
// left it. Sports decide what leaving means (a halt, a throw-in, ...).
#pragma once

#include <Eigen/Core>
#include <span>

#include "core/humanoid.h"

namespace olympics::sports {

struct GroundRect {
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();

  static GroundRect centred(double length_x, double width_y) {
    return {{-length_x / 2, -width_y / 2}, {length_x / 2, width_y / 2}};
  }
  bool contains(const Eigen::Vector3d& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  }
};

// Is the origin of any of `bodies` (e.g. the ankles) outside the area?
inline bool any_body_outside(const core::Humanoid& h, const GroundRect& area,
                             std::span<const int> bodies) {
  for (int b : bodies)
    if (!area.contains(h.body_state(b).position)) return true;
  return false;
}

}  // namespace olympics::sports
