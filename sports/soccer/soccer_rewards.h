// The soccer rewards, term by term (SPORTS.md, Soccer; the seed's eq. 11 for the penalty kick).
//
// Penalty kick, with g = |G - ball_{t-1}| - |G - ball_t| (is the ball getting closer to the goal
// target G?): while g <= 0 only player_to_ball counts (weight 0.4), else ball_to_goal (0.1),
// ball_velocity_to_goal (0.1) and ball_to_target (0.8); no_dribble (weight -1) always.
//   player_to_ball         |root_{t-1} - ball_t| - |root_t - ball_t| (m; on the ground plane)
//   ball_to_goal           |G - ball_{t-1}| - |G - ball_t| (m)
//   ball_velocity_to_goal  the ball's velocity along the direction to G (m/s)
//   ball_to_target         exp(-|e - G|^2), e where the ball's flight (gravity, no drag) meets
//                          the goal plane; 0 when it does not fly towards it
//   no_dribble             1 - exp(-0.2 d^2), d how far the root has passed the ball's spawn
//                          point towards the goal (0 before it)
// Team play (1v1, 2v2), towards the opponents' goal: player_to_ball (0.4), ball_to_goal (0.1),
// ball_velocity_to_goal (0.1), every tick; goal (weight 10): +1 the tick my side scores, -1 the
// tick it concedes. A goalkeeper (mode penalty_kick_keeper) has the penalty kick's terms, of
// which it gets player_to_ball (always) and goal (-1 when the kick goes in). Both: fallen (weight
// 0), 1 while the player is down (falls are not penalised by default; a trainer may weight them).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sport.h"

namespace olympics::sports::soccer {

std::vector<RewardTerm> penalty_kick_rewards();
std::vector<RewardTerm> team_play_rewards();

// One player's tick, as the rewards need it.
struct RewardState {
  Eigen::Vector3d root_before, root;  // the player's root before and after the tick
  Eigen::Vector3d ball_before, ball, ball_velocity;
  Eigen::Vector3d target;  // G: the centre of the goal it attacks
  int attack = 1;          // the direction (+1: +x) of that goal
  bool fallen = false;
};

// The shared terms.
double player_to_ball(const RewardState& s);
double ball_to_goal(const RewardState& s);
double ball_velocity_to_goal(const RewardState& s);
// Where the ball's flight meets the plane x = target.x, or nullopt-like false when it does not
// move towards it.
bool entry_point(const RewardState& s, Eigen::Vector3d& entry);
double ball_to_target(const RewardState& s);
double no_dribble(const RewardState& s, const Eigen::Vector3d& spawn);

// Eq. 11's stage switch "is the ball nearing the goal" (g > 0) has a dead band: g must exceed
// this (m/tick, 3 mm/s) so that a ball lying still, whose position jitters by sub-micrometres
// from tick to tick, does not flip the stage (it zeroed the player-to-ball term on 97 of 10,569
// still ticks).
inline constexpr double kBallNearingGoal = 1e-4;

// Terms in the order of penalty_kick_rewards() / team_play_rewards().
// `goal`: the ball went in this tick.
std::array<float, 7> penalty_kick_terms(const RewardState& s, const Eigen::Vector3d& spawn,
                                        bool goal);
std::array<float, 7> goalkeeper_terms(const RewardState& s, bool goal);
// `goal`: +1 my side scored this tick, -1 it conceded, else 0.
std::array<float, 5> team_play_terms(const RewardState& s, int goal);

}  // namespace olympics::sports::soccer
