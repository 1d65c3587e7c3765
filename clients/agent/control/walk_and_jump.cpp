#include "control/walk_and_jump.h"

#include <algorithm>
#include <cmath>

#include "smpl_observation.h"

namespace olympics::client::control {
namespace {

StepGains walker_gains(const JumpApproach& approach) {
  StepGains g = approach.walk;
  // It turns toward where it will jump only while walking there: stepping round on the spot
  // (StepGains::turn_start) overshot and stepped to and fro for the rest of the attempt.
  g.turn_start = 0;
  return g;
}

bool feet_down(std::span<const float> o) {
  constexpr double kAnkleHeight = 0.07;  // the ankle's origin above the sole, foot flat
  const double ground = -smpl::root_height(o);
  return smpl::body_position(o, smpl::kLAnkle).z() < ground + kAnkleHeight + 0.03 &&
         smpl::body_position(o, smpl::kRAnkle).z() < ground + kAnkleHeight + 0.03;
}

}  // namespace

Eigen::Vector2d WalkAndJump::walk_target(const Eigen::Vector2d& stop, double facing) const {
  if (approach_.line_lead_m <= 0) return stop;
  // The root is at the origin; `along` < 0 is how far before the stop it is, along the line.
  const Eigen::Vector2d line(std::cos(facing), std::sin(facing));
  const double along = -stop.dot(line);
  return stop + line * std::min(0.0, along + approach_.line_lead_m);
}

bool WalkAndJump::arrived(const Eigen::Vector2d& stop, double facing) const {
  if (approach_.line_lead_m <= 0 || approach_.arrived_side_m <= 0)
    return stop.norm() < approach_.arrived_m;
  // On the line it counts how far is left along it: a jump a little to one side of the stop
  // goes the same way, where overshooting it along the line walks into what it jumps.
  const Eigen::Vector2d line(std::cos(facing), std::sin(facing));
  const double ahead = stop.dot(line), side = (stop - ahead * line).norm();
  return ahead < approach_.arrived_m && side < approach_.arrived_side_m;
}

double WalkAndJump::walk_turn(const Eigen::Vector2d& stop, const Eigen::Vector2d& target,
                              double facing) const {
  // Walking onto the line from afar it faces where it walks (the walker's sideways steps are
  // slower), and turns to the jump's way once it is on the line's last line_lead_m.
  if (approach_.line_lead_m <= 0 || standing_ || (target - stop).norm() < 1e-9) return facing;
  return std::atan2(target.y(), target.x());
}

WalkAndJump::WalkAndJump(const JumpApproach& approach, double control_dt)
    : approach_(approach), control_dt_(control_dt) {
  restart();
}

void WalkAndJump::restart() {
  legs_.emplace(walker_gains(approach_), control_dt_);
  still_for_ = 0;
  standing_ = false;
  jumping_.reset();
}

void WalkAndJump::act(std::span<const float> o, const Eigen::Vector2d& stop, double facing,
                      std::span<float> a) {
  std::fill(a.begin(), a.end(), 0.0f);
  if (jumping_) {
    write_standing_jump(approach_.jump, *jumping_, a);
    *jumping_ += control_dt_;
    return;
  }
  // Within reach of the stop and with both feet down it stops walking there and stands where it
  // is (a fresh controller stands when its target is where it is): the walker itself stops
  // only within 0.12 m and slower than 0.25 m/s at a step's end, and near a stop it tends to
  // step to and fro round it for the rest of the attempt.
  if (!standing_ && arrived(stop, facing) && feet_down(o)) {
    legs_.emplace(walker_gains(approach_), control_dt_);
    standing_ = true;
  }
  const Eigen::Vector2d target = standing_ ? Eigen::Vector2d::Zero() : walk_target(stop, facing);
  legs_->act(o, target, walk_turn(stop, target, facing), a);
  const bool still = standing_ && smpl::root_velocity(o).head<2>().norm() < approach_.still_speed;
  still_for_ = still ? still_for_ + control_dt_ : 0;
  // still_s 0: the jump begins on arriving, still moving (the walked-up jump was searched so).
  if (standing_ && (approach_.still_s <= 0 || still_for_ >= approach_.still_s)) jumping_ = 0.0;
}

}  // namespace olympics::client::control
