// A high-jump match: one installation (uprights, a free crossbar, the landing mat) per athlete,
// side by side lane_spacing apart; the athletes jump at the same time from their start marks, in
// rounds (athletics/height_rounds.h: one bar height for all, raised when everyone still in has
// cleared it or is out; official rules break a tie for first by a jump-off); an athlete whose
// attempt is decided waits, unjudged, until its next try; the match ends when the competition is
// over and ranks the athletes by the countback (and the jump-off).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "athletics/athlete_probe.h"
#include "athletics/attempt_series.h"
#include "athletics/height_rounds.h"
#include "framework/jittered_start.h"
#include "framework/smpl_match.h"
#include "high_jump/crossbar.h"
#include "high_jump/high_jump_referee.h"

namespace olympics::sports::high_jump {

std::vector<LayoutBlock> high_jump_task_layout();
std::vector<RefereeCall> high_jump_calls();

// The landing mat's give: foam that takes a landing over 10-20 cm.
inline constexpr core::ContactSoftness kFoam{1500.0, 300.0};
inline constexpr double kMatDepth = 4.0, kMatWidth = 6.0, kMatHeight = 0.7;  // TR 27.9
inline constexpr double kMatGap = 0.1;  // m from the bar's plane to the mat

class HighJumpMatch : public SmplMatch {
 public:
  HighJumpMatch(const HighJumpRules& rules, const ModeSpec& mode, Layout layout,
                const MatchSettings& settings);

  const HighJumpRules& rules() const { return rules_; }
  const athletics::HeightSeries& series(int slot) const { return rounds_.series(slot); }
  const athletics::HeightRounds& rounds() const { return rounds_; }
  // Whether the athlete is in an attempt now (else it waits for its next try, or is out).
  bool in_attempt(int slot) const { return athletes_[slot].in_attempt; }
  const Crossbar& bar(int slot) const { return *athletes_[slot].bar; }
  double lane_y(int slot) const { return slot * rules_.lane_spacing; }
  // Tests: the athlete's humanoid and its bar, to set a scene up by hand.
  core::Humanoid& athlete(int slot) { return player(slot); }
  Crossbar& bar(int slot) { return *athletes_[slot].bar; }

 private:
  struct Athlete {
    HighJumpReferee referee;
    std::unique_ptr<Crossbar> bar;
    double attempt_start = 0;
    bool in_attempt = true;  // judged; false while it waits for its next try
    std::optional<BarDecision> decided;
    Eigen::Vector3d root_prev = Eigen::Vector3d::Zero();         // the last physics step's
    Eigen::Vector3d reward_root_prev = Eigen::Vector3d::Zero();  // the last tick's
  };

  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void extra_state(std::vector<double>& values) const override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;

  Eigen::Vector3d bar_centre(int slot) const { return {rules_.bar_x, bar_y(slot), 0.0}; }
  double bar_y(int slot) const { return rules_.bar_y + lane_y(slot); }
  Eigen::Vector3d goal(int slot) const {
    return {rules_.bar_x + rules_.goal_past, bar_y(slot), rules_.goal_z};
  }
  athletics::Footprint mat(int slot) const;
  core::RootPlacement start_mark(int slot) const { return {{0.0, lane_y(slot), 0.0}, 0.0}; }
  // The start mark moved and turned a little by the match's random stream (up to 0.1 m, 0.1
  // rad: framework/jittered_start.h), for each attempt, so that seeds differ.
  core::RootPlacement jittered_start_mark(int slot) {
    const core::RootPlacement m = start_mark(slot);
    return jittered_start(m.position.head<2>(), m.yaw, rng());
  }
  BarStep read_step(int slot) const;
  void record_attempt(int slot);
  void start_attempt(int slot);
  void finish();

  HighJumpRules rules_;
  athletics::HeightRounds rounds_;
  std::vector<Athlete> athletes_;
  std::vector<const core::GeomTag*> mat_tags_;  // per slot, null without a mat
};

}  // namespace olympics::sports::high_jump
