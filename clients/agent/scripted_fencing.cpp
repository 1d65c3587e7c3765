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

// The guard: at every step the right (sword-side) foot lands this far ahead of the left one, so
// the left is behind the hips when the right one leaves the ground. On the tuning seeds 1-40,
// 0.15-0.3 fell 2-25 times as often as 0.1 (docs/combat-sports.md, issue 30 fourth round).
constexpr double kStagger = 0.1;
// Distance keeping: the opponent coming in faster than this (m/s), it gives ground this much.
constexpr double kClosing = 0.3, kGiveGround_m = 0.5;
// The lunge: launched in the first 60% of a step of the front foot, once that foot is 4 cm up
// (unloaded), the back foot down behind the hips, with the tip less than 0.45 m short of the
// opponent's chest and no nearer than 1.45 m root to root (nearer, it runs into the opponent).
constexpr double kLaunchGap_m = 0.45, kMinLaunch_m = 1.45;
constexpr double kLaunchBy = 0.6, kLifted_m = 0.04;
// The front foot flies 0.3 m beyond its guard spot in 0.25 s, 12 cm up, while the back leg
// straightens (0.76 m hip to ankle) and drives the hip on; then the stepping controller takes
// the legs back at once, the back foot stepping first to catch the body. Holding the lunge
// 0.2 s on landing fell three to four times as often (tuning seeds 1-20).
constexpr double kStride_m = 0.3, kStride_s = 0.25, kStrideLift_m = 0.12;
constexpr double kBackLeg_m = 0.76, kBackPush_m = 0.05;
constexpr double kUpright = 3.0;  // hip correction per radian of pelvis tilt
constexpr double kAnkleHeight = 0.07;
constexpr double kWidth_m = 0.2;  // the front foot lands this far right of the back one
// A touch this soon after the lunge's landing still counts as the lunge's (the tip arrives
// after the foot).
constexpr double kLandedCredit_s = 0.3;
constexpr double kCatch_s = 0.4;  // out of a lunge, stepping in place before giving ground

// A leg whose ankle stays where it is, `length` from its hip (heading frame), its hip drive
// righting the pelvis over the foot, the foot flat: the stepping controller's stance leg.
void stand_on(std::span<const float> o, std::span<float> a, int hip, double length, double push) {
  Eigen::Vector3d r = body_position(o, hip + 2) - body_position(o, hip);
  r.x() -= push;
  r.z() = -std::sqrt(length * length - std::min(r.head<2>().squaredNorm(), 0.8 * length * length));
  write_leg_toward(a, hip, r);
  const Eigen::Vector3d up = body_rotation(o, kPelvis).col(2);
  set_joint(a, hip, 0, joint_angle(a, hip, 0) - kUpright * up.y());
  set_joint(a, hip, 1, joint_angle(a, hip, 1) + kUpright * up.x());
  write_flat_foot(o, a, hip + 1);
}

// A leg in flight from `from` to `to` (from the other ankle, heading frame) at share `s` of its
// flight, lifted in between; solved in the pelvis frame like the stepping swing leg.
void swing(std::span<const float> o, std::span<float> a, int hip, int other_hip,
           const Eigen::Vector2d& from, const Eigen::Vector2d& to, double s) {
  const double b = std::clamp(1.5 * s, 0.0, 1.0);
  const Eigen::Vector2d along =
      body_position(o, other_hip + 2).head<2>() + from + (to - from) * (b * b * (3 - 2 * b));
  const Eigen::Vector3d ankle(along.x(), along.y(),
                              -root_height(o) + kAnkleHeight + kStrideLift_m * std::sin(M_PI * s));
  const Eigen::Matrix3d pelvis = body_rotation(o, kPelvis);
  write_leg_toward(a, hip, pelvis.transpose() * (ankle - body_position(o, hip)));
  write_flat_foot(o, a, hip + 1);
}

}  // namespace

