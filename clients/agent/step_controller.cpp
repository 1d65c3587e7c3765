#include "step_controller.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "smpl_observation.h"

namespace olympics::client {
namespace {

using namespace smpl;

constexpr double kThigh = 0.377, kShank = 0.401;  // hip-knee and knee-ankle (HUMANOID.md 1.1)
constexpr double kAnkleHeight = 0.07;             // ankle origin above the sole, foot flat

struct LegAngles {
  double hip_x, hip_y, knee;
};

// Hip and knee angles putting the ankle at `r` from the hip, `r` in the hip's parent frame: the
// thigh is rolled (x) then pitched (y) to aim along r, and flexed forward by the knee's share.
LegAngles solve_leg(Eigen::Vector3d r) {
  const double d = std::clamp(r.norm(), 0.35, kThigh + kShank - 0.005);
  const Eigen::Vector3d u = r.normalized();
  const double knee =
      M_PI - std::acos(std::clamp(
                 (kThigh * kThigh + kShank * kShank - d * d) / (2 * kThigh * kShank), -1.0, 1.0));
  const double thigh_lead = std::acos(
      std::clamp((kThigh * kThigh + d * d - kShank * kShank) / (2 * kThigh * d), -1.0, 1.0));
  return {std::atan2(u.y(), -u.z()), -std::asin(std::clamp(u.x(), -1.0, 1.0)) - thigh_lead, knee};
}

void write_leg(std::span<float> a, int hip, const LegAngles& leg) {
  set_joint(a, hip, 0, leg.hip_x);
  set_joint(a, hip, 1, leg.hip_y);
  set_joint(a, hip, 2, 0);
  set_joint(a, hip + 1, 1, leg.knee);
}

// Ankle targets that turn the foot flat (heading frame) from the shank as it is now.
void flat_foot(std::span<const float> o, std::span<float> a, int knee) {
  const Eigen::Matrix3d shank = body_rotation(o, knee);
  const Eigen::Vector3d x = shank.col(0), z = shank.col(2);
  set_joint(a, knee + 1, 0, std::asin(std::clamp(z.y(), -1.0, 1.0)));
  set_joint(a, knee + 1, 1, std::asin(std::clamp(x.z(), -1.0, 1.0)));
  set_joint(a, knee + 1, 2, 0);
}

}  // namespace

void write_leg_toward(std::span<float> a, int hip, const Eigen::Vector3d& hip_to_ankle) {
  write_leg(a, hip, solve_leg(hip_to_ankle));
}

void write_flat_foot(std::span<const float> o, std::span<float> a, int knee) {
  flat_foot(o, a, knee);
}

StepGains side_stepping(StepGains g) {
  g.step_s = 0.2;
  g.max_speed = 1.3;
  g.max_forward_speed = 0.6;
  g.max_side_speed = 1.2;
  g.max_side_step = 0.6;
  g.side_step = -0.08;
  return g;
}

void StepController::stand(std::span<const float> o, std::span<float> a) const {
  const BalanceGains& g = gains_.balance;
  const Eigen::Vector3d mid = 0.5 * (body_position(o, kLAnkle) + body_position(o, kRAnkle));
  const Eigen::Vector3d v = root_velocity(o);
  const Eigen::Vector2d balanced = balance_com_ ? com_offset_ : Eigen::Vector2d::Zero();
  const double dx = balanced.x() - mid.x(), dy = balanced.y() - mid.y();
  for (int ankle : {kLAnkle, kRAnkle}) {
    set_joint(a, ankle, 1, g.ankle_bias + g.ankle_p * dx + g.ankle_d * v.x());
    set_joint(a, ankle, 0, -(g.ankle_p * dy + g.ankle_d * v.y()));
  }
  for (int hip : {kLHip, kRHip}) set_joint(a, hip, 1, g.hip_p * dx);
}

bool StepController::losing_balance(std::span<const float> o) const {
  if (!balance_com_ || gains_.recover_m <= 0) return false;
  const Eigen::Vector2d mid =
      0.5 * (body_position(o, kLAnkle) + body_position(o, kRAnkle)).head<2>();
  return (com_offset_ - mid).norm() > gains_.recover_m ||
         root_velocity(o).head<2>().norm() > gains_.recover_speed;
}

Eigen::Vector2d StepController::placement_origin() {
  if (gains_.centre_of_mass_placement == 0) return Eigen::Vector2d::Zero();
  if (!com_)
    throw std::logic_error(
        "StepController: centre_of_mass_placement is above 0 but no centre of mass was given; "
        "call set_centre_of_mass before act");
  if (!step_com_) step_com_ = com_;
  *step_com_ += (*com_ - *step_com_) * std::min(1.0, control_dt_ / gains_.step_s);
  return gains_.centre_of_mass_placement * *step_com_;
}

// Where the body would come to rest over a foot put there `in_s` seconds from now (heading frame,
// from the root): the balanced point (the centre of mass when balance_centre_of_mass) carried on
// by the velocity for `in_s`, plus the velocity times sqrt(height / g), the linear inverted
// pendulum's capture point.
double pendulum_time_s(std::span<const float> o) { return std::sqrt(root_height(o) / 9.81); }

Eigen::Vector2d StepController::capture_point(std::span<const float> o, double in_s) const {
  const Eigen::Vector2d balanced = balance_com_ ? com_offset_ : Eigen::Vector2d::Zero();
  return balanced + root_velocity(o).head<2>() * (in_s + pendulum_time_s(o));
}

void StepController::begin_step(std::span<const float> o, bool left_swings) {
  left_swings_ = left_swings;
  phase_s_ = 0;
  lift_off_ = body_position(o, left_swings ? kLAnkle : kRAnkle).head<2>();
}

void StepController::act(std::span<const float> o, const Eigen::Vector2d& target, double turn,
                         std::span<float> a) {
  const StepGains& g = gains_;
  const Eigen::Vector2d v = root_velocity(o).head<2>();
  const double distance = target.norm();

  const double ground = -root_height(o);  // the floor, root-relative
  const bool at_once = step_at_once_;
  step_at_once_ = false;
  if (!stepping_) {
    const bool must_turn = g.turn_start > 0 && std::abs(turn) > g.turn_start;
    const bool losing = losing_balance(o);
    if (distance < (at_once ? g.arrive_m : g.start_m) && !must_turn && !losing) return stand(o, a);
    stepping_ = true;
    catching_ = losing && g.catch_step_s > 0;
    bool left = (target.y() > 0) != at_once;
    if (catching_ && g.catch_on_the_falling_side) {
      const double feet_y = 0.5 * (body_position(o, kLAnkle).y() + body_position(o, kRAnkle).y());
      left = capture_point(o, 0).y() > feet_y;
    }
    begin_step(o, left);
  } else if (phase_s_ >= (catching_ ? g.catch_step_s : g.step_s)) {
    catching_ = false;
    auto down = [&](int ankle) {
      return body_position(o, ankle).z() < ground + kAnkleHeight + 0.02;
    };
    const bool turned = g.turn_start <= 0 || std::abs(turn) < 0.5 * g.turn_start;
    if (down(kLAnkle) && down(kRAnkle) && distance < g.arrive_m && v.norm() < g.settle_speed &&
        turned) {
      stepping_ = false;
      return stand(o, a);
    }
    begin_step(o, !left_swings_);
  }
  const int swing_hip = left_swings_ ? kLHip : kRHip, stance_hip = left_swings_ ? kRHip : kLHip;
  const double side = left_swings_ ? 1.0 : -1.0;

  // Where the swing foot goes: under where the root (or the centre of mass) will be, half a step
  // on, corrected by the velocity error, to its own side.
  Eigen::Vector2d desired_v = Eigen::Vector2d::Zero();
  if (distance > 1e-9)
    desired_v = target / distance * std::min(g.max_speed, g.speed_per_m * distance);
  // Sideways the feet cannot cross, so only every other step can catch the body: go slower.
  desired_v.y() = std::clamp(desired_v.y(), -g.max_side_speed, g.max_side_speed);
  if (g.max_forward_speed > 0)
    desired_v.x() = std::clamp(desired_v.x(), -g.max_forward_speed, g.max_forward_speed);
  const double step_s = catching_ ? g.catch_step_s : g.step_s;
  const double remaining = step_s - phase_s_;
  Eigen::Vector2d foot = v * (remaining + g.lead_s) + g.velocity_gain * (v - desired_v);
  foot += placement_origin();
  if (catching_) {
    constexpr double kCatchBeyond_m = 0.05;
    foot = capture_point(o, remaining);
    if (v.norm() > 1e-6) foot += kCatchBeyond_m * v.normalized();
  }
  foot.y() += side * g.stance_width;
  // Moving sideways, the foot on the side of the motion leads; side_step moves where it lands.
  const bool leads = side * desired_v.y() > 0;
  if (leads) foot.y() += g.side_step * desired_v.y();
  const Eigen::Vector2d stance_ankle = body_position(o, stance_hip + 2).head<2>();
  foot.y() = side > 0 ? std::max(foot.y(), stance_ankle.y() + 0.12)
                      : std::min(foot.y(), stance_ankle.y() - 0.12);
  const Eigen::Vector2d reach = foot - stance_ankle;
  if (g.max_side_step > 0) {
    // An ellipse: max_step forward and back, max_side_step sideways.
    const double over = std::hypot(reach.x() / g.max_step, reach.y() / g.max_side_step);
    if (over > 1) foot = stance_ankle + reach / over;
  } else if (reach.norm() > g.max_step) {
    foot = stance_ankle + reach * (g.max_step / reach.norm());
  }

  const double s = std::clamp(phase_s_ / step_s, 0.0, 1.0);
  const double blend = std::clamp(2 * s, 0.0, 1.0);  // the foot gets there by mid-swing
  const Eigen::Vector2d horizontal =
      lift_off_ + (foot - lift_off_) * (blend * blend * (3 - 2 * blend));
  const Eigen::Vector3d ankle(horizontal.x(), horizontal.y(),
                              ground + kAnkleHeight + g.lift * std::sin(M_PI * s) - 0.02 * s);

  // Swing leg: solved in the pelvis frame, so its placement holds whatever the pelvis does.
  const Eigen::Matrix3d pelvis = body_rotation(o, kPelvis);
  write_leg(a, swing_hip, solve_leg(pelvis.transpose() * (ankle - body_position(o, swing_hip))));

  // Stance leg: solved in the upright heading frame, which rights the pelvis over the foot.
  Eigen::Vector3d r = body_position(o, stance_hip + 2) - body_position(o, stance_hip);
  const double horizontal_sq =
      std::min(r.head<2>().squaredNorm(), 0.8 * g.leg_length * g.leg_length);
  r.z() = -std::sqrt(g.leg_length * g.leg_length - horizontal_sq);
  LegAngles stance = solve_leg(r);
  // The drive sags under the body's weight: lean the target against the pelvis's tilt.
  const Eigen::Vector3d up = pelvis.col(2);
  stance.hip_x -= g.upright_gain * up.y();
  stance.hip_y += g.upright_gain * up.x();
  write_leg(a, stance_hip, stance);
  // Turning: the planted thigh twists the pelvis (a hip z angle turns the thigh against it).
  set_joint(a, stance_hip, 2, -std::clamp(g.turn_gain * turn, -0.5, 0.5));

  flat_foot(o, a, kLKnee);
  flat_foot(o, a, kRKnee);
  phase_s_ += control_dt_;
}

}  // namespace olympics::client
