#include "guard_footwork.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "smpl_observation.h"
#include "step_controller.h"

namespace olympics::client::control {
namespace {

using namespace smpl;

constexpr double kAnkleHeight = 0.07;         // ankle origin above the sole, foot flat
constexpr int kFront = kRHip, kBack = kLHip;  // the sword (right) side leads

Eigen::Vector2d ankle2(std::span<const float> o, int hip) {
  return body_position(o, hip + 2).head<2>();
}

// A leg whose ankle stays where it is, `length` from its hip (heading frame), the hip drive
// righting the pelvis over the foot, the foot flat: the stepping controller's stance leg.
// `push`: the hip's target this much further ahead of the ankle (a leg driving the body on).
void stand_on(std::span<const float> o, std::span<float> a, int hip, double length, double push,
              double upright) {
  Eigen::Vector3d r = body_position(o, hip + 2) - body_position(o, hip);
  r.x() -= push;
  r.z() = -std::sqrt(length * length - std::min(r.head<2>().squaredNorm(), 0.8 * length * length));
  write_leg_toward(a, hip, r);
  const Eigen::Vector3d up = body_rotation(o, kPelvis).col(2);
  set_joint(a, hip, 0, joint_angle(a, hip, 0) - upright * up.y());
  set_joint(a, hip, 1, joint_angle(a, hip, 1) + upright * up.x());
  write_flat_foot(o, a, hip + 1);
}

void twist(std::span<float> a, int hip, double turn, double gain) {
  set_joint(a, hip, 2, -std::clamp(gain * turn, -0.5, 0.5));
}

}  // namespace

bool GuardFootwork::out_of_guard(std::span<const float> o) const {
  const Eigen::Vector2d stagger = ankle2(o, kFront) - ankle2(o, kBack);
  return stagger.x() < 0.6 * (g_.front_m + g_.back_m);
}

void GuardFootwork::begin_foot(std::span<const float> o, bool front, Eigen::Vector2d to) {
  front_flies_ = front;
  const int flies = front ? kFront : kBack, stands = front ? kBack : kFront;
  from_ = ankle2(o, flies) - ankle2(o, stands);
  to.y() += side_m_;
  to_ = to;
  stage_s_ = 0;
}

void GuardFootwork::begin(std::span<const float> o, Move move, double side_m) {
  move_ = move;
  side_m_ = side_m;
  const double stance = g_.front_m + g_.back_m;
  switch (move) {
    case Move::Guard:
      stage_ = Stage::Guard;
      return;
    case Move::Advance:  // the front foot first, a step on (from feet side by side: a step)
    case Move::Retreat:  // the back foot first
      stage_ = Stage::Shift;
      stage_s_ = 0;
      return;
    case Move::Lunge:
      stage_ = Stage::Lunging;
      return begin_foot(o, true, {stance + g_.lunge_m, -g_.width_m});
  }
}

void GuardFootwork::act(std::span<const float> o, Move wanted, double turn, double side_m,
                        std::span<float> a) {
  const double stance = g_.front_m + g_.back_m;
  stage_s_ += dt_;
  switch (stage_) {
    case Stage::Guard:
      if (wanted != Move::Guard) begin(o, wanted, side_m);
      break;
    case Stage::Shift:
      if (stage_s_ >= g_.shift_s) {
        stage_ = Stage::FirstFoot;
        const double now = (ankle2(o, kFront) - ankle2(o, kBack)).x();
        if (move_ == Move::Advance)
          begin_foot(o, true, {std::min(now, stance) + g_.step_m, -g_.width_m});
        else
          begin_foot(o, false, {-std::min(now, stance) - g_.step_m, g_.width_m});
      }
      break;
    case Stage::FirstFoot:
      if (stage_s_ >= g_.step_s) stage_ = Stage::Settle, stage_s_ = 0;
      break;
    case Stage::Settle:
      if (stage_s_ >= g_.settle_s) {
        stage_ = Stage::SecondFoot;
        side_m_ = 0;  // the first foot moved the guard sideways: the second keeps the width
        if (move_ == Move::Advance)
          begin_foot(o, false, {-stance, g_.width_m});
        else
          begin_foot(o, true, {stance, -g_.width_m});
      }
      break;
    case Stage::SecondFoot:
      if (stage_s_ >= g_.step_s) stage_ = Stage::Guard, stage_s_ = 0, move_ = Move::Guard;
      break;
    case Stage::Lunging:
      if (stage_s_ >= g_.lunge_s) stage_ = Stage::Lunged, stage_s_ = 0;
      break;
    case Stage::Lunged:
      if (stage_s_ >= g_.lunge_hold_s) {
        stage_ = Stage::Recovering;
        side_m_ = 0;
        begin_foot(o, true, {stance, -g_.width_m});
      }
      break;
    case Stage::Recovering:
      if (stage_s_ >= g_.recover_s) stage_ = Stage::Guard, stage_s_ = 0, move_ = Move::Guard;
      break;
  }

  switch (stage_) {
    case Stage::Guard:
      return stand_guard(o, turn, g_.leg_m, g_.leg_m, g_.guard_share, a);
    case Stage::Shift:  // onto the foot that stays: the back one in an advance
    case Stage::Settle:
      return stand_guard(o, turn, g_.leg_m, g_.leg_m,
                         (move_ == Move::Advance) == (stage_ == Stage::Shift) ? 1 - g_.loaded_share
                                                                              : g_.loaded_share,
                         a);
    case Stage::Lunged:
      return stand_guard(o, 0, g_.front_leg_lunge_m, g_.back_leg_lunge_m, g_.loaded_share, a);
    case Stage::FirstFoot:
    case Stage::SecondFoot:
      return swing_foot(o, stage_s_ / g_.step_s, g_.lift_m, g_.leg_m, 0, turn, a);
    case Stage::Lunging:
      return swing_foot(o, stage_s_ / g_.lunge_s, g_.lift_m, g_.back_leg_lunge_m, g_.back_push_m, 0,
                        a);
    case Stage::Recovering:
      return swing_foot(o, stage_s_ / g_.recover_s, g_.lift_m, g_.leg_m, 0, 0, a);
  }
}

void GuardFootwork::stand_guard(std::span<const float> o, double turn, double front_leg,
                                double back_leg, double share, std::span<float> a) const {
  stand_on(o, a, kFront, front_leg, 0, 0.5 * g_.upright_gain);
  stand_on(o, a, kBack, back_leg, 0, 0.5 * g_.upright_gain);
  // Balance the root over its point between the feet, nearer the back foot, with both ankles.
  const Eigen::Vector2d front = ankle2(o, kFront), back = ankle2(o, kBack);
  const Eigen::Vector2d over = back + share * (front - back);
  const Eigen::Vector3d v = root_velocity(o);
  for (int hip : {kFront, kBack}) {
    const int ankle = hip + 2;
    set_joint(a, ankle, 1, joint_angle(a, ankle, 1) - g_.ankle_p * over.x() + g_.ankle_d * v.x());
    set_joint(a, ankle, 0,
              joint_angle(a, ankle, 0) - (-g_.ankle_p * over.y() + g_.ankle_d * v.y()));
    twist(a, hip, turn, g_.turn_gain);
  }
}

void GuardFootwork::swing_foot(std::span<const float> o, double s, double lift, double stance_leg,
                               double push, double turn, std::span<float> a) const {
  s = std::clamp(s, 0.0, 1.0);
  const int flies = front_flies_ ? kFront : kBack, stands = front_flies_ ? kBack : kFront;
  stand_on(o, a, stands, stance_leg, push, g_.upright_gain);
  twist(a, stands, turn, 3.0);
  // The flying foot gets there by two thirds of its flight, lifted in between.
  const double b = std::clamp(1.5 * s, 0.0, 1.0);
  // It catches the body as a step of the walking gait does: further the way it is moving.
  Eigen::Vector2d nominal(0, 0);
  if (move_ == Move::Advance) nominal.x() = g_.step_speed;
  if (move_ == Move::Retreat) nominal.x() = -g_.step_speed;
  const Eigen::Vector2d to =
      to_ + g_.catch_s * (root_velocity(o).head<2>() -
                          (stage_ == Stage::Lunging ? root_velocity(o).head<2>() : nominal))
                             .cwiseProduct(Eigen::Vector2d(stage_ == Stage::Lunging ? 0 : 1, 1));
  const Eigen::Vector2d along = from_ + (to - from_) * (b * b * (3 - 2 * b));
  const Eigen::Vector2d stance_ankle = ankle2(o, stands);
  const Eigen::Vector3d ankle(
      stance_ankle.x() + along.x(), stance_ankle.y() + along.y(),
      -root_height(o) + kAnkleHeight + lift * std::sin(M_PI * s) - 0.02 * s);
  const Eigen::Matrix3d pelvis = body_rotation(o, kPelvis);
  write_leg_toward(a, flies, pelvis.transpose() * (ankle - body_position(o, flies)));
  write_flat_foot(o, a, flies + 1);
}

}  // namespace olympics::client::control
