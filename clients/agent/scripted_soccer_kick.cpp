#include "scripted_soccer_kick.h"

#include <algorithm>
#include <cmath>

#include "control/drive_target.h"
#include "control/smpl_legs.h"
#include "equipment/ball.h"
#include "smpl_observation.h"
#include "step_controller.h"

namespace olympics::client {
namespace {

using namespace smpl;

const double kBallRadius = sports::equipment::soccer_ball().radius;
constexpr double kAnkleHeight = 0.07;  // ankle origin above the sole, foot flat
constexpr double kLegLength = 0.77;    // a standing leg's hip to ankle (a slightly bent knee)

double smooth(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3 - 2 * s);
}

Eigen::Vector3d flat(const Eigen::Vector2d& v) { return {v.x(), v.y(), 0}; }

}  // namespace

SoccerKick::SoccerKick(const control::BodyModel& model, double control_dt, KickGains gains)
    : model_(model),
      dt_(control_dt),
      g_(gains),
      swinging_{control::LimbControl(
                    model,
                    control::LimbIk(model, control::smpl_leg(true), control::smpl_toe_front(true),
                                    Eigen::Vector3d::UnitX()),
                    gains.swing_scale),
                control::LimbControl(
                    model,
                    control::LimbIk(model, control::smpl_leg(false), control::smpl_toe_front(false),
                                    Eigen::Vector3d::UnitX()),
                    gains.swing_scale)} {}

void SoccerKick::start(bool right_foot) {
  right_ = right_foot;
  struck_ = false;
  swinging_[0].reset();
  swinging_[1].reset();
  next(Phase::ShiftToKicker);
}

const char* SoccerKick::phase_name() const {
  switch (phase_) {
    case Phase::Idle:
      return "idle";
    case Phase::ShiftToKicker:
      return "shift_to_kicker";
    case Phase::Plant:
      return "plant";
    case Phase::ShiftToPlanted:
      return "shift_to_planted";
    case Phase::Back:
      return "back";
    case Phase::Swing:
      return "swing";
    case Phase::Land:
      return "land";
    case Phase::Settle:
      return "settle";
    case Phase::Catch:
      return "catch";
  }
  return "?";
}

Eigen::Vector2d SoccerKick::approach_from_ball(const Eigen::Vector2d& direction,
                                               bool right_foot) const {
  const Eigen::Vector2d side(-direction.y(), direction.x());  // left of the kick
  // The root behind the ball on the kick's line (a plant step short of the ball), shifted
  // toward the planting foot's side by approach_side_m.
  return -direction * g_.approach_behind_m +
         side * (right_foot ? g_.approach_side_m : -g_.approach_side_m);
}

void SoccerKick::support(std::span<const float> o, const control::BodyPose& pose,
                         const Eigen::Vector2d& com_target, double left_share, double right_share,
                         std::span<float> a) {
  const Eigen::Vector3d com = model_.centre_of_mass(pose);
  const Eigen::Vector2d v = root_velocity(o).head<2>();
  Eigen::Vector2d shift = g_.com_gain * (com_target - com.head<2>()) - g_.com_damping_s * v;
  if (shift.norm() > g_.max_shift_m) shift *= g_.max_shift_m / shift.norm();
  // Each standing leg solved in the upright heading frame for the pelvis moved by `shift`: its
  // stiff drives push the pelvis there and right it over the foot (as the stepping controller's
  // stance leg), then carry their share of the weight.
  const Eigen::Vector3d tilt = pose.rotation[kPelvis].col(2);
  const double share[2] = {left_share, right_share};
  for (int leg = 0; leg < 2; ++leg) {
    if (share[leg] < 0) continue;  // swinging
    const int hip = leg == 0 ? kLHip : kRHip;
    Eigen::Vector3d r = pose.position[hip + 2] - pose.position[hip] - flat(shift);
    const double horizontal_sq = std::min(r.head<2>().squaredNorm(), 0.8 * kLegLength * kLegLength);
    r.z() = -std::sqrt(kLegLength * kLegLength - horizontal_sq);
    write_leg_toward(a, hip, r);
    if (g_.rigid_ankles) {
      // The foot flat for the legs as asked (not as they are): the whole leg, ankle too, pushes
      // the pelvis to where it was asked to go.
      const Eigen::Matrix3d shank = control::read_joint(a, hip) * control::read_joint(a, hip + 1);
      control::write_joint(a, hip + 2, shank.transpose());
    } else {
      write_flat_foot(o, a, hip + 1);
    }
    set_joint(a, hip, 0, joint_angle(a, hip, 0) - share[leg] * g_.upright_gain * tilt.y());
    set_joint(a, hip, 1, joint_angle(a, hip, 1) + share[leg] * g_.upright_gain * tilt.x());
    // The ankles push the centre of mass toward where it should be (an ankle strategy).
    const Eigen::Vector2d push = g_.ankle_p * (com.head<2>() - com_target) + g_.ankle_d * v;
    set_joint(a, hip + 2, 1, joint_angle(a, hip + 2, 1) + push.x());
    set_joint(a, hip + 2, 0, joint_angle(a, hip + 2, 0) - push.y());
    for (int b = hip; b < hip + 3; ++b)
      control::write_joint(a, b,
                           control::drive_target(model_.body(b), control::read_joint(a, b),
                                                 -share[leg] * g_.support_scale *
                                                     model_.gravity_torque_above(pose, b)));
  }
}

