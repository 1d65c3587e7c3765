// Reward pieces of the ball sports' team play (soccer, basketball): is a player getting to the
// ball, is the ball getting to where its side wants it.
#pragma once

#include <Eigen/Core>

namespace olympics::sports {

// m the root came closer to the ball over a tick, on the ground plane.
inline double approach_to_ball(const Eigen::Vector3d& root_before, const Eigen::Vector3d& root,
                               const Eigen::Vector3d& ball) {
  return (root_before - ball).head<2>().norm() - (root - ball).head<2>().norm();
}

// m the ball came closer to `target` over a tick.
inline double ball_progress(const Eigen::Vector3d& target, const Eigen::Vector3d& ball_before,
                            const Eigen::Vector3d& ball) {
  return (target - ball_before).norm() - (target - ball).norm();
}

// m/s of the ball's velocity along the direction to `target`.
inline double ball_speed_towards(const Eigen::Vector3d& target, const Eigen::Vector3d& ball,
                                 const Eigen::Vector3d& velocity) {
  const Eigen::Vector3d to = target - ball;
  const double d = to.norm();
  return d > 1e-9 ? velocity.dot(to / d) : 0.0;
}

}  // namespace olympics::sports
