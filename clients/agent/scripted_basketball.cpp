#include "scripted_basketball.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "control/minimum_jerk.h"
#include "smplx_observation.h"

namespace olympics::client {
namespace {

using namespace smplx;

// The palm boxes' centres in the wrist bodies' frames (HUMANOID-SMPLX.md).
const Eigen::Vector3d kLeftPalm(-.0031, .0523, -.0013), kRightPalm(-.0029, -.0537, -.0044);

// One arm's pose: turned `out` from the aim's bearing (outward positive), `elevation` above the
// horizontal, the forearm rolled by `roll` (palm up near pi), elbow and fingers bent up.
struct ArmPose {
  double out = M_PI / 2, elevation = 0, roll = 0, elbow = 0, wrist = 0, curl = 0;  // rest: T
};

ArmPose blend(const ArmPose& a, const ArmPose& b, double s) {
  s = control::minimum_jerk(s);
  auto mix = [s](double x, double y) { return x + s * (y - x); };
  return {mix(a.out, b.out),     mix(a.elevation, b.elevation), mix(a.roll, b.roll),
          mix(a.elbow, b.elbow), mix(a.wrist, b.wrist),         mix(a.curl, b.curl)};
}

// The shoulder's target Ry(b) Rz(c) (the joint's hinge order x, y, z) turns the arm forward and
// pitches it; the roll is the elbow's, about the forearm (a shoulder rolled by pi would sit on
// its hinge's +-180 degree limit). Pitching by Ry lowers the arm only once it points forward.
void set_arm(std::span<float> a, bool right, double aim, const ArmPose& p) {
  const double side = right ? 1 : -1;
  const int shoulder = right ? kRShoulder : kLShoulder;
  set_joint(a, shoulder, 1, -p.elevation);
  set_joint(a, shoulder, 2, side * M_PI / 2 + aim - side * p.out);
  const int elbow = right ? kRElbow : kLElbow;
  set_joint(a, elbow, 0, -side * p.elbow);
  set_joint(a, elbow, 1, -p.roll);
  set_joint(a, right ? kRWrist : kLWrist, 0, side * p.wrist);
  const int fingers = right ? kRFingers : kLFingers;
  for (int f = 0; f < kLinksBeforeThumb; ++f)  // the fingers, not the thumb
    set_joint(a, fingers + f, 0, side * p.curl);
}

// The swing whose ball leaves at `speed`, interpolated in the measured responses (ordered by
// speed, at least one); beyond their ends, the end (which flings the ball at its own speed).
SwingResponse swing_for_speed(const std::vector<SwingResponse>& swing, double speed) {
  assert(!swing.empty());
  if (speed <= swing.front().speed) return swing.front();
  for (size_t i = 1; i < swing.size(); ++i) {
    const SwingResponse &a = swing[i - 1], &b = swing[i];
    if (speed > b.speed) continue;
    const double s = (speed - a.speed) / (b.speed - a.speed);
    auto mix = [s](double x, double y) { return x + s * (y - x); };
    return {mix(a.elevation, b.elevation), speed, mix(a.ahead, b.ahead), mix(a.up, b.up)};
  }
  return swing.back();
}

}  // namespace

// The root held over the middle of the ankles by the ankles and hips (the stepping controller's
// standing strategy, for the SMPL-X observation and action).
void stand_on_ankles_and_hips(std::span<const float> o, std::span<float> a,
                              const FreeThrowShot& s) {
  const Eigen::Vector3d mid = 0.5 * (body_position(o, kLAnkle) + body_position(o, kRAnkle));
  const Eigen::Vector3d v = vec3(o, kLinVel);
  const double dx = -mid.x(), dy = -mid.y();
  for (int ankle : {kLAnkle, kRAnkle}) {
    set_joint(a, ankle, 1, s.ankle_bias + s.ankle_p * dx + s.ankle_d * v.x());
    set_joint(a, ankle, 0, -(s.ankle_p * dy + s.ankle_d * v.y()));
  }
  for (int hip : {kLHip, kRHip}) set_joint(a, hip, 1, s.hip_p * dx);
}

// The release point depends a little on the swing, the swing on the speed, the speed on the
// release point: a few rounds of that settle it. The release point is taken on the line from the
// ball to the rim (the swing's plane is turned to the root's bearing of the rim, plus
// `aim_offset`: a centimetre or two aside over the 0.45 m the swing carries the ball).
FreeThrowAim ScriptedBasketballPolicy::aim_for(std::span<const float> o) const {
  const Eigen::Vector3d ball = vec3(o, ball_), rim = vec3(o, rim_);
  const Eigen::Vector3d towards =
      Eigen::Vector3d(rim.x() - ball.x(), rim.y() - ball.y(), 0).normalized();
  FreeThrowAim aim;
  SwingResponse swing = shot_.swing.back();
  for (int round = 0; round < 4; ++round) {
    const Eigen::Vector3d release = ball + swing.ahead * towards + Eigen::Vector3d(0, 0, swing.up);
    aim.carry = (rim - release).head<2>().norm();
    aim.rise = rim.z() - release.z();
    aim.launch_speed =
        launch_speed_for(aim.carry, aim.rise, shot_.launch_elevation, shot_.ball_drag);
    swing = swing_for_speed(shot_.swing, aim.launch_speed > 0 ? aim.launch_speed : 1e9);
  }
  aim.elevation = std::isnan(shot_.fixed_elevation) ? swing.elevation : shot_.fixed_elevation;
  return aim;
}

// The long shot: for each measured row, the solution's speed at its launch angle from its
// release point; the collar bones' lift where the row's speed meets it (interpolated between
// rows; beyond the ends, the end).
FreeThrowAim ScriptedBasketballPolicy::long_aim_for(std::span<const float> o) const {
  const Eigen::Vector3d ball = vec3(o, ball_), rim = vec3(o, rim_);
  const Eigen::Vector3d towards =
      Eigen::Vector3d(rim.x() - ball.x(), rim.y() - ball.y(), 0).normalized();
  FreeThrowAim aim;
  aim.elevation = shot_.swing.back().elevation;
  double last_gap = 0;
  for (size_t i = 0; i < shot_.long_swing.size(); ++i) {
    const LongSwingResponse& row = shot_.long_swing[i];
    const Eigen::Vector3d release = ball + row.ahead * towards + Eigen::Vector3d(0, 0, row.up);
    const double carry = (rim - release).head<2>().norm(), rise = rim.z() - release.z();
    const double needed =
        launch_speed_for(carry, rise, row.launch_deg * M_PI / 180, shot_.ball_drag);
    const double gap = row.speed - (needed + shot_.long_speed_bias);  // > 0: this row flies long
    if (i == 0 || gap <= 0) {
      aim.thorax = row.thorax, aim.carry = carry, aim.rise = rise, aim.launch_speed = needed;
    } else {
      const LongSwingResponse& before = shot_.long_swing[i - 1];
      const double s = -last_gap / (gap - last_gap);
      aim.thorax = before.thorax + s * (row.thorax - before.thorax);
      aim.carry = carry, aim.rise = rise, aim.launch_speed = needed;
    }
    if (gap > 0) break;
    last_gap = gap;
  }
  return aim;
}

// The swing's turn that brings the predicted release speed to the solution's (see FreeThrowShot).
double ScriptedBasketballPolicy::release_trim(std::span<const float> o) const {
  // Heading frame, relative to the root: z is up.
  const Eigen::Vector3d ball = vec3(o, ball_), v = vec3(o, ball_velocity_), rim = vec3(o, rim_);
  const Eigen::Vector3d palms =
      0.5 * (body_position(o, kLWrist) + body_rotation(o, kLWrist) * kLeftPalm +
             body_position(o, kRWrist) + body_rotation(o, kRWrist) * kRightPalm);
  const Eigen::Vector3d towards =
      Eigen::Vector3d(rim.x() - ball.x(), rim.y() - ball.y(), 0).normalized();
  const Eigen::Vector3d from_palms = ball - palms;
  const std::array<double, 4> x = {v.head<2>().norm(), v.z(), from_palms.dot(towards),
                                   from_palms.z()};
  double predicted = shot_.trim_base;
  for (size_t i = 0; i < x.size(); ++i) predicted += shot_.trim_coef[i] * x[i];
  const double wanted = aim_.launch_speed + shot_.twist_speed * trunk_twist(clock_s_);
  return std::clamp((wanted - predicted) / shot_.trim_gain, shot_.trim_min, shot_.trim_max);
}

// The long shot's drives (see FreeThrowShot::swing_thorax): added to the set shot's targets.
void ScriptedBasketballPolicy::add_long_shot_drives(std::span<float> a, double t) const {
  const bool swinging = t >= shot_.shot_s;
  if (shot_.crouch_knee != 0 && t >= shot_.crouch_from_s) {
    const double s = control::minimum_jerk(
        std::clamp((t - shot_.crouch_from_s) / (shot_.shot_s - shot_.crouch_from_s), 0.0, 1.0));
    const double knee = swinging ? shot_.swing_knee : s * shot_.crouch_knee;
    for (int hip : {kLHip, kRHip}) {
      set_joint(a, hip, 1, joint_angle(a, hip, 1) - knee / 2);
      set_joint(a, hip + 1, 1, knee);
      set_joint(a, hip + 2, 1, joint_angle(a, hip + 2, 1) - knee / 2);
    }
  }
  if (!swinging) return;
  if (shot_.swing_trunk != 0)
    for (int link : {kTorso, kSpine, kChest})
      set_joint(a, link, 1, joint_angle(a, link, 1) - shot_.swing_trunk / 3);
  if (shot_.swing_yaw != 0)
    for (int link : {kTorso, kSpine, kChest})
      set_joint(a, link, 2, joint_angle(a, link, 2) + shot_.swing_yaw / 3);
  if (shot_.swing_thorax_yaw != 0)
    for (int thorax : {kLThorax, kRThorax})
      set_joint(a, thorax, 2, joint_angle(a, thorax, 2) + shot_.swing_thorax_yaw);
  const double lift = shot_.long_shot ? aim_.thorax : shot_.swing_thorax;
  if (lift != 0)
    for (int thorax : {kLThorax, kRThorax})
      set_joint(a, thorax, 1,
                joint_angle(a, thorax, 1) - lift -
                    (thorax == kRThorax ? 1 : -1) * shot_.swing_thorax_right);
}

double ScriptedBasketballPolicy::trunk_twist(double t) const {
  if (shot_.twist_gain == 0 || std::isnan(first_rim_bearing_)) return 0;
  const double s =
      std::clamp((t - shot_.twist_from_s) / (shot_.twist_until_s - shot_.twist_from_s), 0.0, 1.0);
  return control::minimum_jerk(s) *
         std::clamp(shot_.twist_gain * (first_rim_bearing_ - shot_.twist_to), -shot_.twist_max,
                    shot_.twist_max);
}

void ScriptedBasketballPolicy::start(const MatchInfo& match) {
  // In team play the team player starts a shot when the ball is presented to it at a restart.
  const bool shoots = match.mode == "free_throw" || match.mode == "1v1" || match.mode == "2v2";
  if (match.sport != "basketball" || !shoots)
    throw std::invalid_argument(
        "the scripted basketball shooter shoots in basketball free_throw, 1v1 or 2v2, not " +
        match.sport + " " + match.mode);
  ball_ = match.observation.offset("ball", "position");
  rim_ = match.observation.offset("rim", "centre");
  ball_velocity_ = match.observation.offset("ball", "velocity");
  swing_tick_ = 0;
  trim_ = 0;
  first_rim_bearing_ = NAN;
  aim_ = {};
  aimed_ = false;
  control_dt_ = match.control_dt;
  clock_s_ = 0;
}

void ScriptedBasketballPolicy::act(std::span<const float> o, std::span<float> a) {
  if (a.size() != kActions || o.size() < static_cast<size_t>(kSelfObservation))
    throw std::invalid_argument("the scripted basketball policy plays the SMPL-X humanoid");
  std::fill(a.begin(), a.end(), 0.0f);
  const Eigen::Vector3d rim = vec3(o, rim_);
  const double rim_bearing = std::atan2(rim.y(), rim.x());
  if (std::isnan(first_rim_bearing_)) first_rim_bearing_ = rim_bearing;
  double bearing = rim_bearing + (shot_.long_shot ? shot_.long_aim_offset : shot_.aim_offset);
  if (shot_.throw_ahead) bearing = shot_.long_aim_offset;
  const double t = clock_s_;
  const double twist = trunk_twist(t);
  for (int link : {kTorso, kSpine, kChest}) set_joint(a, link, 2, twist / 3);
  if (!std::isnan(shot_.cradle_bearing) && t < shot_.shot_s) bearing = shot_.cradle_bearing + twist;
  const ArmPose hold{shot_.hands_apart, shot_.hold_elevation, shot_.palm_roll,
                     shot_.hold_elbow,  shot_.wrist_up,       shot_.finger_curl};
  // The hands come forward low, under the presented ball, then rise to it.
  ArmPose low = hold;
  low.out = 0.35, low.elevation = hold.elevation - shot_.under, low.roll = 0.5 * hold.roll;
  ArmPose under = hold;
  under.elevation = hold.elevation - shot_.under;
  ArmPose pose;
  if (t < 0.25) {
    pose = blend(ArmPose{}, low, t / 0.25);
  } else if (t < 0.45) {
    pose = blend(low, under, (t - 0.25) / 0.2);
  } else if (t < shot_.shot_s) {
    pose = blend(under, hold, (t - 0.45) / 0.2);
  } else {
    if (!aimed_) aim_ = shot_.long_shot ? long_aim_for(o) : aim_for(o), aimed_ = true;
    if (shot_.throw_ahead) aim_.thorax = shot_.long_swing.back().thorax;
    pose = hold;
    pose.elevation = aim_.elevation;
    pose.elbow = shot_.shot_elbow;
    pose.curl = shot_.shot_curl;
    if (shot_.trim_tick > 0 && !shot_.long_shot && aim_.elevation >= shot_.trim_from_elevation) {
      pose.elevation -= shot_.trim_swing;
      if (++swing_tick_ >= shot_.trim_tick) pose.curl = shot_.trim_curl, bearing += shot_.trim_turn;
      if (swing_tick_ == shot_.trim_tick) trim_ = release_trim(o);
      pose.elevation += trim_;
    }
  }
  stand_on_ankles_and_hips(o, a, shot_);
  set_arm(a, false, bearing, pose);
  set_arm(a, true, bearing, pose);
  add_long_shot_drives(a, t);
  clock_s_ += control_dt_;
}

}  // namespace olympics::client