void SoccerKick::swing(const control::BodyPose& pose, bool left, const Eigen::Vector3d& now,
                       const Eigen::Vector3d& then, const Eigen::Vector3d& toward,
                       std::span<float> a) {
  control::LimbGoal n, t;
  n.position = now;
  t.position = then;
  n.axis = t.axis = toward;
  n.axis_either_sign = t.axis_either_sign = false;
  n.axis_weight_m = t.axis_weight_m = 0.1;
  swinging_[left ? 0 : 1].drive(pose, n, t, dt_, a);
}

void SoccerKick::act(std::span<const float> o, const control::BodyPose& pose,
                     const Eigen::Vector3d& ball, const Eigen::Vector2d& direction,
                     double ball_speed, std::span<float> a) {
  if (phase_ == Phase::Idle) return;
  const int kicker = right_ ? kRAnkle : kLAnkle, planter = right_ ? kLAnkle : kRAnkle;
  const double kicker_share_l = right_ ? 0.0 : 1.0;  // left share when the kicker stands alone
  const Eigen::Vector2d side(-direction.y(), direction.x());  // left of the kick
  const Eigen::Vector3d u = flat(direction), up = Eigen::Vector3d::UnitZ();
  const double ground = -root_height(o);
  const Eigen::Vector2d foot_ahead = direction * 0.04;  // the foot's middle, from its ankle
  auto ankle2 = [&](int ankle) { return Eigen::Vector2d(pose.position[ankle].head<2>()); };
  auto toe_of = [&](int ankle) {
    return Eigen::Vector3d(pose.position[ankle] +
                           pose.rotation[ankle] * control::smpl_toe_front(ankle == kLAnkle));
  };
  t_ += dt_;

  // The trunk upright against whatever the legs do.
  static constexpr int kTrunk[] = {kTorso, 10, kChest};
  control::hold_against_gravity(model_, pose, kTrunk, a, g_.support_scale);

  switch (phase_) {
    case Phase::Idle:
      return;
    case Phase::ShiftToKicker: {
      const double s = smooth(t_ / g_.shift_s);
      const Eigen::Vector2d mid = 0.5 * (ankle2(kLAnkle) + ankle2(kRAnkle));
      const Eigen::Vector2d target = mid + s * (ankle2(kicker) - mid) + foot_ahead;
      const double l = 0.5 + s * (kicker_share_l - 0.5);
      support(o, pose, target, l, 1 - l, a);
      if (t_ >= g_.shift_s) {
        lift_off_ = toe_of(planter);
        next(Phase::Plant);
      }
      return;
    }
    case Phase::Plant: {
      // The planted ankle beside the ball, a little behind it; its toe where that puts it.
      Eigen::Vector3d ankle =
          ball + flat(side * (right_ ? 1 : -1) * g_.plant_side_m) - u * g_.plant_behind_m;
      // ...but no further ahead of the centre of mass than the weight can follow it.
      const Eigen::Vector3d com = model_.centre_of_mass(pose);
      const double ahead = (ankle - com).dot(u);
      ankle += u * (std::clamp(ahead, -g_.plant_reach_m, g_.plant_reach_m) - ahead);
      ankle.z() = ground + kAnkleHeight;
      const Eigen::Vector3d toe = ankle + u * 0.19 - up * 0.06;  // pressed down
      auto at = [&](double time) {
        const double s = std::clamp(time / g_.plant_s, 0.0, 1.0);
        Eigen::Vector3d p = lift_off_ + (toe - lift_off_) * smooth(1.6 * s);
        p.z() = std::max(p.z(), ground + 0.03 * (1 - s)) + g_.plant_lift_m * std::sin(M_PI * s);
        return p;
      };
      support(o, pose, ankle2(kicker) + foot_ahead, right_ ? -1 : 1, right_ ? 1 : -1, a);
      swing(pose, /*left=*/right_, at(t_ + g_.ask_ahead_s), at(t_ + g_.ask_ahead_s + dt_), u, a);
      if (t_ >= g_.plant_s) next(Phase::ShiftToPlanted);
      return;
    }
    case Phase::ShiftToPlanted: {
      const double s = smooth(t_ / g_.shift_s);
      const Eigen::Vector2d from = ankle2(kicker), to = ankle2(planter);
      const double l = kicker_share_l + s * ((1 - kicker_share_l) - kicker_share_l);
      support(o, pose, from + s * (to - from) + foot_ahead, l, 1 - l, a);
      // The kicking foot leaves the ground only once the weight is nearly over the planted foot
      // (or after a little longer): lifted sooner, the body topples toward the kicking side.
      const Eigen::Vector2d com = model_.centre_of_mass(pose).head<2>();
      const bool over = std::abs((com - to).dot(side)) < g_.planted_within_m ||
                        t_ >= g_.shift_s + g_.planted_wait_s;
      if (t_ >= g_.shift_s && over) {
        lift_off_ = toe_of(kicker);
        swing_speed_ = std::clamp(ball_speed / g_.ball_per_foot, 1.0, g_.max_foot_speed);
        next(Phase::Back);
      }
      return;
    }
    case Phase::Catch: {
      // It steps while the centre of mass is off the feet or moving; the target, just to the
      // kicking side, makes the kicking foot the first to step.
      catching_->balance_centre_of_mass(model_.centre_of_mass(pose), 0.03);
      catching_->act(o, Eigen::Vector2d(0, right_ ? -0.01 : 0.01), 0, a);
      if (t_ >= g_.catch_s || (t_ > 0.5 && !catching_->stepping())) next(Phase::Idle);
      return;
    }
    default:
      break;
  }

  // The kick proper: the planted foot alone bears the weight. The swing's line is fixed from
  // the planted ankle, so the ball flying off does not move it.
  support(o, pose, ankle2(planter) + foot_ahead, right_ ? 1 : -1, right_ ? -1 : 1, a);
  const Eigen::Vector3d contact_from_planted = -flat(side * (right_ ? 1 : -1) * g_.plant_side_m) +
                                               u * g_.plant_behind_m - u * (kBallRadius + 0.01);
  const Eigen::Vector3d base = pose.position[planter];
  Eigen::Vector3d contact = base + contact_from_planted;
  contact.z() = ground + kBallRadius;
  if (!struck_ && phase_ != Phase::Land) {
    // Until the ball is struck, the contact point follows the ball (it may not be quite where
    // the plant put it).
    contact = ball - u * (kBallRadius + 0.01);
  }
  // Drawn back on the kicking leg's side of the line, not behind the planted foot.
  const Eigen::Vector3d out = -flat(side) * (right_ ? 1 : -1);
  const Eigen::Vector3d back =
      contact - u * g_.backswing_m + up * g_.backswing_up_m + out * g_.backswing_out_m;
  // Along the swing's line, s metres from the contact point: the foot low at the ball and
  // rising on either side.
  auto on_line = [&](double s) {
    const double b = s / g_.backswing_m, f = s / g_.follow_m;
    const Eigen::Vector3d off =
        s < 0 ? Eigen::Vector3d(up * g_.backswing_up_m * b * b + out * g_.backswing_out_m * b * b)
              : Eigen::Vector3d(up * g_.follow_up_m * f * f);
    return Eigen::Vector3d(contact + u * s + off);
  };
  switch (phase_) {
    case Phase::Back: {
      auto at = [&](double time) {
        const double s = smooth(time / g_.back_s);
        return Eigen::Vector3d(lift_off_ + (back - lift_off_) * s);
      };
      swing(pose, /*left=*/!right_, at(t_ + g_.ask_ahead_s), at(t_ + g_.ask_ahead_s + dt_), u, a);
      if (t_ >= g_.back_s) next(Phase::Swing);
      return;
    }
    case Phase::Swing: {
      auto s_at = [&](double time) {
        return std::min(-g_.backswing_m + swing_speed_ * time, g_.follow_m);
      };
      swing(pose, /*left=*/!right_, on_line(s_at(t_ + g_.ask_ahead_s)),
            on_line(s_at(t_ + g_.ask_ahead_s + dt_)), u, a);
      if (s_at(t_) > 0) struck_ = true;
      if (s_at(t_) >= g_.follow_m) {
        swing_end_ = on_line(g_.follow_m) - base;
        if (g_.catch_s > 0) {
          // The body still falls toward the kicking side: a stepping controller of the kick's
          // own, with quicker and longer steps than a walk's, catches it, the kicking foot first.
          StepGains catching;
          catching.step_s = g_.catch_step_s;
          catching.max_step = g_.catch_max_step_m;
          catching_.emplace(catching, dt_);
          next(Phase::Catch);
          return;
        }
        next(g_.step_after ? Phase::Idle : Phase::Land);
      }
      return;
    }
    case Phase::Land: {
      // Down beside the planted foot, a stance's width to the kicking side, a little ahead.
      Eigen::Vector3d ankle = base - flat(side * (right_ ? 1 : -1) * 0.25) + u * 0.05;
      ankle.z() = ground + kAnkleHeight;
      const Eigen::Vector3d toe = ankle + u * 0.19 - up * 0.044;
      const Eigen::Vector3d from = base + swing_end_;
      auto at = [&](double time) {
        return Eigen::Vector3d(from + (toe - from) * smooth(time / g_.land_s));
      };
      swing(pose, !right_, at(t_ + g_.ask_ahead_s), at(t_ + g_.ask_ahead_s + dt_), u, a);
      if (t_ >= g_.land_s) next(Phase::Settle);
      return;
    }
    case Phase::Settle: {
      const Eigen::Vector2d mid = 0.5 * (ankle2(kLAnkle) + ankle2(kRAnkle));
      support(o, pose, mid + foot_ahead, 0.5, 0.5, a);
      if (t_ >= g_.settle_s) next(Phase::Idle);
      return;
    }
    default:
      return;
  }
}

}  // namespace olympics::client
