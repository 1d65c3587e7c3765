// A tennis or table-tennis match (modes ball_return, 1v1, 2v2): humanoids holding rackets, a ball
// flown with continuous collision, a referee per rally, a scoreboard, and the seed's rewards.
//
// Each physics step: the racket faces' start and end poses give swept discs, the ball flies
// against them and the arena, contacts go to the referee, and a racket's hand feels the ball's
// impulse on the next step.
//
// ball_return: one player on team 0; balls come from the far side one after another. A return
// that lands in counts as a hit and the next ball is launched; the episode ends when the player
// loses a point (or falls). 1v1 / 2v2: every point starts with both sides reset to their places
// and a ball fed towards the serving side (or, `start: "serve"`, tossed for the server to serve
// it); points go to the scoreboard until the match is won or
// the time limit ends it (then the leader wins).
#pragma once

#include <array>
#include <memory>
#include <random>

#include "equipment/ball_flight.h"
#include "equipment/body_probe.h"
#include "framework/smpl_match.h"
#include "racket/racket_game.h"
#include "racket/rally_referee.h"
#include "racket/scoreboard.h"

namespace olympics::sports::racket {

enum class RacketMode { BallReturn, Singles, Doubles };

struct RacketMatchConfig {
  RacketGame game;
  RacketMode mode = RacketMode::Singles;
  TennisFormat tennis;             // used by tennis
  TableTennisFormat table_tennis;  // used by table tennis
  double max_rally_s = 10;         // no stroke for this long: the side to play loses the point
  bool feed_to_player = true;      // each point's first ball at the receiver (else anywhere)
  bool serve = false;              // 1v1 / 2v2: each point starts with a toss for the server
};

// The task observation's blocks (after the self observation), shared with `describe`.
std::vector<LayoutBlock> racket_task_layout(int slots);
std::vector<RewardTerm> racket_rewards();
std::vector<RefereeCall> racket_calls();

class RacketMatch : public SmplMatch {
 public:
  RacketMatch(const RacketMatchConfig& config, const ModeSpec& mode, Layout layout,
              const MatchSettings& settings);

  // Returns that landed in this episode (the benchmark's count).
  int returns_in(int slot) const { return hits_[slot]; }

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

  void start_point();
  void reset_players();  // every player back at its place for a point's start
  void feed(int receiving_team, int fed_slot);  // the point's ball, launched to `fed_slot`
  void log_referee_calls();                     // the referee's calls not yet in the log
  void toss();  // `start: "serve"`: a ball tossed for the server (again after a fault or a let)
  int doubles_member(int team);  // which partner of `team` takes this point's ball
  int receiver_y_sign() const;
  void handle_contact(const equipment::BallContact& c, double t);
  void probe_bodies(const Eigen::Vector3d& from, double t);
  core::RootPlacement start_placement(int slot) const;
  equipment::Pose racket_pose(int slot) const;
  Eigen::Vector2d draw_target(int slot);

  RacketMatchConfig config_;
  int hand_body_ = -1;
  equipment::BallFlight flight_;
  equipment::BodyProbe probe_;
  std::vector<equipment::ArenaBox> arena_;
  std::vector<equipment::MovingDisc> discs_;  // per slot: its racket face; poses set each step
  std::vector<equipment::BallContact> contacts_;
  RallyReferee referee_;
  std::unique_ptr<Scoreboard> scoreboard_;
  std::vector<Eigen::Vector2d> target_;    // per slot: where its next stroke should land
  std::vector<std::uint8_t> struck_;       // per slot: C, struck the ball coming to it
  std::vector<int> hits_;                  // per slot: returns that landed in
  std::vector<Eigen::Vector3d> reaction_;  // per slot: impulse on the hand for the next step
  std::vector<Eigen::Vector3d> reaction_at_;
  int served_points_ = 0;
  int fed_slot_ = -1;                   // the feed: who this point's ball was launched to
  int serving_team_ = -1;               // `start: "serve"`: the team whose service turn this is
  std::array<int, 2> service_turns_{};  // ...and how many turns each team has begun
  int server_slot_ = -1;                // `start: "serve"`: who serves this point
  int faults_ = 0;                      // ...and its faults so far
  size_t referee_events_seen_ = 0;
  nlohmann::json points_ = nlohmann::json::array();  // every finished point, for the result
};

}  // namespace olympics::sports::racket
