// Where the one humanoid of a solo match is on the ground and which way it faces, from the
// match's scene poses (what a viewer draws), for tests that measure how a controller moves it.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "sport.h"

namespace olympics::sports {

struct SoloRoot {
  Eigen::Vector2d position{0, 0};  // m, world frame
  double yaw = 0;                  // rad, the root's forward axis about the vertical
};

inline SoloRoot solo_root(const SportMatch& match) {
  std::vector<float> poses;
  match.scene_poses(poses);  // the root first: position, then quaternion (w, x, y, z)
  const Eigen::Quaterniond q(poses[3], poses[4], poses[5], poses[6]);
  const Eigen::Vector3d forward = q * Eigen::Vector3d::UnitX();
  return {Eigen::Vector2d(poses[0], poses[1]), std::atan2(forward.y(), forward.x())};
}

}  // namespace olympics::sports