void ScriptedFencingPolicy::start(const MatchInfo& match) {
  if (match.sport != "fencing")
    throw std::invalid_argument("the scripted fencing policy plays fencing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root", "position"), l.offset("opponent_root", "velocity"),
             l.offset("opponent_targets", "chest"), l.offset("tip", "position"),
             l.offset("piste", "to_my_end")};
  control_dt_ = match.control_dt;
  StepGains gains;
  gains.turn_start = 0.3;  // keep facing the opponent, stepping in place if need be
  gains.max_speed = kMaxSpeed;
  gains.stagger = kStagger;
  gains_ = gains;
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
  if (phase_ == Phase::Lunge && distance > kOutOfReach_m + 1)
    enter(o, Phase::Approach);  // a halt put both back on their lines
  const double gap = (chest - vec3(o, at.tip)).head<2>().norm();
  // Positive: the opponent comes toward me.
  const double closing = -vec3(o, at.opponent_velocity).head<2>().dot(towards);
  switch (phase_) {
    case Phase::Approach:
      if (distance < kOutOfReach_m + 0.15) enter(o, Phase::Attack);
      break;
    case Phase::Attack:
      if (gap < kLaunchGap_m && distance > kMinLaunch_m && !legs_->left_swings() &&
          legs_->step_progress() < kLaunchBy &&
          body_position(o, kRAnkle).z() > -root_height(o) + kAnkleHeight + kLifted_m &&
          body_position(o, kLAnkle).x() < 0 &&
          body_position(o, kLAnkle).z() < -root_height(o) + kAnkleHeight + 0.03) {
        enter(o, Phase::Lunge);
        front_from_back_ = (body_position(o, kRAnkle) - body_position(o, kLAnkle)).head<2>();
      } else if (phase_s_ > kAttack_s || distance < kLunge_m) {
        enter(o, Phase::Recover);
      }
      break;
    case Phase::Lunge:
      if (phase_s_ > kStride_s) enter(o, Phase::Recover);
      break;
    case Phase::Recover:
      if (phase_s_ > kRecover_s) enter(o, Phase::Approach);
      break;
  }
  if (phase_ == Phase::Lunge) {
    swing(o, a, kRHip, kLHip, front_from_back_, {kStagger + kStride_m, -kWidth_m},
          phase_s_ / kStride_s);
    stand_on(o, a, kLHip, kBackLeg_m, kBackPush_m);
  } else {
    double keep = phase_ == Phase::Attack ? kLunge_m - 0.3 : kOutOfReach_m;
    if (phase_ == Phase::Approach && closing > kClosing) keep += kGiveGround_m;
    const double to_my_end = o[at.to_my_end];
    if (phase_ != Phase::Attack && to_my_end < 1.5) keep = std::min(keep, distance);  // no room
    // Out of a lunge it first catches itself where it is, then gives ground.
    if (phase_ == Phase::Recover && after_lunge_ && phase_s_ < kCatch_s) keep = distance;
    const Eigen::Vector2d walk_to = line - towards * keep;
    legs_->act(o, walk_to, std::atan2(line.y(), line.x()), a);
  }

  // The épée on the line from the shoulder to the chest, arm straight.
  point_arm(o, a, Arm::Right,
            arm_.follow(chest - body_position(o, kRShoulder), kArmRate, control_dt_));
  bend_elbow(a, Arm::Right, 0);
}

bool ScriptedFencingPolicy::lunging() const {
  return phase_ == Phase::Lunge ||
         (phase_ == Phase::Recover && after_lunge_ && phase_s_ < kLandedCredit_s);
}

void ScriptedFencingPolicy::enter(std::span<const float> o, Phase phase) {
  // The stepping controller takes the legs back from the lunge from a fresh start.
  if (phase_ == Phase::Lunge) {
    legs_.emplace(gains_, control_dt_);
    legs_->start_stepping(o, true);  // the back (left) foot steps first, catching the body
  }
  after_lunge_ = phase_ == Phase::Lunge;
  phase_ = phase;
  phase_s_ = 0;
}

std::unique_ptr<Policy> make_scripted_fencing() {
  return std::make_unique<ScriptedFencingPolicy>();
}

}  // namespace olympics::client
