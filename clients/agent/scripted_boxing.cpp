#include "scripted_boxing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "arm_control.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// Found by a grid search over 6 bouts of 30 s each (scoring punches, falls): speed 0.4-1.0,
// range 0.7-0.9, guard reach 0.4-0.6; the guard's gloves in front ask for stiffer standing balance
// (alone, standing in guard, the default gains let it fall forward within 3 s).
constexpr double kRange_m = 0.8;       // root to root while punching
constexpr double kInRange_m = 1.1;     // punches start this close
constexpr double kMaxSpeed = 0.7;      // m/s of the approach (faster carries it into the other)
constexpr double kGuardElbow = 1.8;    // rad
constexpr double kGuardForward = 0.6;  // the guard's upper arm: forward, out and down
constexpr double kPunchEvery_s = 0.6;  // a punch, then the other hand
constexpr double kPunchFor_s = 0.25;   // the arm out, then back to the guard
// In and out (tuned on seeds 1-12, docs/combat-sports.md): close range is where two boxers
// collide and fall, and a boxer down never gets up, so each stays out of reach between
// combinations and steps in only to throw one.
constexpr double kInFor_s = 1.2;   // in range for a combination
constexpr double kOutFor_s = 1.5;  // then out of reach
constexpr double kOut_m = 1.5;     // root to root out of reach

void guard(std::span<const float> o, std::span<float> a, Arm arm) {
  const double side = arm == Arm::Right ? -1 : 1;
  point_arm(o, a, arm, {kGuardForward, 0.45 * side, -0.7},
            arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
  bend_elbow(a, arm, kGuardElbow);
}

void punch(std::span<const float> o, std::span<float> a, Arm arm, const Eigen::Vector3d& at) {
  const int shoulder = arm == Arm::Right ? kRShoulder : kLShoulder;
  point_arm(o, a, arm, at - body_position(o, shoulder), arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
  bend_elbow(a, arm, 0.05);
}

}  // namespace

void ScriptedBoxingPolicy::start(const MatchInfo& match) {
  if (match.sport != "boxing")
    throw std::invalid_argument("the scripted boxing policy plays boxing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_targets", "chest"),
             l.offset("opponent_targets", "head"), l.offset("bout", "resting")};
  control_dt_ = match.control_dt;
  StepGains gains;
  gains.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  gains.max_speed = kMaxSpeed;
  gains.balance = {2.0, 2.0, 0.0, 2.0};
  legs_.emplace(gains, control_dt_);
  clock_s_ = cycle_s_ = 0;
}

void ScriptedBoxingPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedBoxingPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted boxing policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const Blocks& at = blocks_;
  const bool resting = o[at.resting] > 0.5;
  const Eigen::Vector3d opponent = vec3(o, at.opponent);
  const Eigen::Vector2d line = opponent.head<2>();
  const double distance = line.norm();
  const Eigen::Vector2d towards =
      distance > 1e-6 ? Eigen::Vector2d(line / distance) : Eigen::Vector2d(1, 0);
  const double bearing = std::atan2(line.y(), line.x());

  if (resting) {
    legs_->act(o, Eigen::Vector2d::Zero(), 0, a);
  } else {
    cycle_s_ += control_dt_;
    if (cycle_s_ > kInFor_s + kOutFor_s) cycle_s_ = 0;
    const double range = cycle_s_ < kInFor_s ? kRange_m : kOut_m;
    legs_->act(o, line - towards * range, bearing, a);
  }
  guard(o, a, Arm::Left);
  guard(o, a, Arm::Right);
  if (resting || distance > kInRange_m) {
    clock_s_ = 0;
    return;
  }
  clock_s_ += control_dt_;
  const double into = std::fmod(clock_s_, kPunchEvery_s);
  const int n = static_cast<int>(clock_s_ / kPunchEvery_s);
  if (into > kPunchFor_s) return;
  const Arm arm = n % 2 == 0 ? Arm::Left : Arm::Right;
  const Eigen::Vector3d target = vec3(o, n % 4 < 2 ? at.head : at.chest);
  punch(o, a, arm, target);
}

std::unique_ptr<Policy> make_scripted_boxing() { return std::make_unique<ScriptedBoxingPolicy>(); }

}  // namespace olympics::client
