#include "basketball/basketball_match.h"

#include <cmath>

#include "core/humanoid_assets.h"
#include "core/state_hash.h"
#include "framework/ball_observation.h"
#include "framework/jittered_start.h"

namespace olympics::sports::basketball {
namespace {

const core::ModelSpec& player_model() {
  static const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::SmplX);
  return spec;
}

constexpr double kFloorTouch = 0.01;  // m: the ball's bottom this close to the floor

}  // namespace

std::vector<LayoutBlock> free_throw_layout() {
  return {ball_observation_block(),
          {"rim", 3, "m", "the rim's centre relative to the root, heading frame"},
          {"target", 3, "m",
           "the target of the desired launch velocity (above the rim) relative to the ball, "
           "heading frame"},
          {"throw", 2, "fraction, flag",
           "share of the time left; 1 while the ball is still being presented, else 0"}};
}

std::vector<RefereeCall> basketball_calls() {
  return {{"basket", "the ball went down through the rim (slot: the shooter, points)"},
          {"miss", "the ball came down on the floor or left the court without a basket"},
          {"fall", "a player fell (body)"}};
}

BasketballMatch::BasketballMatch(const BasketballConfig& config, const ModeSpec& mode,
                                 Layout layout, const MatchSettings& settings)
    : SmplMatch(mode, std::move(layout), settings), config_(config), rng_(settings.seed) {
  config_.court.build(scene().world());
  add_player(player_model(), {});
  const Eigen::Vector2d spot(config_.court.free_throw_line_x() - kBehindLine, 0);
  const core::RootPlacement start = jittered_start(spot, 0.0, rng_);
  reset_player(0, start);
  const Eigen::Vector2d forward(std::cos(start.yaw), std::sin(start.yaw));
  const Eigen::Vector2d at = start.position.head<2>() + kPresentForward * forward;
  present_ = {at.x(), at.y(), kPresentHeight};
  ball_ = std::make_unique<equipment::Ball>(scene().world(), equipment::basketball(), present_);
  ball_before_step_ = present_;
}

Eigen::Vector3d BasketballMatch::target() const {
  return config_.court.rim_centre() + Eigen::Vector3d(0, 0, kTargetAboveRim);
}

void BasketballMatch::before_physics_step() {
  ball_->prepare_step(scene().settings().physics_dt());
  ball_before_step_ = ball_->position();
}

void BasketballMatch::after_physics_step(double step_start) {
  if (step_start < config_.present_s) {  // still presented: it stays on its spot
    ball_->set_state(present_, Eigen::Vector3d::Zero());
    return;
  }
  const Eigen::Vector3d now = ball_->position();
  if (config_.court.basket(ball_before_step_, now)) basket_this_tick_ = true;
  if (!presenting() && now.z() - ball_->spec().radius < kFloorTouch) touched_floor_ = true;
}

void BasketballMatch::settle_tick() {
  const bool basket = basket_this_tick_;
  basket_this_tick_ = false;
  set_reward(0, free_throw_terms(ball_->position(), ball_->velocity(), target(), basket));
  if (basket) {
    outcome_.scores[0] = 1;
    nlohmann::json e = referee_event("basket", time(), 0);
    e["points"] = 1;
    log(std::move(e));
    return outcome_.end("basket", 0);
  }
  const bool off_court = !config_.court.inside(ball_->position().head<2>());
  if (touched_floor_ || off_court) {
    nlohmann::json e = referee_event("miss", time());
    e["where"] = touched_floor_ ? "floor" : "off_court";
    log(std::move(e));
    return outcome_.end("missed", -1);
  }
  if (!fell_this_tick().empty()) return outcome_.end("fall", -1);
}

void BasketballMatch::write_task_observation(int, const HeadingFrame& frame,
                                             ObservationWriter& out) const {
  write_ball_observation(*ball_, frame, out);
  out.begin("rim").put(frame.point(config_.court.rim_centre()));
  out.begin("target").put(frame.vector(target() - ball_->position()));
  out.begin("throw")
      .put(1.0 - static_cast<double>(tick()) / time_limit_ticks())
      .put(presenting() ? 1.0 : 0.0);
}

void BasketballMatch::extra_state(std::vector<double>& values) const {
  core::append_body_state(ball_->body(), values);
}

void BasketballMatch::describe_scene(SceneBuilder& scene) const {
  config_.court.describe(scene);
  const int ball = scene.add_body("ball", -1, "ball");
  scene.add_sphere(ball, Eigen::Vector3d::Zero(), ball_->spec().radius, "ball", "#e07a2a");
}

void BasketballMatch::extra_scene_poses(std::vector<float>& out) const {
  append_pose(out, ball_->position(), ball_->orientation());
}

}  // namespace olympics::sports::basketball
