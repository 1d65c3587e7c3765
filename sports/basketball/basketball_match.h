// A basketball match of SMPL-X humanoids (fingers: 153 joint targets). Mode free_throw: one
// shooter behind the free-throw line, facing the basket; the ball is presented between its hands
// (held still in front of the chest for `present_s`, so the hands can close on it) and is then
// the players' to hold by friction alone: no weld, no attachment. The throw ends with a basket,
// the ball on the floor or off the court, a fall, or the time limit.
#pragma once

#include <memory>
#include <random>

#include "basketball/basketball_rewards.h"
#include "basketball/court.h"
#include "equipment/ball.h"
#include "framework/smpl_match.h"

namespace olympics::sports::basketball {

struct BasketballConfig {
  Court court;
  double present_s = 0.5;  // the ball is held still between the hands this long
};

std::vector<LayoutBlock> free_throw_layout();
std::vector<RefereeCall> basketball_calls();

class BasketballMatch : public SmplMatch {
 public:
  BasketballMatch(const BasketballConfig& config, const ModeSpec& mode, Layout layout,
                  const MatchSettings& settings);

  // For tests and benchmarks.
  equipment::Ball& ball() { return *ball_; }
  const equipment::Ball& ball() const { return *ball_; }
  const Court& court() const { return config_.court; }
  // Where the ball is presented: in front of the shooter's chest, between its hands.
  Eigen::Vector3d present_spot() const { return present_; }
  bool presenting() const { return time() < config_.present_s; }
  // The target of eq. 12's desired velocity, above the rim.
  Eigen::Vector3d target() const;

  // In front of the chest, between the hands of the hold pose (measured, docs/basketball.md).
  static constexpr double kPresentForward = 0.54, kPresentHeight = 1.2;
  static constexpr double kBehindLine = 0.35;  // the shooter's root behind the free-throw line

 private:
  void write_task_observation(int slot, const HeadingFrame& frame,
                              ObservationWriter& out) const override;
  void before_physics_step() override;
  void after_physics_step(double step_start) override;
  void settle_tick() override;
  void describe_scene(SceneBuilder& scene) const override;
  void extra_scene_poses(std::vector<float>& out) const override;
  void extra_state(std::vector<double>& values) const override;

  BasketballConfig config_;
  std::mt19937_64 rng_;
  std::unique_ptr<equipment::Ball> ball_;
  Eigen::Vector3d present_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d ball_before_step_ = Eigen::Vector3d::Zero();
  bool basket_this_tick_ = false;
  bool touched_floor_ = false;  // after the presentation
};

}  // namespace olympics::sports::basketball
