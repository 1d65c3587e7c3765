#include "soccer/soccer_rewards.h"

#include <cmath>

#include "framework/ball_progress.h"

namespace olympics::sports::soccer {
namespace {

constexpr double kGravity = 9.81;

}  // namespace

std::vector<RewardTerm> penalty_kick_rewards() {
  return {{"player_to_ball", 0.4, "m/tick the root came closer to the ball (while g <= 0)"},
          {"ball_to_goal", 0.1, "m/tick the ball came closer to the goal target (while g > 0)"},
          {"ball_velocity_to_goal", 0.1, "m/s of the ball towards the goal target (while g > 0)"},
          {"ball_to_target", 0.8,
           "exp(-d^2), d from the ball's predicted entry in the goal plane to the target (g > 0)"},
          {"no_dribble", -1.0, "1 - exp(-0.2 d^2), d how far the root passed the ball's spot"},
          {"goal", 0.0, "1 the tick the kick goes in (-1 for a goalkeeper); not in eq. 11"},
          {"fallen", 0.0, "1 while the player is down (falls are not penalised by default)"}};
}

std::vector<RewardTerm> team_play_rewards() {
  return {{"player_to_ball", 0.4, "m/tick the root came closer to the ball"},
          {"ball_to_goal", 0.1, "m/tick the ball came closer to the opponents' goal"},
          {"ball_velocity_to_goal", 0.1, "m/s of the ball towards the opponents' goal"},
          {"goal", 10.0, "+1 the tick my side scores, -1 the tick it concedes"},
          {"fallen", 0.0, "1 while the player is down (falls are not penalised by default)"}};
}

double player_to_ball(const RewardState& s) {
  return approach_to_ball(s.root_before, s.root, s.ball);
}

double ball_to_goal(const RewardState& s) { return ball_progress(s.target, s.ball_before, s.ball); }

double ball_velocity_to_goal(const RewardState& s) {
  return ball_speed_towards(s.target, s.ball, s.ball_velocity);
}

bool entry_point(const RewardState& s, Eigen::Vector3d& entry) {
  const double towards = s.attack * s.ball_velocity.x();
  const double gap = s.attack * (s.target.x() - s.ball.x());
  if (towards <= 1e-6 || gap < 0) return false;
  const double t = gap / towards;
  entry = s.ball + s.ball_velocity * t;
  entry.z() -= 0.5 * kGravity * t * t;
  return true;
}

double ball_to_target(const RewardState& s) {
  Eigen::Vector3d e;
  if (!entry_point(s, e)) return 0.0;
  return std::exp(-(e - s.target).squaredNorm());
}

double no_dribble(const RewardState& s, const Eigen::Vector3d& spawn) {
  const double past = std::max(0.0, s.attack * (s.root.x() - spawn.x()));
  return 1.0 - std::exp(-0.2 * past * past);
}

std::array<float, 7> penalty_kick_terms(const RewardState& s, const Eigen::Vector3d& spawn,
                                        bool goal) {
  const bool closer = ball_to_goal(s) > kBallNearingGoal;  // g > 0, past the dead band
  return {static_cast<float>(closer ? 0.0 : player_to_ball(s)),
          static_cast<float>(closer ? ball_to_goal(s) : 0.0),
          static_cast<float>(closer ? ball_velocity_to_goal(s) : 0.0),
          static_cast<float>(closer ? ball_to_target(s) : 0.0),
          static_cast<float>(no_dribble(s, spawn)),
          goal ? 1.0f : 0.0f,
          s.fallen ? 1.0f : 0.0f};
}

std::array<float, 7> goalkeeper_terms(const RewardState& s, bool goal) {
  return {static_cast<float>(player_to_ball(s)),
          0,
          0,
          0,
          0,
          goal ? -1.0f : 0.0f,
          s.fallen ? 1.0f : 0.0f};
}

std::array<float, 5> team_play_terms(const RewardState& s, int goal) {
  return {static_cast<float>(player_to_ball(s)), static_cast<float>(ball_to_goal(s)),
          static_cast<float>(ball_velocity_to_goal(s)), static_cast<float>(goal),
          s.fallen ? 1.0f : 0.0f};
}

}  // namespace olympics::sports::soccer
