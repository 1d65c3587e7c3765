#include "high_jump/high_jump_rewards.h"

#include <algorithm>
#include <cmath>

namespace olympics::sports::high_jump {

std::vector<RewardTerm> high_jump_rewards() {
  return {
      {"position", 1.0, "r_p: the root's progress toward the goal this tick, clamped to [0, 1]"},
      {"height", 1.0, "r_h: the root's height (m) within 0.5 m of the bar's plane; else 0"}};
}

std::array<float, 2> high_jump_reward_terms(const Eigen::Vector3d& root_prev,
                                            const Eigen::Vector3d& root,
                                            const Eigen::Vector3d& goal, double bar_x) {
  const double progress = (root_prev - goal).norm() - (root - goal).norm();
  const bool at_bar = std::abs(root.x() - bar_x) <= 0.5;
  return {static_cast<float>(std::clamp(progress, 0.0, 1.0)),
          at_bar ? static_cast<float>(root.z()) : 0.0f};
}

}  // namespace olympics::sports::high_jump
