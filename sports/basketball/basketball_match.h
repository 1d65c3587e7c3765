// A basketball match of SMPL-X humanoids (fingers: 153 joint targets).
//
// Mode free_throw: one shooter behind the free-throw line, facing the basket; the ball is
// presented between its hands (held still in front of the chest for `present_s`, so the hands
// can close on it) and is then the players' to hold by friction alone: no weld, no attachment.
// The throw ends with a basket, the ball on the floor or off the court, a fall before the ball
// is released, or the time limit.
//
// Team play (1v1, 2v2) on the half court (3x3) or the full court (`court: full`): the
// BasketballReferee's rules (points by where the shot was released, clearing on the half court,
// the shot clock, out of bounds, the game to points_to_win or the time limit); this class
// carries out its restarts: the taking side's player on the spot
// with the ball presented between its hands as at a free throw, a teammate beside it, the
// defenders `restart_distance` away between it and the basket. Who touched the ball, and whether
// it hit the basket or the floor, come from its sensed contacts at the physics rate.
#pragma once

#include <memory>
#include <random>

#include "basketball/basket_watch.h"
#include "basketball/basketball_referee.h"
#include "basketball/basketball_rewards.h"
#include "basketball/court.h"
#include "equipment/ball.h"
#include "framework/smpl_match.h"

namespace olympics::sports::basketball {

struct BasketballConfig {
  Court court;
  TeamPlayRules rules;
  double present_s = 0.5;         // the ball is held still between the hands this long
  double restart_distance = 2.0;  // m: the defenders from the taker at a restart
  double game_s = 600;            // team play's default time limit
  bool stand_up = true;           // team play: a player down 2 s is stood up where it lies
};

// The humanoid basketball plays, chosen here once: the SMPL-X with fingers, which hold the ball.
inline constexpr core::HumanoidKind kHumanoid = core::HumanoidKind::SmplX;

bool is_team_play(const std::string& mode);
std::vector<LayoutBlock> basketball_task_layout(const ModeSpec& mode);
std::vector<RefereeCall> basketball_calls();

class BasketballMatch : public SmplMatch {
 public:
  BasketballMatch(const BasketballConfig& config, const ModeSpec& mode, Layout layout,
                  const MatchSettings& settings);

  // For tests and benchmarks.
  equipment::Ball& ball() { return *ball_; }
  const equipment::Ball& ball() const { return *ball_; }
  const Court& court() const { return config_.court; }
  const BasketballReferee& referee() const { return referee_; }
  // Where the ball is (or was last) presented: in front of a player's chest, between its hands.
  Eigen::Vector3d present_spot() const { return present_; }
  bool presenting() const { return time() < present_until_; }
  // The target of eq. 12's desired velocity, above the rim of `basket`.
  Eigen::Vector3d target(int basket = 0) const;
  // The basket a slot's side attacks (0 on the half court).
  int attacked_by(int slot) const { return referee_.attacks(team_of(slot)); }

  // In front of the chest, between the hands of the hold pose (measured, docs/basketball.md).
  static constexpr double kPresentForward = 0.54, kPresentHeight = 1.2;
  static constexpr double kBehindLine = 0.35;  // the shooter's root behind the free-throw line

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;
  void extra_state(std::vector<double>& values) const override;

  void settle_free_throw();
  void settle_team_play();
  // The ball still between the hands of a player just placed at `at`.
  void present_to(int slot, const core::RootPlacement& at);
  void carry_out(const Restart& r);
  void log_stoppage(const Stoppage& s);
  core::RootPlacement placement(const Eigen::Vector2d& at, const Eigen::Vector2d& facing);
  // A slot's tick as the rewards need it, possession as it stands; `points` is left at 0.
  TeamPlayState reward_state(int slot) const;
  nlohmann::json score_json() const;
  // At the end: every counted basket and how often play stopped for each reason.
  void write_game_summary();

  BasketballConfig config_;
  bool team_play_;
  std::unique_ptr<equipment::Ball> ball_;
  BasketballReferee referee_;
  BasketWatch watch_;
  Eigen::Vector3d present_ = Eigen::Vector3d::Zero();
  double present_until_ = 0;
  int presented_slot_ = -1;
  Eigen::Vector3d ball_before_step_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d ball_before_tick_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> root_before_;
  int basket_this_tick_ = -1;      // which basket the ball went down through this tick, if any
  int from_below_this_tick_ = -1;  // which rim it went up through from below this tick, if any
  bool touched_floor_ = false;     // free throw: after the presentation
  double shooter_touch_s_ = 0;     // free throw: when the ball last touched the shooter
  bool out_this_tick_ = false;     // team play: the ball on the floor outside the lines
  nlohmann::json baskets_ = nlohmann::json::array();     // every counted basket, for the result
  nlohmann::json stoppages_ = nlohmann::json::object();  // reason -> count
};

}  // namespace olympics::sports::basketball
