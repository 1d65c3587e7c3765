// The scripted jumpers' attempt (long jump, high jump): walk (StepController) to a stop point,
// face a direction, stand there still for a moment (or not: JumpApproach::still_s 0), then make a
// standing jump (control::StandingJump) in the direction faced. The sport's policy says where the
// stop is and which way to face, from its own observation, each tick.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "control/standing_jump.h"
#include "step_controller.h"

namespace olympics::client::control {

struct JumpApproach {
  double still_s = 0.8;      // s standing still at the stop before the jump; 0: jump on arriving
  double arrived_m = 0.15;   // m from the stop where it stops walking and stands
  double still_speed = 0.1;  // m/s of the root below which it counts as still
  double walk_speed = 1.2;   // m/s the walker is asked for at most (StepGains::max_speed)
  StandingJump jump;
};

class WalkAndJump {
 public:
  WalkAndJump(const JumpApproach& approach, double control_dt);
  // From the start mark again (the next attempt).
  void restart();
  // Writes the whole action: walking toward `stop` (a ground point in the heading frame,
  // relative to the root) turned to `facing` (rad, left positive), then the jump.
  void act(std::span<const float> observation, const Eigen::Vector2d& stop, double facing,
           std::span<float> action);
  bool jumping() const { return jumping_.has_value(); }

 private:
  JumpApproach approach_;
  double control_dt_;
  std::optional<StepController> legs_;
  bool standing_ = false;          // it has stopped walking and stands where it came to
  double still_for_ = 0;           // s it has stood still there
  std::optional<double> jumping_;  // s into the jump, once it began
};

}  // namespace olympics::client::control
