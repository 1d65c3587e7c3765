// A long-jump match: one runway, board and sand pit per athlete (side by side, lane_spacing
// apart, so attempts never meet), each athlete's series of attempts taken one after another
// from its start mark; the match ends when every series is complete and ranks the athletes.
#pragma once

#include <optional>
#include <vector>

#include "athletics/athlete_probe.h"
#include "athletics/attempt_series.h"
#include "framework/jittered_start.h"
#include "framework/smpl_match.h"
#include "long_jump/long_jump_referee.h"
#include "long_jump/long_jump_rules.h"

namespace olympics::sports::long_jump {

std::vector<LayoutBlock> long_jump_task_layout();
std::vector<RefereeCall> long_jump_calls();

// The sand's give: stiff but well damped (a break of a centimetre or two under a landing).
inline constexpr core::ContactSoftness kSand{30000.0, 3000.0};

class LongJumpMatch : public SmplMatch {
 public:
  LongJumpMatch(const LongJumpRules& rules, const ModeSpec& mode, Layout layout,
                const MatchSettings& settings);

  const LongJumpRules& rules() const { return rules_; }
  const athletics::HorizontalSeries& series(int slot) const { return athletes_[slot].series; }
  double lane_y(int slot) const { return slot * rules_.lane_spacing; }
  // Tests: the athlete's humanoid, to place it where a scripted setup wants it.
  core::Humanoid& athlete(int slot) { return player(slot); }

 private:
  struct Athlete {
    athletics::HorizontalSeries series;
    LongJumpReferee referee;
    double attempt_start = 0;
    std::optional<athletics::AttemptResult> decided;  // this tick's decision, acted on in settle
    Eigen::Vector3d root_prev = Eigen::Vector3d::Zero();
  };

  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void describe_scene(SceneBuilder& scene) const override;

  void build_lane(int slot);
  JumpStep read_step(int slot) const;
  core::RootPlacement start_mark(int slot) const;
  // The start mark moved and turned a little by the match's random stream (up to 0.1 m, 0.1
  // rad: framework/jittered_start.h), for each attempt, so that seeds differ.
  core::RootPlacement jittered_start_mark(int slot) {
    const core::RootPlacement m = start_mark(slot);
    return jittered_start(m.position.head<2>(), m.yaw, rng());
  }
  athletics::Footprint pit(int slot) const;
  Eigen::Vector3d goal(int slot) const { return {rules_.goal_x, lane_y(slot), rules_.goal_z}; }
  void finish();

  LongJumpRules rules_;
  std::vector<Athlete> athletes_;
  std::vector<const core::GeomTag*> pit_tags_;  // per slot: its pit's sand
  std::vector<int> feet_;
};

}  // namespace olympics::sports::long_jump
