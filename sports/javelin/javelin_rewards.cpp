#include "javelin/javelin_rewards.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::javelin {

std::vector<RewardTerm> javelin_rewards() {
  return {
      {"grasp", 0.09, "hold stage: exp(-|cord - right palm|) (0.1 x 0.9); else 0"},
      {"javelin_state", 0.01,
       "hold stage: 0.7 exp(-|cord - its start|) + 0.2 exp(-angle to the default attitude) + "
       "0.05 exp(-|v|) + 0.05 exp(-|w|) of the javelin (0.1 x 0.1); else 0"},
      {"closer", 0.9,
       "throw and flight stages: clamp(the javelin's progress toward x = 50 m this tick / 5, 0, "
       "1); else 0"},
      {"root_stay", 0.05, "throw stage: exp(-mean of the root's squared xy offset from its start)"},
      {"release", 0.05, "throw stage: clamp(|cord - right palm|, 0, 1)"},
      {"heading", 0.1,
       "flight stage: exp(-10 e^2), e the horizontal angle between the javelin and the "
       "direction to the target"}};
}

std::array<float, kJavelinTerms> javelin_reward_terms(const JavelinRewardState& s) {
  std::array<float, kJavelinTerms> t{};
  const double hand = (s.cord - s.hand).norm();
  if (s.stage == Stage::Hold) {
    t[0] = static_cast<float>(std::exp(-hand));
    t[1] = static_cast<float>(
        0.7 * std::exp(-(s.cord - s.cord_start).norm()) + 0.2 * std::exp(-s.attitude_error) +
        0.05 * std::exp(-s.velocity.norm()) + 0.05 * std::exp(-s.spin.norm()));
    return t;
  }
  const double closer = (std::abs(s.target_x - s.x_prev) - std::abs(s.target_x - s.x)) / 5.0;
  t[2] = static_cast<float>(std::clamp(closer, 0.0, 1.0));
  if (s.stage == Stage::Throw) {
    t[3] = static_cast<float>(std::exp(-0.5 * s.root_offset.squaredNorm()));
    t[4] = static_cast<float>(std::clamp(hand, 0.0, 1.0));
  } else {
    t[5] = static_cast<float>(std::exp(-10.0 * s.heading_err * s.heading_err));
  }
  return t;
}

}  // namespace olympics::sports::javelin
