#include "scripted_boxing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "arm_control.h"
#include "control/body_model.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// Tuned on seeds 1-40 (docs/combat-sports.md; the figures are on other seeds). A boxer that
// steps while it punches falls: the stepping controller never stands still next to a moving
// opponent, and an arm thrown from a foot in the air tips it over (about 8 falls a minute). So
// the boxer walks into range, plants both feet, and punches only while planted.
constexpr double kRange_m = 0.85;        // root to root while punching
constexpr double kInRange_m = 1.1;       // punches start this close
constexpr double kMaxSpeed = 0.3;        // m/s of the approach (faster carries it into the other)
constexpr double kGapShare = 0.5;        // each boxer closes half the gap: both move
constexpr double kPlantWithin_m = 0.15;  // plants when this near its range...
constexpr double kPlantFacing = 0.25;    // ...facing the opponent within this (rad)...
constexpr double kPlantSpeed = 0.3;      // ...and moving slower than this (m/s)
// ...and not moving back with the centre of mass at the heels. The plant's ankles hold the centre
// of mass over the middle of the ankles, 6 cm in front of the heels' edge, and cannot stop a body
// already moving back: a boxer planted backing off at 0.2-0.3 m/s tipped over backward within a
// second, no one touching it (traced on seeds 1-80: 12 of main's 50 falls). So it plants only
// when its capture point (the centre of mass plus its velocity times sqrt(height / g), where it
// would come to rest) is no more than 2 cm behind the ankles and it backs off slower than 5 cm/s.
constexpr double kPlantCaptureBehind_m = 0.02;
constexpr double kPlantBackSpeed = 0.05;
constexpr double kReplantBeyond_m = 0.3;  // planted, it steps again when this far off its range
constexpr double kReplantFacing = 0.6;    // or the opponent this far to the side (rad)
// ...or it moves faster than this (m/s): pushed, a planted boxer steps at once to catch itself
// (with the feet placed about the centre of mass, seeds 1-20: stepping off only 0.3 m off its
// range, it was already moving 0.7 m/s, tipping, and fell within a second in 28 of 33).
constexpr double kReplantSpeed = 0.35;
// The feet are placed halfway between the root and the centre of mass, which the guard holds
// 4 cm ahead: placed about the root, the boxer drifted forward into the other and circled it;
// about the centre of mass, it faced, planted and punched much more, but fell 6 times a minute.
constexpr double kCentreOfMassPlacement = 0.5;
constexpr double kPlantedLeg_m = 0.74;  // hip to ankle planted: knees bent, centre of mass low
// Stepping, the stance leg is held as straight as the leg solver allows, 0.773 m hip to ankle
// (the stepping controller's default 0.77; the SMPL leg gives another 2 cm under the body's
// weight, docs/control.md): a boxer jolted off its plant catches itself on it. Jolted planted at
// 0.4-0.6 m/s (tests/sports/catch_step_test.cpp, 90 runs) it fell in 14, against 17 at 0.77 m;
// the more bent, the more falls (0.76: 21, 0.74: 28; in bouts at 0.74, ten times as many).
// Tuning seeds 1-60: 0.298 -> 0.213 falls a minute, scoring punches 14 -> 13
// (docs/combat-sports.md, fourteenth round).
constexpr double kSteppingLeg_m = 0.773;
constexpr double kUpright = 2.0;                // hip correction per radian of pelvis tilt
constexpr double kAnkleP = 3.0, kAnkleD = 2.0;  // ankle per m of centre of mass off, per m/s
constexpr double kGuardElbow = 1.8;             // rad
constexpr double kGuardForward = 0.6;           // the guard's upper arm: forward, out and down
constexpr double kPunchEvery_s = 0.6;           // a punch, then the other hand
constexpr double kPunchFor_s = 0.25;            // the arm out, then back to the guard
// The punch goes to the chest, under the other's guard gloves (at the head, most punches met a
// glove first), with the trunk leaning forward and turning the punching shoulder forward while
// the arm is out: from where the guards do not touch, a straight arm alone falls short. A punch
// whose target is beyond reach even so is not thrown (the arm stays in guard).
constexpr double kPunchLean = 0.4;     // rad, the trunk pitched forward
constexpr double kPunchTurn = 0.4;     // rad, the trunk turned about the spine
constexpr double kPunchReach_m = 0.9;  // shoulder to the chest's centre, at most

