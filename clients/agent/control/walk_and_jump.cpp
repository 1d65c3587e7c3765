#include "control/walk_and_jump.h"

#include <algorithm>

#include "smpl_observation.h"

namespace olympics::client::control {
namespace {

StepGains walker_gains(const JumpApproach& approach) {
  StepGains g;
  g.max_speed = approach.walk_speed;
  g.turn_start = 0.15;  // standing, it steps round until square to where it will jump
  return g;
}

}  // namespace

WalkAndJump::WalkAndJump(const JumpApproach& approach, double control_dt)
    : approach_(approach), control_dt_(control_dt) {
  restart();
}

void WalkAndJump::restart() {
  legs_.emplace(walker_gains(approach_), control_dt_);
  still_for_ = 0;
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
  legs_->act(o, stop, facing, a);
  const bool there = !legs_->stepping() && stop.norm() < approach_.arrived_m &&
                     smpl::root_velocity(o).head<2>().norm() < approach_.still_speed;
  still_for_ = there ? still_for_ + control_dt_ : 0;
  if (still_for_ >= approach_.still_s) jumping_ = 0.0;
}

}  // namespace olympics::client::control
