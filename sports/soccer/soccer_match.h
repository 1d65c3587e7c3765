// A soccer match of SMPL humanoids: modes penalty_kick (one kicker, an empty goal),
// penalty_kick_keeper (a kicker and a goalkeeper), 1v1 and 2v2. The ball is an ODE body (a size-5
// ball with drag and rolling resistance, equipment/ball.h) that players move with any body part;
// a FastBallGuard keeps a hard shot from passing through a post, the bar, the net or a foot.
// Who touched the ball comes from its sensed contacts at the physics rate.
//
// Penalty kick: the ball on the spot `penalty_distance` from the goal at +x, the kicker 2 m
// behind it; the episode ends with a goal, the ball out of play or the time limit (the kicker may
// touch the ball again; the reward's no_dribble term says what the seed thought of that). Team
// play: the SoccerReferee's rules (goals, throw-ins, goal kicks, corners, kick-offs, halves); this
// class carries out its restarts: the ball on its spot, the players back in their halves for a
// kick-off, opponents moved back from any other restart.
#pragma once

#include <memory>
#include <optional>
#include <random>

#include "equipment/ball.h"
#include "equipment/fast_ball.h"
#include "framework/smpl_match.h"
#include "soccer/field.h"
#include "soccer/soccer_referee.h"
#include "soccer/soccer_rewards.h"

namespace olympics::sports::soccer {

enum class SoccerMode { PenaltyKick, PenaltyKickKeeper, TeamPlay };

struct SoccerConfig {
  Field field;
  SoccerRules rules;
  double penalty_distance = 11;  // m from the goal line to the penalty spot
  bool stand_up = false;         // falls: a player down 2 s is stood up where it lies
};

SoccerMode soccer_mode(const std::string& mode);
std::vector<LayoutBlock> soccer_task_layout(const ModeSpec& mode);
std::vector<RefereeCall> soccer_calls();

class SoccerMatch : public SmplMatch {
 public:
  SoccerMatch(const SoccerConfig& config, const ModeSpec& mode, Layout layout,
              const MatchSettings& settings);

  // For tests and benchmarks: the ball (its state may be set), the rules, the field.
  equipment::Ball& ball() { return *ball_; }
  const equipment::Ball& ball() const { return *ball_; }
  const SoccerReferee& referee() const { return referee_; }
  const Field& field() const { return config_.field; }
  // Whether a player touched the ball in the last tick.
  bool touched_this_tick(int slot) const { return touch_tick_[slot] == tick(); }
  // Where the ball starts: the penalty spot, or the centre spot in team play.
  Eigen::Vector3d ball_spot() const { return spawn_; }

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void extra_state(std::vector<double>& values) const override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;

  // `judged`: the ball where the rules judge it this tick (crossed_at_, else where it is now).
  void settle_penalty(const Eigen::Vector3d& judged);
  void settle_team_play(const Eigen::Vector3d& judged);
  void carry_out(const Stoppage& s);
  void log_stoppage(const Stoppage& s);
  // The goal and out calls, and the goal's line in the result's "goals" (scores already counted).
  void record_goal(const GoalCall& g);
  void record_out(const std::string& line, int last_touch);
  void kick_off_positions(int kicking_team);
  void clear_restart_area(const Restart& r);
  int attack(int slot) const;
  RewardState reward_state(int slot) const;
  void remember_positions();
  nlohmann::json score_json() const;
  core::RootPlacement placement(const Eigen::Vector2d& at, int facing);

  SoccerConfig config_;
  SoccerMode kind_;
  std::unique_ptr<equipment::Ball> ball_;
  equipment::FastBallGuard guard_;
  SoccerReferee referee_;
  Eigen::Vector3d spawn_ = Eigen::Vector3d::Zero();  // the ball's spot (penalty kick)
  std::vector<Eigen::Vector3d> root_before_;
  Eigen::Vector3d ball_before_ = Eigen::Vector3d::Zero();
  // Where the ball was at the first physics step of this tick that found it wholly over a line
  // (goals and outs are judged every step, as basketball's baskets: a ball over the line for
  // part of a tick has crossed it).
  std::optional<Eigen::Vector3d> crossed_at_;
  std::vector<int> touch_tick_;                     // per slot: the last tick it touched the ball
  int last_toucher_ = -1;                           // penalty: the slot that touched the ball last
  nlohmann::json goals_ = nlohmann::json::array();  // every goal, for the result
};

}  // namespace olympics::sports::soccer
