#include "golf/golf_rewards.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::golf {

std::vector<RewardTerm> golf_rewards() {
  return {
      {"contact", 1.0, "r_c: exp(-100 |ball - club head|^2) before the club's contact, 1 after"},
      {"position", 1.0,
       "r_p: the ball's approach to the target this tick, clamped to [0, 1], after contact"},
      {"goal", 1.0, "r_g: exp(-0.1 |ball_xy - target_xy|) after contact"},
      {"landing", 1.0, "r_land: exp(-0.1 |predicted landing - target_xy|) after contact (eq. 6)"}};
}

Eigen::Vector2d seed_landing_point(const Eigen::Vector3d& p, const Eigen::Vector3d& v) {
  constexpr double g = 9.8;  // the code's
  const double disc = 4 * v.z() * v.z() + 8 * g * p.z();
  const double t = (2 * v.z() + std::sqrt(std::max(disc, 0.0))) / (2 * g);
  return p.head<2>() + v.head<2>() * t;
}

std::array<float, 4> golf_reward_terms(const GolfRewardState& s) {
  const double club_err = (s.ball - s.head).squaredNorm();
  const float contact = s.contact ? 1.0f : static_cast<float>(std::exp(-100 * club_err));
  if (!s.contact) return {contact, 0.0f, 0.0f, 0.0f};
  const double closer = (s.ball_prev - s.target).norm() - (s.ball - s.target).norm();
  const double to_goal = (s.ball.head<2>() - s.target.head<2>()).norm();
  const double land_err = (seed_landing_point(s.ball, s.ball_velocity) - s.target.head<2>()).norm();
  return {contact, static_cast<float>(std::clamp(closer, 0.0, 1.0)),
          static_cast<float>(std::exp(-0.1 * to_goal)),
          static_cast<float>(std::exp(-0.1 * land_err))};
}

}  // namespace olympics::sports::golf
