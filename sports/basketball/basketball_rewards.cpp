#include "basketball/basketball_rewards.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::basketball {

std::vector<RewardTerm> free_throw_rewards() {
  return {{"ball_velocity", 0.5,
           "exp(-0.1 |v_ball - v_desired|^2): v_desired reaches the target above the rim at its "
           "apex (eq. 12)"},
          {"ball_velocity_to_target", 0.5, "the ball's velocity towards the target, m/s"},
          {"basket", 1.0, "1 on the tick the ball goes down through the rim"}};
}

Eigen::Vector3d desired_launch_velocity(const Eigen::Vector3d& ball,
                                        const Eigen::Vector3d& target) {
  const double dz = std::max(target.z() - ball.z(), kMinRise);
  const double t = std::sqrt(2 * dz / kGravity);
  const Eigen::Vector2d across = (target - ball).head<2>();
  const Eigen::Vector2d horizontal = across / t;
  return {horizontal.x(), horizontal.y(), (dz + 0.5 * kGravity * t * t) / t};
}

std::array<float, 3> free_throw_terms(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity,
                                      const Eigen::Vector3d& target, bool basket) {
  const Eigen::Vector3d miss = velocity - desired_launch_velocity(ball, target);
  const Eigen::Vector3d to_target = target - ball;
  const double towards = to_target.norm() > 1e-9 ? velocity.dot(to_target.normalized()) : 0.0;
  return {static_cast<float>(std::exp(-0.1 * miss.squaredNorm())), static_cast<float>(towards),
          basket ? 1.0f : 0.0f};
}

}  // namespace olympics::sports::basketball
