// An épée bout (1v1): two SMPL fencers with épées on a piste; touches are found at the physics
// rate from the tip's contacts (TouchSensor) and decided by the FencingReferee; after every halt
// both fencers go back to their on-guard lines. Rewards: the seed's eq. 9-10 (combat_rewards.h).
#pragma once

#include <array>
#include <optional>
#include <random>

#include "fencing/fencing_referee.h"
#include "fencing/piste.h"
#include "framework/smpl_match.h"
#include "framework/touch_sensor.h"

namespace olympics::sports::fencing {

struct FencingConfig {
  FencingRules rules;
  Piste piste;
  double touch_force_n = 50;  // the tip's contact force that registers a touch
  bool whole_body = false;    // every body is a target (épée), not only the torso and head
};

// The SMPL humanoid holding an épée, as fencers are built.
const core::ModelSpec& fencer_model();

std::vector<LayoutBlock> fencing_task_layout();
std::vector<RefereeCall> fencing_calls();

class FencingMatch : public SmplMatch {
 public:
  FencingMatch(const FencingConfig& config, const ModeSpec& mode, Layout layout,
               const MatchSettings& settings);

  const FencingReferee& referee() const { return referee_; }
  // The tip of a fencer's épée: position and velocity in the world.
  Eigen::Vector3d tip_position(int slot) const;

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void on_time_limit() override;
  void describe_scene(SceneBuilder& scene) const override { config_.piste.describe(scene); }

  void record_halt(const Halt& halt);
  void back_on_guard();
  core::RootPlacement on_guard(int fencer);
  nlohmann::json score_json() const;

  FencingConfig config_;
  int hand_body_ = -1;
  int hand_own_geoms_ = 0;  // the hand's geoms before the épée's
  std::vector<int> targets_;
  std::array<int, 2> ankles_{};
  FencingReferee referee_;
  std::optional<TouchSensor> touches_;
  nlohmann::json exchanges_ = nlohmann::json::array();  // every decided exchange, for the result
};

}  // namespace olympics::sports::fencing
