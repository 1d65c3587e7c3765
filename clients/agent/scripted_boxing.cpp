#include "scripted_boxing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "arm_control.h"
#include "scripted_boxing_punch.h"
#include "control/body_model.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

double tune_env(const char* name, double fallback) {  // TEMPORARY tuning hook
  const char* v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}
const double kIkPunch = tune_env("kIkPunch", 1);
const double kDamp = tune_env("kDamp", 0);
const double kFoot = tune_env("kFoot", 0);
const double kBalanceCom = tune_env("kBalanceCom", 1);
const double kHoldBand_m = tune_env("kHoldBand_m", 0.15);
const double kBackWithin_m = tune_env("kBackWithin_m", 0.3);
const double kClinchBelow_m = tune_env("kClinchBelow_m", 0);
const double kChamber = tune_env("kChamber", 0);
const double kChamberForward = tune_env("kChamberForward", 0.1);
const double kTrunk = tune_env("kTrunk", 0);
const double kTrigger = tune_env("kTrigger", 0);
const double kTriggerFacing = tune_env("kTriggerFacing", 0.3);
const double kNeverUnplant = tune_env("kNeverUnplant", 0);
const double kNeedPlant = tune_env("kNeedPlant", 1);
const double kHoldTurn = tune_env("kHoldTurn", 0.4);
const double kHoldStepPunch = tune_env("kHoldStepPunch", 0);
const double kHoldFor_s = tune_env("kHoldFor_s", 1.0);
const double kStillSpeed = tune_env("kStillSpeed", 0.2);
const double kHeadShare = tune_env("kHeadShare", 0.5);

// Tuned on seeds 1-40 (docs/combat-sports.md; the figures are on other seeds). A boxer that
// steps while it punches falls: the stepping controller never stands still next to a moving
// opponent, and an arm thrown from a foot in the air tips it over (about 8 falls a minute). So
// the boxer walks into range, plants both feet, and punches only while planted.
const double kRange_m = tune_env("kRange_m", 0.85);         // root to root while punching
const double kInRange_m = tune_env("kInRange_m", 1.1);        // punches start this close
const double kMaxSpeed = tune_env("kMaxSpeed", 0.3);         // m/s of the approach (faster carries it into the other)
const double kGapShare = tune_env("kGapShare", 0.5);         // each boxer closes half the gap: both move
const double kPlantWithin_m = tune_env("kPlantWithin_m", 0.15);   // plants when this near its range...
const double kPlantFacing = tune_env("kPlantFacing", 0.25);     // ...facing the opponent within this (rad)...
const double kPlantSpeed = tune_env("kPlantSpeed", 0.3);       // ...and moving slower than this (m/s)
const double kReplantBeyond_m = tune_env("kReplantBeyond_m", 0.3);  // planted, it steps again when this far off its range
const double kReplantFacing = tune_env("kReplantFacing", 0.6);    // or the opponent this far to the side (rad)
constexpr double kPlantedLeg_m = 0.74;    // hip to ankle planted: knees bent, centre of mass low
constexpr double kUpright = 2.0;          // hip correction per radian of pelvis tilt
constexpr double kAnkleP = 1.0, kAnkleD = 1.0;  // ankle per m of centre of mass off, per m/s
constexpr double kGuardElbow = 1.8;             // rad
constexpr double kGuardForward = 0.6;           // the guard's upper arm: forward, out and down
const double kPunchEvery_s = tune_env("kPunchEvery_s", 0.6);           // a punch, then the other hand
const double kPunchFor_s = tune_env("kPunchFor_s", 0.25);            // the arm out, then back to the guard
const double kThrough_m = tune_env("kThrough_m", 0.1);              // the glove aimed this far beyond the target

