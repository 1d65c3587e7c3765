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
constexpr double kRecover_s = 0.8;
constexpr double kArmRate = 2.0;  // rad/s the épée arm turns at (faster spins the body)
// Walking speed (m/s). Most falls came as both fencers rushed in at the stepping controller's
// 1.2 m/s and collided or stopped short; at 0.7 they fell about 20 times less often on seeds
// 1-40 (the tuning seeds; 0.6-0.8 were alike, 0.9 fell five times as often).
constexpr double kMaxSpeed = 0.7;

// EXPERIMENT, NOT KEPT (docs/combat-sports.md, issue 30 third round): it falls 0.62 times a
// minute on the tuning seeds 1-40, against 0.18 for the fencer without a lunge.
// The lunge (front = right foot, the sword side; back = left). Launched as the front foot lifts
// in a step, the back foot down, from this far root to root:
constexpr double kLaunch_m = 1.65;
constexpr double kBackFootBehind_m = 0.05;  // the back ankle at most this far ahead of the hips
constexpr double kCloseTo_m = 1.0;          // closing, it walks toward this distance
constexpr double kGuardElbow = 0.3;         // rad: the arm half bent in guard, extended first
const double kExtend_m = kLaunch_m + 0.2;   // the arm straightens before the foot leaves
constexpr double kLifted_m = 0.1;           // the front ankle this high: its step becomes the lunge
constexpr double kStride_s = 0.15;          // the front foot's flight
constexpr double kStride_m = 0.35;          // how far the front foot lands ahead of where it was
constexpr double kStrideLift_m = 0.05;
constexpr double kHold_s = 0.2;            // landed: the tip arrives or the lunge is short
constexpr double kBackLeg_m = 0.70;        // the back leg extends (hip to ankle)
constexpr double kFrontLegLanded_m = 0.7;  // the front knee bends over the landed foot
constexpr double kUpright = 3.0;           // hip correction per radian of pelvis tilt
constexpr double kAnkleHeight = 0.07;
constexpr double kGuardLeg_m = 0.75;
constexpr double kMidClamp = 0.3;      // m: at most this far sideways
constexpr double kBackToMiddle = 0.5;  // sideways target per metre off the piste's middle
constexpr double kLaunchSpeed = 0.7;   // m/s: no lunge out of a faster step
constexpr double kGuard_s = 0.5;       // in guard out of reach at least this long
constexpr double kClose_s = 1.5;       // closing to the launch distance at most this long

// A leg whose ankle stays where it is, `length` from its hip (heading frame), its hip drive
// righting the pelvis over the foot, the foot flat: the stepping controller's stance leg.
void stand_on(std::span<const float> o, std::span<float> a, int hip, double length) {
  Eigen::Vector3d r = body_position(o, hip + 2) - body_position(o, hip);
  r.z() = -std::sqrt(length * length - std::min(r.head<2>().squaredNorm(), 0.8 * length * length));
  write_leg_toward(a, hip, r);
  const Eigen::Vector3d up = body_rotation(o, kPelvis).col(2);
  set_joint(a, hip, 0, joint_angle(a, hip, 0) - kUpright * up.y());
  set_joint(a, hip, 1, joint_angle(a, hip, 1) + kUpright * up.x());
  write_flat_foot(o, a, hip + 1);
}

// A leg in flight from `from` to `to` (ankle positions, heading frame from the root) at share
// `s` of its flight, lifted in between; solved in the pelvis frame like the stepping swing leg.
void swing(std::span<const float> o, std::span<float> a, int hip, const Eigen::Vector3d& from,
           const Eigen::Vector3d& to, double s) {
  const double b = std::clamp(1.5 * s, 0.0, 1.0);
  Eigen::Vector3d ankle = from + (to - from) * (b * b * (3 - 2 * b));
  ankle.z() = -root_height(o) + kAnkleHeight + kStrideLift_m * std::sin(M_PI * s);
  const Eigen::Matrix3d pelvis = body_rotation(o, kPelvis);
  write_leg_toward(a, hip, pelvis.transpose() * (ankle - body_position(o, hip)));
  write_flat_foot(o, a, hip + 1);
}

}  // namespace

