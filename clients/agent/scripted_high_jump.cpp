#include "scripted_high_jump.h"

#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {

control::StandingJump HighJumpPlan::tucked_jump() {
  // The search's means after 20 iterations (tests/sports/high_jump/scripted_high_jump_test.cpp):
  // a slow, deep crouch leaning forward, a short push with the ankles, then the knees pulled
  // up to the chest (hips -2.2, knees 2.6 rad) for the flight over the bar.
  control::StandingJump j;
  j.crouch = {-1.138, 1.106, -0.611, 0.997, 0.064, 0.626};
  j.push = {0.184, 0.361, -0.653, -0.444, 0.048, -1.671};
  j.flight = {-2.176, 2.561, -0.609, 0.759, -0.315, -0.632};
  j.crouch_s = 0.988, j.push_s = 0.172;
  return j;
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
