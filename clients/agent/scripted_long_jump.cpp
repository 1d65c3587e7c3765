#include "scripted_long_jump.h"

#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {

control::StandingJump LongJumpPlan::standing_long_jump() {
  // The search's means after 12 + 25 iterations (tests/sports/long_jump/
  // scripted_long_jump_test.cpp): a deep crouch with the trunk forward and the arms back, a
  // push of the hips, knees and ankles with the arms thrown forward, then the hips flexed and
  // knees tucked for the flight.
  control::StandingJump j;
  j.crouch = {-1.256, 1.326, -0.758, 0.979, 0.549, 0.587};
  j.push = {0.857, -0.122, -1.030, -1.526, -0.364, -1.613};
  j.flight = {-0.109, -0.013, -0.402, 0.816, 0.341, -1.725};
  j.crouch_s = 0.790, j.push_s = 0.223;
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
