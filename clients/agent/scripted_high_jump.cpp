#include "scripted_high_jump.h"

#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {

control::StandingJump HighJumpPlan::tucked_jump() {
  // The search in tests/sports/high_jump/scripted_high_jump_test.cpp (docs/athletics.md "The
  // scripted jumpers"): a short crouch, a push with the arms swung, then the knees pulled up to
  // the chest (hips -2.4, knees 3.1 rad) for the flight over the bar.
  control::StandingJump j;
  j.crouch = {-0.878, 1.838, -1.513, 0.760, -0.698, -0.870};
  j.push = {-0.406, -0.577, -1.003, -1.467, -0.214, -2.010};
  j.flight = {-2.410, 3.137, -0.820, 0.398, -0.486, -1.339};
  j.crouch_s = 0.781, j.push_s = 0.240;
  return j;
}

control::JumpApproach HighJumpPlan::seed_approach() {
  // Jump on arriving (still_s 0): standing still after the walk toppled it (20 of 20 fell on
  // tuning seeds 1-20 with 0.3 s still). The walker: steps of 0.25 s up to 0.6 m (default 0.3 s,
  // 0.5 m) make ~1.4 m/s, slowing by 1.2 m/s per metre left (default 2.4) to arrive at about
  // 0.35 m/s some 16.5 s in; onto the line square to the bar 2 m ahead of itself, arrived 0.15 m
  // before the stop along it, within 0.5 m to its side.
  control::JumpApproach a{
      .still_s = 0, .line_lead_m = 2.0, .arrived_side_m = 0.5, .jump = tucked_jump()};
  a.walk.max_speed = 2.5, a.walk.step_s = 0.25, a.walk.max_step = 0.6, a.walk.speed_per_m = 1.2;
  return a;
}

void ScriptedHighJumpPolicy::start(const MatchInfo& match) {
  if (match.sport != "high_jump")
    throw std::invalid_argument("the scripted high jumper jumps the high jump, not " + match.sport);
  bar_ = match.observation.offset("bar", "end_minus_y");
  time_left_ = match.observation.offset("attempt", "time_left");
  jumper_.emplace(plan_.approach, match.control_dt);
  last_time_left_ = 2;
}

void ScriptedHighJumpPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!jumper_) throw std::logic_error("ScriptedHighJumpPolicy: act() before start()");
  if (a.size() != smpl::kActions || o.size() < static_cast<size_t>(smpl::kSelfObservation))
    throw std::invalid_argument("the scripted high jumper plays the SMPL humanoid");
  if (o[time_left_] > last_time_left_ + 1e-6) jumper_->restart();  // the next attempt
  last_time_left_ = o[time_left_];
  // The bar's two ends (each 3 floats); over is across the bar, away from where it stands.
  const Eigen::Vector2d end_a(o[bar_], o[bar_ + 1]), end_b(o[bar_ + 3], o[bar_ + 4]);
  const Eigen::Vector2d middle = 0.5 * (end_a + end_b);
  Eigen::Vector2d over(-(end_b - end_a).y(), (end_b - end_a).x());
  over.normalize();
  if (over.dot(middle) < 0) over = -over;
  jumper_->act(o, middle - plan_.stop_m * over, std::atan2(over.y(), over.x()), a);
}

std::unique_ptr<Policy> make_scripted_high_jump() {
  return std::make_unique<ScriptedHighJumpPolicy>();
}

}  // namespace olympics::client
