#include "scripted_fencing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "arm_control.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

constexpr double kOutOfReach_m = 2.1;  // root to root: the tips cannot reach
constexpr double kLunge_m = 1.25;      // root to root while attacking: the tip is in the target
constexpr double kAttack_s = 1.2;      // longest attack before falling back
constexpr double kRecover_s = 0.8;
constexpr double kArmRate = 2.0;  // rad/s the épée arm turns at (faster spins the body)
// Walking speed (m/s). Most falls came as both fencers rushed in at the stepping controller's
// 1.2 m/s and collided or stopped short; at 0.7 they fell about 20 times less often on seeds
// 1-40 (the tuning seeds; 0.6-0.8 were alike, 0.9 fell five times as often).
constexpr double kMaxSpeed = 0.7;

}  // namespace

void ScriptedFencingPolicy::start(const MatchInfo& match) {
  if (match.sport != "fencing")
    throw std::invalid_argument("the scripted fencing policy plays fencing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_targets", "chest"),
             l.offset("piste", "to_my_end")};
  control_dt_ = match.control_dt;
  StepGains gains;
  gains.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  gains.max_speed = kMaxSpeed;
  legs_.emplace(gains, control_dt_);
  arm_ = ArmDirection(Arm::Right);
  phase_ = Phase::Approach;
  phase_s_ = 0;
}

void ScriptedFencingPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedFencingPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument(
        "the scripted fencing policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const Blocks& at = blocks_;
  const Eigen::Vector3d opponent = vec3(o, at.opponent);
  const Eigen::Vector3d chest = vec3(o, at.chest);
  const Eigen::Vector2d line = opponent.head<2>();
  const double distance = line.norm();
  const Eigen::Vector2d towards =
      distance > 1e-6 ? Eigen::Vector2d(line / distance) : Eigen::Vector2d(1, 0);

  phase_s_ += control_dt_;
  switch (phase_) {
    case Phase::Approach:
      if (distance < kOutOfReach_m + 0.15) phase_ = Phase::Attack, phase_s_ = 0;
      break;
    case Phase::Attack:
      if (phase_s_ > kAttack_s || distance < kLunge_m) phase_ = Phase::Recover, phase_s_ = 0;
      break;
    case Phase::Recover:
      if (phase_s_ > kRecover_s) phase_ = Phase::Approach, phase_s_ = 0;
      break;
  }
  double keep = phase_ == Phase::Attack ? kLunge_m - 0.3 : kOutOfReach_m;
  const double to_my_end = o[at.to_my_end];
  if (phase_ != Phase::Attack && to_my_end < 1.5) keep = std::min(keep, distance);  // no room
  const Eigen::Vector2d walk_to = line - towards * keep;
  legs_->act(o, walk_to, std::atan2(line.y(), line.x()), a);

  // The épée on the line from the shoulder to the chest, arm straight.
  point_arm(o, a, Arm::Right,
            arm_.follow(chest - body_position(o, kRShoulder), kArmRate, control_dt_));
  bend_elbow(a, Arm::Right, 0);
}

std::unique_ptr<Policy> make_scripted_fencing() {
  return std::make_unique<ScriptedFencingPolicy>();
}

}  // namespace olympics::client
