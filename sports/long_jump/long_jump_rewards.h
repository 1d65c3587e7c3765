// The seed's long-jump reward (eq. 2), term by term as SMPLOlympics' code has it:
//   before the line: R = r_p + 0.01 r_v
//   past it:         R = r_p + 0.01 r_v + 0.1 r_h + 30 r_l
// r_p = |p_prev - G| - |p - G| of the root (clamped to [0, 1]), G the goal 1 m up at x = 30;
// r_v = the root's x velocity; r_h = the root's height; r_l = the landing's mark (mean x of the
// bodies - 20) on the landing tick only. A term that does not apply is 0; the weights are the
// layout's.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::long_jump {

std::vector<RewardTerm> long_jump_rewards();

struct LongJumpRewardState {
  Eigen::Vector3d root_prev, root, goal;
  double root_vx = 0;
  bool past_line = false;
  bool landed_this_tick = false;
  double mark = 0;  // r_l when landed_this_tick
};

// The terms in long_jump_rewards() order: position, velocity, height, length.
std::array<float, 4> long_jump_reward_terms(const LongJumpRewardState& s);

}  // namespace olympics::sports::long_jump
