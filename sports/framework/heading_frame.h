// A humanoid's heading frame: origin at its root, rotated by the root's heading (yaw) only. Task
// observations are written in it, like the self observation (HUMANOID.md section 2).
#pragma once

#include "core/humanoid.h"
#include "core/rotation.h"

namespace olympics::sports {

struct HeadingFrame {
  explicit HeadingFrame(const core::BodyState& root_state)
      : root(root_state), to_heading(core::inverse_heading(root_state.orientation)) {}
  // A world point relative to the root, in the heading frame.
  Eigen::Vector3d point(const Eigen::Vector3d& p) const { return to_heading * (p - root.position); }
  // A world direction or velocity in the heading frame.
  Eigen::Vector3d vector(const Eigen::Vector3d& v) const { return to_heading * v; }

  core::BodyState root;
  Eigen::Quaterniond to_heading;
};

}  // namespace olympics::sports
