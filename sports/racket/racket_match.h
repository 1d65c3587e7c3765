// A tennis or table-tennis match (modes ball_return, 1v1, 2v2): humanoids holding rackets, a ball
// flown with continuous collision, a referee per rally, a scoreboard, and the seed's rewards.
//
// Each physics step: the humanoids step, the racket faces' start and end poses give swept discs,
// the ball flies against them and the arena, contacts go to the referee, and a racket's hand
// feels the ball's impulse on the next step.
//
// ball_return: one player on team 0; balls come from the far side one after another. A return
// that lands in counts as a hit and the next ball is launched; the episode ends when the player
// loses a point (or falls). 1v1 / 2v2: every point starts with both sides reset to their places
// and a ball fed towards the serving side; points go to the scoreboard until the match is won or
// the time limit ends it (then the leader wins).
#pragma once

#include <memory>
#include <random>

#include "core/fall_detector.h"
#include "core/humanoid_scene.h"
#include "equipment/ball_flight.h"
#include "equipment/body_probe.h"
#include "racket/racket_game.h"
#include "racket/rally_referee.h"
#include "racket/scoreboard.h"
#include "sport.h"

namespace olympics::sports::racket {

enum class RacketMode { BallReturn, Singles, Doubles };

struct RacketMatchConfig {
  RacketGame game;
  RacketMode mode = RacketMode::Singles;
  TennisFormat tennis;             // used by tennis
  TableTennisFormat table_tennis;  // used by table tennis
  double max_rally_s = 10;         // no stroke for this long: the side to play loses the point
};

// The team of each slot in a mode.
std::vector<int> racket_mode_teams(RacketMode mode);

// The task observation's blocks (after the self observation), shared with `describe`.
std::vector<LayoutBlock> racket_task_layout(int slots);
std::vector<std::string> racket_reward_names();

class RacketMatch : public SportMatch {
 public:
  RacketMatch(const RacketMatchConfig& config, const MatchSettings& settings);

  int slot_count() const override { return static_cast<int>(teams_.size()); }
  int team_count() const override { return config_.mode == RacketMode::BallReturn ? 1 : 2; }
  int team_of(int slot) const override { return teams_[slot]; }
  int obs_size() const override;
  int action_size() const override { return 69; }
  const std::vector<std::string>& reward_terms() const override { return term_names_; }
  void observe(int slot, std::span<float> out) const override;
  void step(const std::vector<std::span<const float>>& actions) override;
  const TickOutcome& outcome() const override { return outcome_; }
  int tick() const override { return tick_; }
  void forfeit(int losing_team, const std::string& reason) override;
  std::uint64_t state_hash() const override;

  // Returns that landed in this episode (the benchmark's count).
  int returns_in(int slot) const { return hits_[slot]; }

 private:
  void start_point();
  void launch_next_ball();
  void physics_step(std::vector<equipment::BallContact>& contacts);
  void handle_contact(const equipment::BallContact& c, double t);
  void probe_bodies(const Eigen::Vector3d& from, double t);
  void settle_point();
  core::RootPlacement start_placement(int slot) const;
  equipment::Pose racket_pose(int slot) const;
  Eigen::Vector2d draw_target(int slot);

  RacketMatchConfig config_;
  std::vector<int> teams_;
  int time_limit_ticks_;
  std::mt19937_64 rng_;
  core::HumanoidScene scene_;
  int hand_body_ = -1;
  std::vector<int> entity_of_slot_;
  std::vector<core::FallDetector> falls_;
  equipment::BallFlight flight_;
  equipment::BodyProbe probe_;
  std::vector<equipment::ArenaBox> arena_;
  std::vector<equipment::MovingDisc> discs_;  // per slot: its racket face; poses set each step
  RallyReferee referee_;
  std::unique_ptr<Scoreboard> scoreboard_;
  std::vector<Eigen::Vector2d> target_;    // per slot: where its next stroke should land
  std::vector<std::uint8_t> struck_;       // per slot: C, struck the ball coming to it
  std::vector<int> hits_;                  // per slot: returns that landed in
  std::vector<Eigen::Vector3d> reaction_;  // per slot: impulse on the hand for the next step
  std::vector<Eigen::Vector3d> reaction_at_;
  int served_points_ = 0;
  double time_ = 0;
  int tick_ = 0;
  std::vector<std::string> term_names_;
  TickOutcome outcome_;
  nlohmann::json tick_events_ = nlohmann::json::array();
  size_t referee_events_seen_ = 0;
  nlohmann::json points_ = nlohmann::json::array();  // every finished point, for the result
};

}  // namespace olympics::sports::racket
