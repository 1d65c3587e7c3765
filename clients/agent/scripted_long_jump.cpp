#include "scripted_long_jump.h"

#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {

control::StandingJump LongJumpPlan::standing_long_jump() {
  control::StandingJump j;
  j.crouch = {-0.9, 1.4, 0.4, 0.5, 0.0, 0.8};
  j.push = {0.2, 0.0, -0.6, 0.2, 0.0, -0.8};
  j.flight = {-1.4, 1.0, 0.0, 0.6, 0.0, -0.8};
  j.crouch_s = 0.5, j.push_s = 0.2;
  return j;
}

void ScriptedLongJumpPolicy::start(const MatchInfo& match) {
  if (match.sport != "long_jump")
    throw std::invalid_argument("the scripted long jumper jumps the long jump, not " + match.sport);
  line_ = match.observation.offset("take_off_line", "point");
  goal_ = match.observation.offset("goal", "position");
  time_left_ = match.observation.offset("attempt", "time_left");
  jumper_.emplace(plan_.approach, match.control_dt);
  last_time_left_ = 2;
}

void ScriptedLongJumpPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!jumper_) throw std::logic_error("ScriptedLongJumpPolicy: act() before start()");
  if (a.size() != smpl::kActions || o.size() < static_cast<size_t>(smpl::kSelfObservation))
    throw std::invalid_argument("the scripted long jumper plays the SMPL humanoid");
  if (o[time_left_] > last_time_left_ + 1e-6) jumper_->restart();  // the next attempt
  last_time_left_ = o[time_left_];
  // The runway's centre line runs through the line's point and the goal's (both on it).
  const Eigen::Vector2d line(o[line_], o[line_ + 1]), goal(o[goal_], o[goal_ + 1]);
  const Eigen::Vector2d along = (goal - line).normalized();
  jumper_->act(o, line - plan_.stop_m * along, std::atan2(along.y(), along.x()), a);
}

std::unique_ptr<Policy> make_scripted_long_jump() {
  return std::make_unique<ScriptedLongJumpPolicy>();
}

}  // namespace olympics::client
