// The free-throw rewards, term by term (SPORTS.md, Basketball; the seed's eq. 12):
//   ball_velocity        exp(-0.1 |v_ball - v_desired|^2), v_desired the launch velocity whose
//                        ballistic path (gravity, no drag) reaches the target T at its apex:
//                        t = sqrt(2 dz / g) with dz = T_z - ball_z, horizontal speed = the
//                        horizontal distance / t towards T, vertical speed = (dz + g t^2 / 2) / t
//                        (weight 0.5)
//   ball_velocity_to_target  the ball's velocity along the direction to T, m/s (weight 0.5)
//   basket               1 on the tick the ball goes through the rim (weight 1)
// T is kTargetAboveRim above the rim's centre: the seed says "the target above the rim" without
// a height. A ball at or above T's height is given dz = kMinRise (a lob from there).
//
// Team play (1v1, 2v2), as soccer's: player_to_ball (0.4), m/tick the root came closer to the
// ball; ball_to_basket (0.1) and ball_velocity_to_basket (0.1), the ball's progress and speed
// towards T, counted for the side in possession and against the other (both sides attack the one
// basket: the defence wants the ball away from it); points (weight 10): the points my side
// scored this tick, minus those it conceded; fallen (weight 0), 1 while the player is down.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::basketball {

inline constexpr double kTargetAboveRim = 0.3;  // m
inline constexpr double kMinRise = 0.05;        // m
inline constexpr double kGravity = 9.81;

std::vector<RewardTerm> free_throw_rewards();

Eigen::Vector3d desired_launch_velocity(const Eigen::Vector3d& ball, const Eigen::Vector3d& target);
// Terms in the order of free_throw_rewards().
std::array<float, 3> free_throw_terms(const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity,
                                      const Eigen::Vector3d& target, bool basket);

std::vector<RewardTerm> team_play_rewards();

// One player's tick, as the team-play rewards need it.
struct TeamPlayState {
  Eigen::Vector3d root_before, root;  // the player's root before and after the tick
  Eigen::Vector3d ball_before, ball, ball_velocity;
  Eigen::Vector3d target;  // T above the rim
  int possession = 0;      // +1 my side has the ball, -1 the other side, 0 nobody yet
  int points = 0;          // my side's points this tick minus the other side's
  bool fallen = false;
};

// Terms in the order of team_play_rewards().
std::array<float, 5> team_play_terms(const TeamPlayState& s);

}  // namespace olympics::sports::basketball
