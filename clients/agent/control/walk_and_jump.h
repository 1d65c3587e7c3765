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
  // The walker's gains (its top speed max_speed, step_s, ...); turn_start is always 0: it turns
  // only while walking (stepping round on the spot overshot).
  StepGains walk{};
  // > 0: it walks onto the line through the stop along the way it will face, aiming this far
  // (m) ahead of itself along that line, so that it arrives square to where it jumps; 0: straight
  // to the stop.
  double line_lead_m = 0;
  // > 0 (with line_lead_m): it has arrived once less than arrived_m of the line is left to the
  // stop and it is less than this far to the line's side.
  double arrived_side_m = 0;
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
  // Where the walker heads: the stop, or a point on the line into it (line_lead_m).
  Eigen::Vector2d walk_target(const Eigen::Vector2d& stop, double facing) const;
  bool arrived(const Eigen::Vector2d& stop, double facing) const;
  // Which way it turns on the way there: to the walk's direction, then to `facing`.
  double walk_turn(const Eigen::Vector2d& stop, const Eigen::Vector2d& target, double facing) const;

  JumpApproach approach_;
  double control_dt_;
  std::optional<StepController> legs_;
  bool standing_ = false;          // it has stopped walking and stands where it came to
  double still_for_ = 0;           // s it has stood still there
  std::optional<double> jumping_;  // s into the jump, once it began
};

}  // namespace olympics::client::control
