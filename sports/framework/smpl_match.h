// What every match of SMPL humanoids shares, so that a sport writes only its own rules:
//
// - slots and teams, from the sport's mode table;
// - the scene (one humanoid per slot), stepped at the control rate with the scene's substeps;
// - ticks and the time limit (from the scene's control step), truncation at the limit;
// - the random generator, seeded from the match seed;
// - falls: every player's FallDetector is read once per tick; going down logs a "fall" event;
// - the outcome's sizes, rewards as the weighted sum of the layout's terms, forfeits;
// - the observation: the self observation, then the sport's blocks through an
//   ObservationWriter that checks them against the layout;
// - the state hash (the scene, plus whatever the sport keeps outside ODE).
//
// A tick: actions -> for each physics step: before_physics_step(), the scene steps,
// after_physics_step() -> falls -> settle_tick() (the sport's referee and rewards) -> the time
// limit (on_time_limit()) -> info["events"].
#pragma once

#include <functional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "core/fall_detector.h"
#include "core/humanoid_scene.h"
#include "framework/heading_frame.h"
#include "framework/observation_writer.h"
#include "framework/referee_events.h"
#include "framework/scene_view.h"
#include "sport.h"

namespace olympics::sports {

class SmplMatch : public SportMatch {
 public:
  // The `falls` setting of the sports that offer stand_up_fallen: "report" or "stand_up".
  static SettingSpec falls_setting(const std::string& default_choice);
  int slot_count() const final { return mode_.slot_count(); }
  int team_count() const final { return mode_.team_count(); }
  int team_of(int slot) const final { return mode_.slot_teams[slot]; }
  int obs_size() const final { return layout_.observation_size(); }
  int action_size() const final { return layout_.action_size(); }
  const std::vector<std::string>& reward_terms() const final { return reward_names_; }
  const Layout& layout() const final { return layout_; }
  double time_limit_s() const final { return time_limit_ticks_ * control_dt(); }
  double control_dt() const final { return scene_.settings().control_dt; }
  void observe(int slot, std::span<float> out) const final;
  void step(const std::vector<std::span<const float>>& actions) final;
  const TickOutcome& outcome() const final { return outcome_; }
  int tick() const final { return tick_; }
  void forfeit(int losing_team, const std::string& reason) final;
  std::uint64_t state_hash() const final;
  // The players' bodies and what they hold, then the sport's arena (describe_scene).
  nlohmann::json scene_description() const final;
  void scene_poses(std::vector<float>& out) const final;
  // The world as it stands, read-only (tests, scene data for viewers).
  const core::HumanoidScene& scene() const { return scene_; }

 protected:
  // `layout` must begin with the self observation block ("self").
  SmplMatch(const ModeSpec& mode, Layout layout, const MatchSettings& settings,
            const core::SceneSettings& scene = {});

  // ---- What a sport writes.
  // Its blocks after "self", in layout order, seen from `slot` (frame: that humanoid's).
  virtual void write_task_observation(int slot, const HeadingFrame& frame,
                                      ObservationWriter& out) const = 0;
  // Around every physics step of a tick (actions are set before the first).
  virtual void before_physics_step() {}
  // `step_start`: the match time when this physics step began; time() is its end.
  virtual void after_physics_step(double step_start) { (void)step_start; }
  // After a tick's physics and falls: the referee, rewards (set_reward), ending the match.
  virtual void settle_tick() = 0;
  // The time limit came and the match is not over. By default: truncated, won by the team with
  // the most points (equal points, or a single team: nobody).
  virtual void on_time_limit();
  // State kept outside the scene's bodies (a ball flown outside ODE), hashed after them.
  virtual void extra_state(std::vector<double>& values) const { (void)values; }
  // For viewers: the arena and any moving body the players do not carry (a ball), and each
  // tick the poses of the bodies it added, in order (scene_view.h).
  virtual void describe_scene(SceneBuilder& scene) const { (void)scene; }
  virtual void extra_scene_poses(std::vector<float>& out) const { (void)out; }

  // ---- What the framework gives it.
  // Adds the humanoid of the next slot; `fall_exempt` bodies may touch the ground besides the
  // feet (a hand that holds equipment).
  void add_player(const core::ModelSpec& spec, const core::RootPlacement& placement,
                  const std::vector<std::string>& fall_exempt = {});
  // Back to the rest pose at `placement`, fall detection restarted.
  void reset_player(int slot, const core::RootPlacement& placement);
  core::HumanoidScene& scene() { return scene_; }
  // The match's one random generator, seeded from the match seed: every draw a sport makes
  // (who serves first, jittered start marks, ball launches) comes from it, in the order the
  // sport makes them, so the same seed plays the same match.
  std::mt19937_64& rng() { return rng_; }
  // The slot whose humanoid is the physics entity `entity` (a GeomTag's), or -1: the arena,
  // equipment.
  int slot_of_entity(int entity) const;
  core::Humanoid& player(int slot) { return scene_.humanoid(slot); }
  const core::Humanoid& player(int slot) const { return scene_.humanoid(slot); }
  const ModeSpec& mode() const { return mode_; }
  const std::vector<int>& teams() const { return mode_.slot_teams; }
  double time() const { return time_; }  // seconds simulated
  // Falls: is the slot down (a body other than its feet on the ground, or too low; it stays
  // down until it has been clear for kUpAfterS, so a body lying on the ground is one fall),
  // and which slots went down this tick.
  bool down(int slot) const { return down_[slot] != 0; }
  const std::vector<int>& fell_this_tick() const { return fell_; }
  // Stands every player that has been down kStandUpAfterS or longer up where it lies, facing
  // `yaw(slot)`, and logs "stood_up" (a sport's `falls: stand_up` setting: a game goes on).
  void stand_up_fallen(const std::function<double(int)>& yaw);
  static constexpr double kStandUpAfterS = 2;
  const core::FallDetector& fall_detector(int slot) const { return falls_[slot]; }
  // The reward terms of a slot for this tick, in layout order; its reward is their weighted sum.
  void set_reward(int slot, std::span<const float> terms);
  void log(nlohmann::json event) { events_.add(std::move(event), time_); }
  const nlohmann::json& events() const { return events_.events(); }
  static constexpr double kUpAfterS = 0.5;
  int time_limit_ticks() const { return time_limit_ticks_; }
  bool time_up() const { return tick_ >= time_limit_ticks_; }
  // Ends the match at the time limit: every slot still playing is truncated.
  void end_by_time_limit(int winner_team);
  // The team with the strictly highest score, else -1.
  int leading_team() const;

  TickOutcome outcome_;  // the sport fills scores, info and the end; sizes are set

 private:
  ModeSpec mode_;
  Layout layout_;
  std::vector<std::string> reward_names_;
  std::vector<float> reward_weights_;
  core::HumanoidScene scene_;
  std::mt19937_64 rng_;
  std::vector<core::FallDetector> falls_;
  std::vector<std::uint8_t> down_;
  std::vector<int> clear_ticks_;    // per slot, while down: ticks in a row the detector was clear
  std::vector<double> down_since_;  // per slot, while down: when it went down
  std::vector<int> fell_;
  EventLog events_;
  int time_limit_ticks_;
  int tick_ = 0;
  double time_ = 0;
};

}  // namespace olympics::sports
