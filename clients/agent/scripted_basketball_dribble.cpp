#include "scripted_basketball_dribble.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ball_aim.h"
#include "control/drive_target.h"
#include "control/limb_control.h"
#include "control/minimum_jerk.h"
#include "control/smplx_limbs.h"
#include "control/standing_balance.h"
#include "equipment/ball.h"
#include "smplx_observation.h"

namespace olympics::client {
namespace {

constexpr double kGravity = 9.81;
// The basketball the server plays with (sports/equipment/ball.cpp): radius, restitution, drag.
const sports::equipment::BallSpec kBall = sports::equipment::basketball();
const double kBallRadius = kBall.radius, kBallRestitution = kBall.restitution;
const double kBallDrag = basketball_drag_per_mass();
// From the palm box's centre to the ball's centre when the palm touches the top of the ball.
const double kPalmOverBall = kBallRadius + control::kSmplxPalmHalfThickness;
constexpr double kHorizon_s = 1.2;
constexpr int kLeftAnkle = 3, kRightAnkle = 7;  // SMPL-X bodies

}  // namespace

BasketballDribble::BasketballDribble(const DribbleParams& params)
    : p_(params),
      model_(control::BodyModel::humanoid(core::HumanoidKind::SmplX)),
      ik_(model_, control::smplx_arm(true), control::smplx_palm_centre(true),
          control::smplx_palm_normal()),
      left_ik_(model_, control::smplx_arm(false), control::smplx_palm_centre(false),
               control::smplx_palm_normal()),
      push_speed_(params.push_speed) {}

std::optional<BasketballDribble::Meeting> BasketballDribble::next_meeting(
    const Eigen::Vector3d& ball, const Eigen::Vector3d& velocity, double floor) const {
  Eigen::Vector3d x = ball, v = velocity;
  const double meet = floor + p_.meet_height;
  bool rising_after_bounce = v.z() > 0 && x.z() < meet;
  for (double t = 0; t < kHorizon_s; t += kServerStep_s) {
    // As the server steps it (ball_aim.h): velocity first, drag from the step's start.
    const Eigen::Vector3d before = x, v_before = v;
    v += kServerStep_s * (Eigen::Vector3d(0, 0, -kGravity) - kBallDrag * v.norm() * v);
    x += kServerStep_s * v;
    if (x.z() < floor + kBallRadius && v.z() < 0) {
      x.z() = floor + kBallRadius;
      v.z() = -kBallRestitution * v.z();
      rising_after_bounce = true;
    }
    if (!rising_after_bounce) continue;
    if (before.z() < meet && x.z() >= meet) return Meeting{t + kServerStep_s, x, v};
    if (v_before.z() > 0 && v.z() <= 0) return Meeting{t + kServerStep_s, x, v};
  }
  return std::nullopt;
}

// The palm's centre, feet's frame, `t` s into the stroke (or waiting, without one).
Eigen::Vector3d BasketballDribble::palm_goal(double t) const {
  const double dip = push_speed_ * p_.stroke_s / M_PI;  // the cosine's depth for that speed
  const double ready = meet_z_ + dip / 2;
  if (!stroke_from_ || t < 0 || t > p_.stroke_s) return {meet_xy_.x(), meet_xy_.y(), ready};
  const double z = ready - dip * (1 - std::cos(2 * M_PI * t / p_.stroke_s)) / 2;
  const Eigen::Vector2d xy = meet_xy_ + sweep_ * (t - p_.stroke_s / 4);
  return {xy.x(), xy.y(), z};
}

void BasketballDribble::drive_arm(const control::LimbIk& ik, std::vector<Eigen::Matrix3d>& start,
                                  const control::BodyPose& pose, const Eigen::Vector3d& now,
                                  const Eigen::Vector3d& next, double dt, std::span<float> action) {
  control::LimbGoal goal;
  goal.position = now;
  goal.axis = -Eigen::Vector3d::UnitZ();  // the palm facing the floor
  goal.axis_either_sign = false;
  goal.axis_weight_m = p_.palm_axis_weight_m;
  if (start.empty()) {
    // The fixed start of every solve: the first goal's solution from the T-pose.
    start =
        ik.solve(pose, goal, std::vector<Eigen::Matrix3d>(3, Eigen::Matrix3d::Identity())).relative;
  }
  const control::LimbSolution at = ik.solve(pose, goal, start);
  goal.position = next;
  const control::LimbSolution then = ik.solve(pose, goal, at.relative, 10);
  std::vector<Eigen::Matrix3d> relative = model_.relative_rotations(pose);
  const auto& joints = ik.joints();
  for (size_t k = 0; k < joints.size(); ++k) relative[joints[k].body] = at.relative[k];
  const control::BodyPose wanted = model_.forward(relative);
  // From the T-pose the arm comes to its first goal over `settle_s` (a step of its targets swings
  // it so hard that the pelvis turns by half a radian).
  const double settled = control::minimum_jerk(clock_s_ / p_.settle_s);
  for (size_t k = 0; k < joints.size(); ++k) {
    const int b = joints[k].body;
    const Eigen::Matrix3d target =
        control::exp_rotation(settled * control::log_rotation(at.relative[k]));
    const Eigen::Vector3d velocity =
        settled * control::log_rotation(then.relative[k] * at.relative[k].transpose()) / dt;
    const Eigen::Vector3d held = p_.gravity_scale * model_.gravity_torque(wanted, b);
    control::write_joint(action, b, control::drive_target(model_.body(b), target, held, velocity));
  }
}

void BasketballDribble::drive(const control::BodyPose& pose, const Eigen::Vector3d& seen_ball,
                              const Eigen::Vector3d& seen_velocity, double floor, double dt,
                              std::span<float> action) {
  // Plan in the feet's frame: the pelvis, whose heading the observation's frame follows, turns
  // on the legs by a few tenths of a radian as the arms move, the feet do not.
  const Eigen::Vector3d left = pose.position[kLeftAnkle], right = pose.position[kRightAnkle];
  const Eigen::Vector3d feet_origin(0.5 * (left.x() + right.x()), 0.5 * (left.y() + right.y()), 0);
  const double feet_yaw = std::atan2(-(left - right).x(), (left - right).y());
  const Eigen::Matrix3d to_heading =
      Eigen::AngleAxisd(feet_yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d ball = to_heading.transpose() * (seen_ball - feet_origin);
  const Eigen::Vector3d ball_velocity = to_heading.transpose() * seen_velocity;
  auto heading_point = [&](const Eigen::Vector3d& feet_point) -> Eigen::Vector3d {
    return feet_origin + to_heading * feet_point;
  };
  const std::optional<Meeting> meeting = next_meeting(ball, ball_velocity, floor);
  // Off the floor and rising: how high it will get says how hard the last push was.
  const bool rising = ball_velocity.z() > 0;
  if (rising && !ball_was_rising_ && ball.z() < floor + 0.4) adapt_pending_ = bounced_once_ = true;
  ball_was_rising_ = rising;
  if (adapt_pending_ && meeting && count_.strokes > 0) {
    // The apex of the ball's path from here, just off the floor.
    double apex = ball.z(), vz = ball_velocity.z();
    apex += vz * vz / (2 * kGravity);  // drag's share over 0.8 m is a few millimetres
    push_speed_ = std::clamp(push_speed_ + p_.apex_gain * (floor + p_.apex_wanted - apex),
                             p_.min_push, p_.max_push);
    adapt_pending_ = false;
  }
  const double t = stroke_from_ ? clock_s_ - *stroke_from_ : 0;
  const double quarter = p_.stroke_s / 4;
  if (stroke_from_ && t > p_.stroke_s) stroke_from_.reset();
  const double waiting_z = floor + p_.meet_height + kPalmOverBall;
  if (!bounced_once_) {
    // The presented ball is held in front of the body's middle, 0.55 m ahead of the root. The
    // palm reaches for its top (and stays 10-15 cm short: it is at the arm's reach) and, from
    // when it drops until its first bounce, dips in a stroke, again and again. Measured on the
    // tuning seeds, the dips leave the arm where it meets the ball after its bounce: 40 of 40
    // first dribbles, against 12 with one dip (docs/basketball.md, "The standing dribble").
    if (!stroke_from_ && ball_velocity.norm() > 0.1) {
      ++count_.strokes;
      stroke_from_ = clock_s_;
      const Eigen::Vector2d wanted = (p_.home - meet_xy_) / p_.first_return_s;
      sweep_ = ball_velocity.head<2>() + p_.steer * (wanted - ball_velocity.head<2>());
    } else if (!stroke_from_) {
      meet_xy_ = ball.head<2>();
      meet_z_ = ball.z() + kPalmOverBall;
      sweep_.setZero();
    }
  } else if (meeting && (!stroke_from_ || t < quarter) && meeting->in_s < quarter + dt) {
    // Time the stroke so that the palm meets the ball a quarter of the way in, at its fastest;
    // refined every tick until then.
    if (!stroke_from_) ++count_.strokes;
    stroke_from_ = clock_s_ + meeting->in_s - quarter;
    meet_xy_ = meeting->ball.head<2>();
    meet_z_ = meeting->ball.z() + kPalmOverBall;
    const Eigen::Vector2d wanted = (p_.home - meet_xy_) / p_.return_s;
    const Eigen::Vector2d incoming = meeting->velocity.head<2>();
    sweep_ = incoming + p_.steer * (wanted - incoming);
  } else if (!stroke_from_) {
    // Waiting: over where the ball will come up (or home).
    meet_xy_ = meeting ? Eigen::Vector2d(meeting->ball.head<2>()) : p_.home;
    meet_z_ = waiting_z;
    sweep_.setZero();
  }
  const double s = stroke_from_ ? clock_s_ - *stroke_from_ : 0;
  drive_arm(ik_, start_, pose, heading_point(palm_goal(s + dt)),
            heading_point(palm_goal(s + 2 * dt)), dt, action);
  // The other arm forward on its side, still (it also takes up the turn the right arm's swing
  // puts into the body).
  const Eigen::Vector3d other = heading_point({p_.home.x(), -p_.home.y(), waiting_z});
  drive_arm(left_ik_, left_start_, pose, other, other, dt, action);
  clock_s_ += dt;
}

void DribbleTally::tick(double height, double vz, double apart) {
  if (lost_) return;
  const bool floor = last_vz_ < 0 && vz >= 0 && height < 0.5;
  const bool push = vz < last_vz_ - 1.0 && height > 0.4;
  last_vz_ = vz;
  if (apart > kLostApart_m) lost_ = true;
  if (floor) {
    if (bounced_) lost_ = true;
    bounced_ = true;
  }
  if (push && bounced_) ++dribbles_, bounced_ = false;
}

void ScriptedDribbler::start(const MatchInfo& match) {
  if (match.sport != "basketball" || (match.mode != "1v1" && match.mode != "2v2"))
    throw std::invalid_argument("the scripted dribbler plays basketball 1v1 or 2v2, not " +
                                match.sport + " " + match.mode);
  ball_ = match.observation.offset("ball", "position");
  ball_velocity_ = match.observation.offset("ball", "velocity");
  control_dt_ = match.control_dt;
  dribble_.emplace(params_);
}

void ScriptedDribbler::act(std::span<const float> o, std::span<float> a) {
  if (!dribble_) throw std::logic_error("ScriptedDribbler: act() before start()");
  if (a.size() != smplx::kActions || o.size() < static_cast<size_t>(smplx::kSelfObservation))
    throw std::invalid_argument("the scripted dribbler plays the SMPL-X humanoid");
  std::fill(a.begin(), a.end(), 0.0f);
  const control::BodyPose pose = model_.pose_from_observation(o);
  // The trunk leaned forward (the arm reaches further), held against its weight.
  const Eigen::Matrix3d lean = control::from_euler_xyz({0, params_.trunk_lean / 3, 0});
  for (int b : {smplx::kTorso, smplx::kSpine, smplx::kChest})
    control::write_joint(
        a, b,
        control::drive_target(model_.body(b), lean,
                              control::kLoadedDriveSoftness * model_.gravity_torque(pose, b)));
  dribble_->drive(pose, smplx::vec3(o, ball_), smplx::vec3(o, ball_velocity_), -o[0], control_dt_,
                  a);
  control::StandingGains balance;
  balance.max_toes_down = params_.max_toes_down;
  control::hold_standing_balance(model_, pose, smplx::vec3(o, smplx::kLinVel), a, balance);
  // The fingers curled into a cup over the ball: its rim pushes an off-centre ball back under
  // the palm.
  for (int f = 0; f < smplx::kLinksBeforeThumb; ++f)
    smplx::set_joint(a, smplx::kRFingers + f, 0, params_.finger_curl);
}

}  // namespace olympics::client
