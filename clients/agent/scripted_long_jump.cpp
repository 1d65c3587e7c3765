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

control::StandingJump LongJumpPlan::walking_long_jump() {
  // The search's means jumping on arrival at the walk-up's stop: 8 iterations with the line 6 m
  // from the start mark on tuning seeds 1-4, 6 more on seeds 1-8, 4 more on the full 20 m
  // runway, seeds 1-8 (docs/athletics.md).
  constexpr double kMeans[] = {-1.752, 1.639,  -1.471, 1.164,  0.969,  0.383,  0.766,
                               -0.669, -1.074, -1.880, 0.025,  -2.407, -0.138, -0.069,
                               -1.899, 1.417,  0.910,  -2.549, 0.620,  0.223};
  return control::StandingJump::from(kMeans);
}

void ScriptedLongJumpPolicy::start(const MatchInfo& match) {
  if (match.sport != "long_jump")
    throw std::invalid_argument("the scripted long jumper jumps the long jump, not " + match.sport);
  line_ = match.observation.offset("take_off_line", "point");
  goal_ = match.observation.offset("goal", "position");
  time_left_ = match.observation.offset("attempt", "time_left");
  control_dt_ = match.control_dt;
  jumper_.reset();
  last_time_left_ = 2;
}

void ScriptedLongJumpPolicy::act(std::span<const float> o, std::span<float> a) {
  if (control_dt_ <= 0) throw std::logic_error("ScriptedLongJumpPolicy: act() before start()");
  if (a.size() != smpl::kActions || o.size() < static_cast<size_t>(smpl::kSelfObservation))
    throw std::invalid_argument("the scripted long jumper plays the SMPL humanoid");
  if (o[time_left_] > last_time_left_ + 1e-6) jumper_.reset();  // the next attempt
  last_time_left_ = o[time_left_];
  // The runway's centre line runs through the line's point and the goal's (both on it).
  const Eigen::Vector2d line(o[line_], o[line_ + 1]), goal(o[goal_], o[goal_ + 1]);
  const Eigen::Vector2d along = (goal - line).normalized();
  if (!jumper_) {  // the attempt's start mark: near the line it stands, further back it walks up
    stage_ = line.dot(along) > plan_.walk_up_beyond_m ? &plan_.walk_up : &plan_.standing;
    jumper_.emplace(stage_->approach, control_dt_);
  }
  jumper_->act(o, line - stage_->stop_m * along, std::atan2(along.y(), along.x()), a);
}

std::unique_ptr<Policy> make_scripted_long_jump() {
  return std::make_unique<ScriptedLongJumpPolicy>();
}

}  // namespace olympics::client
