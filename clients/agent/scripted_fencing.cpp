#include "scripted_fencing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/limb_control.h"
#include "control/smpl_limbs.h"
#include "fencing/epee.h"
#include "fencing/fencing_match.h"
#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

// Tuned on seeds 1-200 only (docs/combat-sports.md); the figures are on seeds 100001+.
constexpr double kOutOfReach_m = 2.1;   // root to root on guard: the tips cannot reach
constexpr double kAttackFrom_m = 2.25;  // closer than this (and on guard a while) it attacks
constexpr double kLunge_m = 1.4;        // root to root the attack steps to
constexpr double kGuardTip_m = 1.35;    // tip from the shoulder on guard, in line
constexpr double kThrough_m = 0.08;     // the attack drives the tip this far past the chest
constexpr double kTipSpeed = 2.0;       // m/s the tip's goal moves at (a heavy épée swung at
                                        // once spins the body on its feet)
constexpr double kExtendFirst_s = 0.2;  // the arm extends this long before the legs step in
constexpr double kAttack_s = 1.2;       // longest attack before recovering
constexpr double kRecover_s = 0.8;
constexpr double kOnGuard_s = 0.4;     // least time on guard between attacks
constexpr double kGravityScale = 2;    // compensation, multiples of the weight (control.md)
constexpr double kBalanceAhead = 0.0;  // centre of mass held this far ahead of the ankles
constexpr int kChestTarget = 3;        // opponent_targets: pelvis, torso, spine, chest, head

}  // namespace

// Everything the policy reads of an observation, in one place (the blocks by name).
struct ScriptedFencingPolicy::View {
  Eigen::Vector3d opponent;  // the opponent's root, heading frame
  Eigen::Vector3d chest;     // the opponent's chest
  double to_my_end = 0;      // m to my end of the piste
  double my_touches = 0;
};

ScriptedFencingPolicy::View ScriptedFencingPolicy::read_view(std::span<const float> o) const {
  const Blocks& at = blocks_;
  return {vec3(o, at.opponent_root), vec3(o, at.opponent_targets + 3 * kChestTarget),
          o[at.piste + 2], o[at.bout]};
}

struct ScriptedFencingPolicy::Arm {
  Arm()
      : model(sports::fencing::fencer_model()),
        epee(model,
             control::LimbIk(model, control::smpl_right_arm(), sports::fencing::kTipInHand,
                             Eigen::Vector3d(0, -1, 0)),
             kGravityScale) {}
  control::BodyModel model;
  control::LimbControl epee;
};

ScriptedFencingPolicy::ScriptedFencingPolicy() = default;
ScriptedFencingPolicy::~ScriptedFencingPolicy() = default;

void ScriptedFencingPolicy::start(const MatchInfo& match) {
  if (match.sport != "fencing")
    throw std::invalid_argument("the scripted fencing policy plays fencing, not " + match.sport);
  const ObservationLayout& l = match.observation;
  blocks_ = {l.offset("opponent_root"), l.offset("opponent_targets"), l.offset("piste"),
             l.offset("bout")};
  control_dt_ = match.control_dt;
  if (!arm_) arm_ = std::make_unique<Arm>();
  arm_->epee.reset();
  StepGains gains;
  gains.turn_start = 0.3;                // keep facing the opponent, stepping in place if need be
  gains.balance = {2.0, 2.0, 0.0, 2.0};  // stiffer standing: the épée is held out in front
  legs_.emplace(gains, control_dt_);
  phase_ = Phase::Guard;
  phase_s_ = 0;
  touches_ = 0;
  have_tip_goal_ = false;
}

