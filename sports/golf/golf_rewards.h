// The seed's golf reward (eqs. 4-6), term by term as SMPLOlympics' code has it
// (compute_ball_reward in humanoid_golf.py):
//   R = r_c + r_p + r_g + r_land
// r_c = exp(-100 |p_ball - p_head|^2) until the club has made contact, 1 after;
// r_p = clamp(|p_ball,prev - T| - |p_ball - T|, 0, 1) after contact (T: the target, z = 0);
// r_g = exp(-0.1 |p_ball,xy - T_xy|) after contact (the code's norm is not squared);
// r_land = exp(-0.1 |p_land - T_xy|) after contact, p_land = p_ball,xy + v_xy t with
//   t = (2 v_z + sqrt(4 v_z^2 + 8 g z)) / (2 g), g = 9.8, the root taken as 0 when imaginary
//   (the code's predict_land_point: the ball's centre down to z = 0).
// Before contact r_p, r_g and r_land are 0. Official rules use the same terms with the hole as
// the target and contact meaning the current stroke's club contact.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::golf {

std::vector<RewardTerm> golf_rewards();

struct GolfRewardState {
  Eigen::Vector3d ball_prev, ball, ball_velocity, head, target;
  bool contact = false;
};

// The seed's landing point (p_land above).
Eigen::Vector2d seed_landing_point(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity);

// The terms in golf_rewards() order: contact, position, goal, landing.
std::array<float, 4> golf_reward_terms(const GolfRewardState& s);

}  // namespace olympics::sports::golf
