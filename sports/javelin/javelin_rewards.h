// The seed's javelin reward (eq. 7), term by term as SMPLOlympics' task code has it (the scan of
// eq. 7 is unreadable; SPORTS.md decodes the code). Three stages by control ticks since the
// attempt began (hold < 20, throw < 40, then flight):
//   hold:   0.1 (0.9 exp(-|j - hand|) + 0.1 r_state)
//   throw:  0.9 r_closer + 0.05 exp(-mean(root_xy^2)) + 0.05 clamp(|j - hand|, 0, 1)
//   flight: 0.9 r_closer + 0.1 exp(-10 heading_err^2)
// j = the javelin's cord, hand = the right palm (R_Wrist) origin; r_state = 0.7 exp(-|j - j0|)
// + 0.2 exp(-angle to the default attitude) + 0.05 exp(-|v_j|) + 0.05 exp(-|w_j|) (j0 where
// the cord began); r_closer = clamp((|T - x_prev| - |T - x|) / 5, 0, 1) with x the javelin's
// centre along the runway from the start mark and T = 50 m; root_xy the root's offset from its
// start; heading_err the horizontal angle (rad) between the javelin's axis and the direction
// from it to the target. Each term is sent by name, 0 outside its stage; the weights (the
// products above: 0.1 * 0.9 = 0.09 ...) are the layout's.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "javelin/javelin_referee.h"
#include "sport.h"

namespace olympics::sports::javelin {

std::vector<RewardTerm> javelin_rewards();

struct JavelinRewardState {
  Stage stage = Stage::Hold;
  Eigen::Vector3d cord = Eigen::Vector3d::Zero(), hand = Eigen::Vector3d::Zero();
  Eigen::Vector3d cord_start = Eigen::Vector3d::Zero();
  double attitude_error = 0;  // rad
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(), spin = Eigen::Vector3d::Zero();
  Eigen::Vector2d root_offset = Eigen::Vector2d::Zero();  // root xy minus its start
  double x_prev = 0, x = 0;  // the javelin's centre from the start mark, last tick and now
  double target_x = 50;
  double heading_err = 0;  // rad
};

inline constexpr int kJavelinTerms = 6;
// The terms in javelin_rewards() order: grasp, javelin_state, closer, root_stay, release,
// heading.
std::array<float, kJavelinTerms> javelin_reward_terms(const JavelinRewardState& s);

}  // namespace olympics::sports::javelin
