#include "long_jump/long_jump_rewards.h"

#include <algorithm>

namespace olympics::sports::long_jump {

std::vector<RewardTerm> long_jump_rewards() {
  return {
      {"position", 1.0, "r_p: the root's progress toward the goal this tick, clamped to [0, 1]"},
      {"velocity", 0.01, "r_v: the root's x velocity (m/s)"},
      {"height", 0.1, "r_h: the root's height (m), once a foot is past the line; else 0"},
      {"length", 30.0, "r_l: the mark (m past the line) on the landing tick; else 0"}};
}

std::array<float, 4> long_jump_reward_terms(const LongJumpRewardState& s) {
  const double progress = (s.root_prev - s.goal).norm() - (s.root - s.goal).norm();
  return {static_cast<float>(std::clamp(progress, 0.0, 1.0)), static_cast<float>(s.root_vx),
          s.past_line ? static_cast<float>(s.root.z()) : 0.0f,
          s.landed_this_tick ? static_cast<float>(s.mark) : 0.0f};
}

}  // namespace olympics::sports::long_jump