void guard_arm(std::span<const float> o, std::span<float> a, Arm arm) {
  const double side = arm == Arm::Right ? -1 : 1;
  point_arm(o, a, arm, {kGuardForward, 0.45 * side, -0.7},
            arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
  bend_elbow(a, arm, kGuardElbow);
}

// The torso, spine and chest, a third each: pitched forward by `lean` and turned by `turn`
// (left positive) from upright.
void bend_trunk(std::span<float> a, double lean, double turn) {
  for (int joint : {int(kTorso), kTorso + 1, int(kChest)}) {
    set_joint(a, joint, 1, joint_angle(a, joint, 1) + lean / 3);
    set_joint(a, joint, 2, joint_angle(a, joint, 2) + turn / 3);
  }
}

void punch(std::span<const float> o, std::span<float> a, Arm arm, const Eigen::Vector3d& at) {
  const int shoulder = arm == Arm::Right ? kRShoulder : kLShoulder;
  point_arm(o, a, arm, at - body_position(o, shoulder), arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
  bend_elbow(a, arm, 0.05);
}

bool feet_down(std::span<const float> o) {
  const double floor = -root_height(o);
  return body_position(o, kLAnkle).z() < floor + 0.1 && body_position(o, kRAnkle).z() < floor + 0.1;
}

// Would both feet planted where they stand hold this body? It is not moving back (`towards`: the
// opponent's direction) and its capture point (`com`: the centre of mass, heading frame from the
// root) is not behind the ankles.
bool plant_would_hold(std::span<const float> o, const Eigen::Vector3d& com,
                      const Eigen::Vector2d& towards) {
  const Eigen::Vector3d v = root_velocity(o);
  const double ankles_x = 0.5 * (body_position(o, kLAnkle).x() + body_position(o, kRAnkle).x());
  const double capture_x = com.x() + v.x() * pendulum_time_s(o);
  return capture_x - ankles_x > -kPlantCaptureBehind_m &&
         v.head<2>().dot(towards) > -kPlantBackSpeed;
}

// Both feet planted where they stand, knees bent, each leg's hip drive holding the pelvis upright
// over its foot (the stepping controller's stance leg, twice), and the ankles balancing the
// centre of mass (`com`, heading frame from the root) over the middle of the feet.
void plant(std::span<const float> o, std::span<float> a, const Eigen::Vector3d& com) {
  const Eigen::Vector3d up = body_rotation(o, kPelvis).col(2);
  for (int hip : {kLHip, kRHip}) {
    Eigen::Vector3d r = body_position(o, hip + 2) - body_position(o, hip);
    const double leg_sq = kPlantedLeg_m * kPlantedLeg_m;
    r.z() = -std::sqrt(leg_sq - std::min(r.head<2>().squaredNorm(), 0.8 * leg_sq));
    write_leg_toward(a, hip, r);
    set_joint(a, hip, 0, joint_angle(a, hip, 0) - kUpright * up.y());
    set_joint(a, hip, 1, joint_angle(a, hip, 1) + kUpright * up.x());
    write_flat_foot(o, a, hip + 1);
  }
  const Eigen::Vector3d mid = 0.5 * (body_position(o, kLAnkle) + body_position(o, kRAnkle));
  const Eigen::Vector3d v = root_velocity(o);
  const double dx = com.x() - mid.x(), dy = com.y() - mid.y();
  for (int ankle : {kLAnkle, kRAnkle}) {
    set_joint(a, ankle, 1, joint_angle(a, ankle, 1) + kAnkleP * dx + kAnkleD * v.x());
    set_joint(a, ankle, 0, joint_angle(a, ankle, 0) - (kAnkleP * dy + kAnkleD * v.y()));
  }
}

const control::BodyModel& smpl_model() {
  static const control::BodyModel model = control::BodyModel::humanoid(core::HumanoidKind::Smpl);
  return model;
}

}  // namespace

StepGains boxing_step_gains() {
  StepGains g;
  g.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  g.max_speed = kMaxSpeed;
  g.balance = {2.0, 2.0, 0.0, 2.0};  // standing in the rest, gloves up
  g.centre_of_mass_placement = kCentreOfMassPlacement;
  g.leg_length = kSteppingLeg_m;
  return g;
}

void hold_guard(std::span<const float> o, std::span<float> a) {
  guard_arm(o, a, Arm::Left);
  guard_arm(o, a, Arm::Right);
}

void ScriptedBoxingPolicy::start(const MatchInfo& match) {
  if (match.sport != "boxing")
    throw std::invalid_argument("the scripted boxing policy plays boxing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_targets", "chest"),
             l.offset("bout", "resting")};
  start_alone(match.control_dt);
}

