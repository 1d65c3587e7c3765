// The seed's hurdles reward (eq. 3), as SMPLOlympics' code has it (compute_hurdle_reward):
//   R = 1 x r_distance,  r_distance = |p_prev - G| - |p - G| of the root, clamped to [0, 1],
// G = (110, 0, 1): the finish line's point on the lane's centre, 1 m up; p_prev the root a tick
// before. Both rule sets reward alike; the weight is the layout's.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::hurdles {

std::vector<RewardTerm> hurdles_rewards();

// The terms in hurdles_rewards() order: distance.
std::array<float, 1> hurdles_reward_terms(const Eigen::Vector3d& root_prev,
                                          const Eigen::Vector3d& root, const Eigen::Vector3d& goal);

}  // namespace olympics::sports::hurdles
