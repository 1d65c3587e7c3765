#include "basketball/basketball_rewards.h"

#include <algorithm>
#include <cmath>

#include "framework/ball_progress.h"

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
  return {static_cast<float>(std::exp(-0.1 * miss.squaredNorm())),
          static_cast<float>(ball_speed_towards(target, ball, velocity)), basket ? 1.0f : 0.0f};
}

std::vector<RewardTerm> team_play_rewards() {
  return {{"player_to_ball", 0.4, "m/tick the root came closer to the ball"},
          {"ball_to_basket", 0.1,
           "m/tick the ball came closer to the target above the rim (negative for the side "
           "without the ball)"},
          {"ball_velocity_to_basket", 0.1,
           "m/s of the ball towards the target (negative for the side without the ball)"},
          {"points", 10.0, "the points my side scored this tick minus those it conceded"},
          {"fallen", 0.0, "1 while the player is down (falls are not penalised by default)"}};
}

std::array<float, 5> team_play_terms(const TeamPlayState& s) {
  const double side = s.possession;
  return {static_cast<float>(approach_to_ball(s.root_before, s.root, s.ball)),
          static_cast<float>(side * ball_progress(s.target, s.ball_before, s.ball)),
          static_cast<float>(side * ball_speed_towards(s.target, s.ball, s.ball_velocity)),
          static_cast<float>(s.points), s.fallen ? 1.0f : 0.0f};
}

}  // namespace olympics::sports::basketball