void guard(std::span<const float> o, std::span<float> a, Arm arm,
           double forward = kGuardForward, double elbow = kGuardElbow) {
  const double side = arm == Arm::Right ? -1 : 1;
  point_arm(o, a, arm, {forward, 0.45 * side, -0.7},
            arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
  bend_elbow(a, arm, elbow);
}

bool feet_down(std::span<const float> o) {
  const double floor = -root_height(o);
  return body_position(o, kLAnkle).z() < floor + 0.1 && body_position(o, kRAnkle).z() < floor + 0.1;
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

void ScriptedBoxingPolicy::start(const MatchInfo& match) {
  if (match.sport != "boxing")
    throw std::invalid_argument("the scripted boxing policy plays boxing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_targets", "chest"),
             l.offset("opponent_targets", "head"), l.offset("bout", "resting")};
  control_dt_ = match.control_dt;
  gains_ = StepGains();
  gains_.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  gains_.max_speed = kMaxSpeed;
  gains_.velocity_gain = tune_env("kVelGain", gains_.velocity_gain);
  gains_.lead_s = tune_env("kLead", gains_.lead_s);
  gains_.balance = {2.0, 2.0, 0.0, 2.0};  // standing in the rest, gloves up
  legs_.emplace(gains_, control_dt_);
  clock_s_ = 0;
  planted_ = was_resting_ = false;
  if (!punch_) punch_ = std::make_unique<BoxingPunch>(kTrunk > 0.5);
  punch_->reset();
}

void ScriptedBoxingPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedBoxingPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument("the scripted boxing policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  now += control_dt_;
  const Blocks& at = blocks_;
  const bool resting = o[at.resting] > 0.5;
  const Eigen::Vector3d opponent = vec3(o, at.opponent);
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
  bool may_punch = planted_;
  if (kFoot > 0.5) {  // hold: the stepping controller stands (turning in place), never plants
    const Eigen::Vector3d com = smpl_model().centre_of_mass(smpl_model().pose_from_observation(o));
    if (kBalanceCom > 0.5) legs_->balance_centre_of_mass(com, 0.03);
    if (resting) planted_ = false;
    else if (planted_ && (off > kHoldBand_m + 0.2 || off < -kBackWithin_m)) planted_ = false;
    else if (!planted_ && std::abs(off) < kHoldBand_m) planted_ = true;
    if (!planted_ || resting) set_ = false;
    else if (kFoot > 1.5 && !set_ && feet_down(o) && root_velocity(o).head<2>().norm() < kPlantSpeed &&
             std::abs(bearing) < kPlantFacing)
      set_ = true;
    else if (set_ && std::abs(bearing) > kReplantFacing) {
      set_ = false;
      legs_.emplace(gains_, control_dt_);
    }
    if (resting) legs_->act(o, Eigen::Vector2d::Zero(), 0, a);
    else if (set_) plant(o, a, com);
    else if (planted_) legs_->act(o, Eigen::Vector2d::Zero(), std::abs(bearing) > kHoldTurn ? bearing : 0.0, a);
    else legs_->act(o, towards * off * kGapShare, bearing, a);
    hold_s_ = planted_ ? hold_s_ + control_dt_ : 0;
    const double closing = (vec3(o, at.opponent + 3) - root_velocity(o)).head<2>().norm();
    may_punch = planted_ && (kHoldStepPunch > 0.5 || set_ || !legs_->stepping()) && hold_s_ > kHoldFor_s &&
                root_velocity(o).head<2>().norm() < kStillSpeed && closing < kStillSpeed;
  } else {
  if (resting) {
  } else if (planted_) {
    if (kNeverUnplant < 0.5 && (std::abs(off) > kReplantBeyond_m || std::abs(bearing) > kReplantFacing)) {
      planted_ = false;
      legs_.emplace(gains_, control_dt_);  // a fresh step from both feet down
    }
  } else if (std::abs(off) < kPlantWithin_m && std::abs(bearing) < kPlantFacing && feet_down(o) &&
             root_velocity(o).head<2>().norm() < kPlantSpeed) {
    planted_ = true;
  }
  if (planted_)
    plant(o, a, smpl_model().centre_of_mass(smpl_model().pose_from_observation(o)));
  else if (resting)
    legs_->act(o, Eigen::Vector2d::Zero(), 0, a);
  else
  {
    const Eigen::Vector3d opp_v = vec3(o, at.opponent + 3);
    const double opening = (opp_v - root_velocity(o)).head<2>().dot(towards);  // d distance / dt
    legs_->act(o, towards * (off + kDamp * opening) * kGapShare, bearing, a);
  }

  }
  guard(o, a, Arm::Left);
  guard(o, a, Arm::Right);
  if (kTrigger > 0.5) {  // a punch starts only from both feet down, facing, in range
    clock_s_ += control_dt_;
    if (punching_ && clock_s_ > kPunchFor_s) punching_ = false, clock_s_ = 0, ++count_;
    if (!punching_) {
      const bool ready = !resting && (kFoot > 0.5 ? may_punch : (planted_ || kNeedPlant < 0.5)) && distance < kInRange_m && std::abs(bearing) < kTriggerFacing &&
                         feet_down(o) && clock_s_ > kPunchEvery_s - kPunchFor_s;
      if (kChamber > 0.5) guard(o, a, count_ % 2 == 0 ? Arm::Left : Arm::Right, kChamberForward, 2.3);
      if (!ready || no_punch) return;
      punching_ = true, clock_s_ = 0, ++thrown, last_throw = now;
    }
  }
  if (kTrigger < 0.5) {
  if (!resting && distance < kClinchBelow_m) may_punch = true;
  if (resting || !may_punch || distance > kInRange_m) {
    clock_s_ = 0;
    return;
  }
  clock_s_ += control_dt_;
  const double into = std::fmod(clock_s_, kPunchEvery_s);
  count_ = static_cast<int>(clock_s_ / kPunchEvery_s);
  if (into > kPunchFor_s) {
    if (kChamber > 0.5) guard(o, a, (count_ + 1) % 2 == 0 ? Arm::Left : Arm::Right, kChamberForward, 2.3);
    return;
  }
  if (no_punch) return;
  if (into < control_dt_ * 0.99) ++thrown, last_throw = now;
  }
  const int n = count_;
  const Arm arm = n % 2 == 0 ? Arm::Left : Arm::Right;
  const Eigen::Vector3d target = vec3(o, (n % 4) < 4 * kHeadShare ? at.head : at.chest);
  if (kIkPunch > 0.5) {
    punch_->throw_at(o, a, arm, target, kThrough_m);
  } else {
    const int shoulder = arm == Arm::Right ? kRShoulder : kLShoulder;
    point_arm(o, a, arm, target - body_position(o, shoulder),
              arm == Arm::Right ? M_PI / 2 : -M_PI / 2);
    bend_elbow(a, arm, 0.05);
  }
}

std::unique_ptr<Policy> make_scripted_boxing() { return std::make_unique<ScriptedBoxingPolicy>(); }

}  // namespace olympics::client
