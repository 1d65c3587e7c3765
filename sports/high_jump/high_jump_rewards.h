// The seed's high-jump reward (eq. 1), term by term:
//   R = r_p                 while the root's x < 19.5 or > 20.5
//   R = r_p + r_h           within 0.5 m of the bar's plane
// r_p = |p_prev - G| - |p - G| of the root (clamped to [0, 1]), G = (22, 6, 1): 2 m past the
// bar, 1 m up; r_h = the root's height. A term that does not apply is 0.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::high_jump {

std::vector<RewardTerm> high_jump_rewards();

// Root positions in the world; `bar_x` the bar's plane. Terms: position, height.
std::array<float, 2> high_jump_reward_terms(const Eigen::Vector3d& root_prev,
                                            const Eigen::Vector3d& root,
                                            const Eigen::Vector3d& goal, double bar_x);

}  // namespace olympics::sports::high_jump
