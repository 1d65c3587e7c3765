#include "combat/combat_rewards.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rotation.h"

namespace olympics::sports::combat {

std::array<float, kCombatTerms> combat_reward_terms(const CombatRewardInput& in) {
  std::array<float, kCombatTerms> t{};
  Eigen::Vector3d to_opponent = in.opponent_root - in.root.position;
  to_opponent.z() = 0;
  if (to_opponent.norm() > 1e-9) {
    const Eigen::Vector3d d = to_opponent.normalized();
    const Eigen::Vector3d local = core::inverse_heading(in.root.orientation) * d;
    t[kFacing] = static_cast<float>(std::exp(-2.0 * (1.0 - local.x())));
    const double speed = in.root.linear_velocity.head<2>().dot(d.head<2>());
    if (speed > 0) {
      const double shortfall = std::max(0.0, 1.0 - speed);
      t[kVelocity] = static_cast<float>(std::exp(-4.0 * shortfall * shortfall));
    }
  } else {
    t[kFacing] = 1.0f;  // on top of each other: every direction faces it
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& s : in.strikers)
    for (const auto& target : in.targets) nearest = std::min(nearest, (s - target).squaredNorm());
  if (std::isfinite(nearest)) t[kStrike] = static_cast<float>(std::exp(-10.0 * nearest));
  t[kPoint] = in.scored ? 1.0f : 0.0f;
  return t;
}

std::vector<RewardTerm> combat_rewards(const std::string& striker) {
  return {{"facing", 0.1, "exp(-2 (1 - d_x)): facing the opponent's root (heading frame)"},
          {"velocity", 0.1,
           "exp(-4 max(0, 1 - s)^2) for root speed s > 0 towards the opponent, else 0"},
          {"strike", 0.6, "exp(-10 min |p - p_target|^2), p " + striker + ", over the targets"},
          {"point", 1.0, "1 on the tick this player scores"}};
}

}  // namespace olympics::sports::combat