void ScriptedBoxingPolicy::start_alone(double control_dt) {
  control_dt_ = control_dt;
  legs_.emplace(gains_, control_dt_);
  clock_s_ = 0;
  planted_ = was_resting_ = false;
}

void ScriptedBoxingPolicy::act(std::span<const float> o, std::span<float> a) {
  const Blocks& at = blocks_;
  act_against(o, {vec3(o, at.opponent), vec3(o, at.chest), o[at.resting] > 0.5}, a);
}

void ScriptedBoxingPolicy::act_against(std::span<const float> o, const Bout& bout,
                                       std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedBoxingPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted boxing policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const bool resting = bout.resting;
  const Eigen::Vector3d& opponent = bout.opponent;
  const Eigen::Vector2d line = opponent.head<2>();
  const double distance = line.norm();
  const Eigen::Vector2d towards =
      distance > 1e-6 ? Eigen::Vector2d(line / distance) : Eigen::Vector2d(1, 0);
  const double bearing = std::atan2(line.y(), line.x());
  const double off = distance - kRange_m;

  if (resting != was_resting_) {  // the bell: both boxers were put back in their corners
    planted_ = false;
    legs_.emplace(gains_, control_dt_);
    was_resting_ = resting;
  }
  const Eigen::Vector3d com = smpl_model().centre_of_mass(smpl_model().pose_from_observation(o));
  if (resting) {
  } else if (planted_) {
    if (std::abs(off) > kReplantBeyond_m || std::abs(bearing) > kReplantFacing ||
        root_velocity(o).head<2>().norm() > kReplantSpeed) {
      planted_ = false;
      legs_.emplace(gains_, control_dt_);  // a fresh step from both feet down
    }
  } else if (std::abs(off) < kPlantWithin_m && std::abs(bearing) < kPlantFacing && feet_down(o) &&
             root_velocity(o).head<2>().norm() < kPlantSpeed && plant_would_hold(o, com, towards)) {
    planted_ = true;
  }
  // Stepping, it stands balancing its centre of mass (not its root) and steps to catch itself
  // when that moves off the feet or the body moves fast (StepGains::recover_m, recover_speed).
  if (planted_) {
    plant(o, a, com);
  } else {
    legs_->balance_centre_of_mass(com, 0);
    legs_->set_centre_of_mass(com);  // the feet placed about it (kCentreOfMassPlacement)
    if (resting)
      legs_->act(o, Eigen::Vector2d::Zero(), 0, a);
    else
      legs_->act(o, towards * off * kGapShare, bearing, a);
  }

  hold_guard(o, a);
  if (resting || !planted_ || distance > kInRange_m) {
    clock_s_ = 0;
    return;
  }
  clock_s_ += control_dt_;
  const double into = std::fmod(clock_s_, kPunchEvery_s);
  const int n = static_cast<int>(clock_s_ / kPunchEvery_s);
  if (into > kPunchFor_s) return;
  const Arm arm = n % 2 == 0 ? Arm::Left : Arm::Right;
  const Eigen::Vector3d& target = bout.chest;
  const Eigen::Vector3d shoulder = body_position(o, arm == Arm::Right ? kRShoulder : kLShoulder);
  if ((target - shoulder).norm() > kPunchReach_m) return;
  bend_trunk(a, kPunchLean, arm == Arm::Right ? kPunchTurn : -kPunchTurn);  // shoulder forward
  punch(o, a, arm, target);
}

std::unique_ptr<Policy> make_scripted_boxing() { return std::make_unique<ScriptedBoxingPolicy>(); }

}  // namespace olympics::client