void ScriptedFencingPolicy::act(std::span<const float> o, std::span<float> a) {
  if (!legs_) throw std::logic_error("ScriptedFencingPolicy: act() before start()");
  if (a.size() != kActions)
    throw std::invalid_argument(
        "the scripted fencing policy drives the SMPL humanoid (69 actions)");
  std::fill(a.begin(), a.end(), 0.0f);
  const View view = read_view(o);
  const Eigen::Vector2d line = view.opponent.head<2>();
  const double distance = line.norm();
  const Eigen::Vector2d towards =
      distance > 1e-6 ? Eigen::Vector2d(line / distance) : Eigen::Vector2d(1, 0);
  const control::BodyPose pose = arm_->model.pose_from_observation(o);
  const Eigen::Vector3d shoulder = pose.position[kRShoulder];
  const Eigen::Vector3d to_chest = view.chest - shoulder;
  const Eigen::Vector3d in_line = to_chest.normalized();

  // Phases: on guard out of reach, an attack, a recovery. A touch (mine) or a halt that puts
  // both back on their lines ends an attack.
  const bool landed = view.my_touches > touches_;
  touches_ = view.my_touches;
  phase_s_ += control_dt_;
  auto enter = [&](Phase p) { phase_ = p, phase_s_ = 0; };
  switch (phase_) {
    case Phase::Guard:
      if (phase_s_ > kOnGuard_s && distance < kAttackFrom_m) enter(Phase::Attack);
      break;
    case Phase::Attack:
      if (landed || phase_s_ > kAttack_s || distance > kOutOfReach_m + 1) enter(Phase::Recover);
      break;
    case Phase::Recover:
      if (phase_s_ > kRecover_s || distance > kOutOfReach_m + 1) enter(Phase::Guard);
      break;
  }
  const bool attacking = phase_ == Phase::Attack;

  // Legs: keep the distance (in on the attack once the arm is out), facing the opponent.
  double keep = attacking && phase_s_ > kExtendFirst_s ? kLunge_m : kOutOfReach_m;
  if (attacking && phase_s_ <= kExtendFirst_s) keep = std::min(keep, distance);
  if (!attacking && view.to_my_end < 1.5) keep = std::min(keep, distance);  // no room behind
  legs_->balance_centre_of_mass(arm_->model.centre_of_mass(pose), kBalanceAhead);
  // Each fencer closes only its share of the gap: both moving the whole way overshoot, then
  // back away too fast and fall (measured).
  const double share = attacking ? 1.0 : 0.5;
  legs_->act(o, towards * (distance - keep) * share, std::atan2(line.y(), line.x()), a);
  if (!legs_->stepping()) control::hold_standing_legs(arm_->model, pose, a, kGravityScale);

  // Arm: the tip in line on guard; on the attack through the chest. The goal moves at a
  // limited speed, so the IK's next-tick goal gives the arm its velocity.
  const Eigen::Vector3d wanted = attacking ? Eigen::Vector3d(view.chest + in_line * kThrough_m)
                                           : Eigen::Vector3d(shoulder + in_line * kGuardTip_m);
  if (!have_tip_goal_) tip_goal_ = wanted, have_tip_goal_ = true;
  const Eigen::Vector3d step = wanted - tip_goal_;
  const double max_step = kTipSpeed * control_dt_;
  const Eigen::Vector3d move =
      step.norm() > max_step ? Eigen::Vector3d(step * (max_step / step.norm())) : step;
  control::LimbGoal now, next;
  now.position = tip_goal_ + move;
  next.position = now.position + move;
  now.axis = next.axis = in_line;
  now.axis_either_sign = next.axis_either_sign = false;
  tip_goal_ = now.position;
  arm_->epee.drive(pose, now, next, control_dt_, a);

  // The trunk held up against the épée's weight; the free arm back and down.
  static constexpr int kTrunk[] = {control::kSmplTorso, control::kSmplSpine, control::kSmplChest,
                                   control::kSmplRThorax};
  control::hold_against_gravity(arm_->model, pose, kTrunk, a, kGravityScale);
  set_joint(a, kLShoulder, 0, -1.2);
}

std::unique_ptr<Policy> make_scripted_fencing() {
  return std::make_unique<ScriptedFencingPolicy>();
}

}  // namespace olympics::client
