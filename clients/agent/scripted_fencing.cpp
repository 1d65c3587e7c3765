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
using Stage = control::GuardFootwork::Stage;

constexpr double kGuardFar_m = 2.3;    // root to root: further than this, advance
constexpr double kGuardNear_m = 1.9;   // nearer than this (not attacking), retreat
constexpr double kTooClose_m = 1.35;   // attacking, nearer than this without a lunge: get out
constexpr double kLaunchGap_m = 0.45;  // the tip this far short of the chest: lunge
constexpr double kWait_s = 0.6;        // at guard distance this long, then attack
constexpr double kClosing = 0.3;       // m/s: the opponent closing faster than this, retreat
constexpr double kNoRoom_m = 1.0;      // nearer my end than this, no retreat
constexpr double kArmRate = 2.0;       // rad/s the épée arm turns at (faster spins the body)
constexpr double kToMiddle = 0.3;      // m sideways per m off the piste's middle, per step
constexpr double kToMiddleMax = 0.08;

}  // namespace

void ScriptedFencingPolicy::start(const MatchInfo& match) {
  if (match.sport != "fencing")
    throw std::invalid_argument("the scripted fencing policy plays fencing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_root", "velocity"),
             l.offset("opponent_targets", "chest"), l.offset("tip", "position"),
             l.offset("piste", "across"),           l.offset("piste", "to_my_end")};
  control_dt_ = match.control_dt;
  legs_.emplace(control::GuardGains{}, control_dt_);
  arm_ = ArmDirection(Arm::Right);
  in_guard_s_ = 0;
  attacking_ = false;
  last_distance_ = 0;
}

bool ScriptedFencingPolicy::lunging() const {
  return legs_ && (legs_->stage() == Stage::Lunging || legs_->stage() == Stage::Lunged);
}

ScriptedFencingPolicy::Move ScriptedFencingPolicy::choose(std::span<const float> o) {
  const Blocks& at = blocks_;
  const Eigen::Vector3d opponent = vec3(o, at.opponent);
  const double distance = opponent.head<2>().norm();
  const Eigen::Vector2d towards = opponent.head<2>() / std::max(distance, 1e-6);
  // Positive: the opponent moves toward me.
  const double closing = -vec3(o, at.opponent_velocity).head<2>().dot(towards);
  const double gap = (vec3(o, at.chest) - vec3(o, at.tip)).head<2>().norm();
  const bool room = o[at.to_my_end] > kNoRoom_m;

  if (distance > 3.5) attacking_ = false, in_guard_s_ = 0;  // a halt: back on the lines
  if (legs_->out_of_guard(o)) return room ? Move::Retreat : Move::Advance;
  if (gap < kLaunchGap_m) {  // in reach: lunge (an attack's, or a stop hit)
    attacking_ = false, in_guard_s_ = 0;
    return Move::Lunge;
  }
  if (attacking_) {
    if (distance < kTooClose_m) {
      attacking_ = false, in_guard_s_ = 0;
      return room ? Move::Retreat : Move::Guard;
    }
    return Move::Advance;
  }
  if (closing > kClosing && distance < kGuardFar_m && room) return Move::Retreat;
  if (distance > kGuardFar_m) return Move::Advance;
  if (distance < kGuardNear_m && room) return Move::Retreat;
  in_guard_s_ += control_dt_;
  if (in_guard_s_ > kWait_s) attacking_ = true;
  return Move::Guard;
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

  // A halt puts both fencers back on their lines, standing: the footwork starts afresh.
  const double distance = opponent.head<2>().norm();
  if (std::abs(distance - last_distance_) > 0.3) legs_.emplace(control::GuardGains{}, control_dt_);
  last_distance_ = distance;
  const Move wanted = legs_->free() ? choose(o) : Move::Guard;
  const double side = -std::clamp(kToMiddle * o[at.across], -kToMiddleMax, kToMiddleMax);
  legs_->act(o, wanted, std::atan2(opponent.y(), opponent.x()), side, a);

  // The épée on the line from the shoulder to the chest, arm straight.
  point_arm(o, a, Arm::Right,
            arm_.follow(chest - body_position(o, kRShoulder), kArmRate, control_dt_));
  bend_elbow(a, Arm::Right, 0);
}

std::unique_ptr<Policy> make_scripted_fencing() {
  return std::make_unique<ScriptedFencingPolicy>();
}

}  // namespace olympics::client