void ScriptedFencingPolicy::start(const MatchInfo& match) {
  if (match.sport != "fencing")
    throw std::invalid_argument("the scripted fencing policy plays fencing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_targets", "chest"),
             l.offset("piste", "to_my_end"), l.offset("piste", "across")};
  control_dt_ = match.control_dt;
  gains_ = StepGains();
  gains_.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  gains_.max_speed = kMaxSpeed;
  legs_.emplace(gains_, control_dt_);
  arm_ = ArmDirection(Arm::Right);
  phase_ = Phase::Guard;
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
  const double turn = std::atan2(line.y(), line.x());
  if (phase_ == Phase::Lunge && distance > kOutOfReach_m + 1)
    enter(Phase::Guard);  // a halt put both back on their en-garde lines
  const double floor = -root_height(o);
  switch (phase_) {
    case Phase::Guard:
      if (distance < kOutOfReach_m + 0.15 && phase_s_ > kGuard_s) enter(Phase::Close);
      break;
    case Phase::Close:
      // The lunge takes over a step of the front foot as it leaves the ground, the back foot
      // down: lifting a loaded foot drags it instead.
      if (distance < kLaunch_m && body_position(o, kRAnkle).z() > floor + kLifted_m &&
          body_position(o, kLAnkle).x() < kBackFootBehind_m &&
          body_position(o, kLAnkle).z() < floor + 0.1 &&
          root_velocity(o).head<2>().norm() < kLaunchSpeed) {
        enter(Phase::Lunge);
        front_from_back_ = body_position(o, kRAnkle) - body_position(o, kLAnkle);
      } else if (phase_s_ > kClose_s) {
        enter(Phase::Recover);
      }
      break;
    case Phase::Lunge:
      if (phase_s_ > kStride_s + kHold_s) enter(Phase::Recover);
      break;
    case Phase::Recover:
      if (phase_s_ > kRecover_s) enter(Phase::Guard);
      break;
  }

  if (phase_ == Phase::Lunge) {
    const Eigen::Vector3d back = body_position(o, kLAnkle);
    if (phase_s_ < kStride_s) {
      swing(o, a, kRHip, back + front_from_back_,
            back + Eigen::Vector3d(kStride_m, front_from_back_.y(), 0), phase_s_ / kStride_s);
    } else {
      stand_on(o, a, kRHip, kFrontLegLanded_m);
    }
    stand_on(o, a, kLHip, kBackLeg_m);
  } else {
    double keep = kOutOfReach_m;
    if (phase_ == Phase::Close) keep = kCloseTo_m;
    const double to_my_end = o[at.to_my_end];
    if (phase_ != Phase::Close && to_my_end < 1.5) keep = std::min(keep, distance);  // no room
    // Circling each other drifts them off the piste's side: lean the way back to its middle.
    Eigen::Vector2d walk_to = line - towards * keep;
    walk_to.y() -= std::clamp(kBackToMiddle * o[at.across], -kMidClamp, kMidClamp);
    legs_->act(o, walk_to, turn, a);
  }

  // The épée on the line from the shoulder to the chest; the arm half bent in guard, extended
  // first in the lunge.
  point_arm(o, a, Arm::Right,
            arm_.follow(chest - body_position(o, kRShoulder), kArmRate, control_dt_));
  const bool extend = phase_ == Phase::Lunge || (phase_ == Phase::Close && distance < kExtend_m);
  bend_elbow(a, Arm::Right, extend ? 0 : kGuardElbow);
}

void ScriptedFencingPolicy::enter(Phase phase) {
  // The stepping controller takes the legs back standing, from a fresh start.
  if (phase_ == Phase::Lunge) legs_.emplace(gains_, control_dt_);
  phase_ = phase;
  phase_s_ = 0;
}

std::unique_ptr<Policy> make_scripted_fencing() {
  return std::make_unique<ScriptedFencingPolicy>();
}

}  // namespace olympics::client
