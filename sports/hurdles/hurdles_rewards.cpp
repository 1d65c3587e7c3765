#include "hurdles/hurdles_rewards.h"

#include <algorithm>

namespace olympics::sports::hurdles {

std::vector<RewardTerm> hurdles_rewards() {
  return {{"distance", 1.0,
           "r_distance: the root's progress toward the finish (1 m up on my lane's centre) this "
           "tick, clamped to [0, 1]"}};
}

std::array<float, 1> hurdles_reward_terms(const Eigen::Vector3d& root_prev,
                                          const Eigen::Vector3d& root,
                                          const Eigen::Vector3d& goal) {
  const double progress = (root_prev - goal).norm() - (root - goal).norm();
  return {static_cast<float>(std::clamp(progress, 0.0, 1.0))};
}

}  // namespace olympics::sports::hurdles
