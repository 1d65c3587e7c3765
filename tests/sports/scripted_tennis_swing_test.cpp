// The scripted tennis player's swing (clients/agent/scripted_tennis_swing.h): the arm's turn
// about the shoulder, and that it meets balls it can reach.
#include "scripted_tennis_swing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "control/ball_path.h"
#include "control/limb_control.h"
#include "control/smpl_limbs.h"
#include "core/control_rate.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "core/self_observation.h"
#include "equipment/equipment.h"
#include "racket/racket_equipment.h"
#include "registry.h"
#include "scripted_racket.h"
#include "scripted_racket_play.h"
#include "smpl_observation.h"
#include "step_controller.h"

namespace olympics::client {
namespace {

TEST(ScriptedTennisSwing, TurnsFromRestToTheContactRateAtContact) {
  const double rate = 10, back = 1.2, follow = 0.5;
  EXPECT_DOUBLE_EQ(swing_turn(-1.0, rate, back, follow).angle, -back);
  EXPECT_DOUBLE_EQ(swing_turn(-1.0, rate, back, follow).rate, 0);
  // It starts from rest 2 back / rate before contact, and reaches the ball at the contact rate.
  EXPECT_NEAR(swing_turn(-2 * back / rate + 1e-9, rate, back, follow).rate, 0, 1e-6);
  EXPECT_NEAR(swing_turn(0, rate, back, follow).angle, 0, 1e-12);
  EXPECT_NEAR(swing_turn(0, rate, back, follow).rate, rate, 1e-12);
  // The angle is the integral of the rate (a tick's steps, within a small fraction of a radian).
  double angle = -back;
  for (double tau = -0.3; tau < 0.1; tau += 0.001)
    angle += 0.001 * swing_turn(tau + 0.0005, rate, back, follow).rate;
  EXPECT_NEAR(angle, swing_turn(0.1, rate, back, follow).angle, 0.01);
  EXPECT_DOUBLE_EQ(swing_turn(0.2, rate, back, follow).angle, follow);
}

// Ball-return seeds (tuning seeds) whose first ball the player plans a stroke within reach for:
// of these 11 first balls the racket touched 1 (seed 87) with the swing solved by inverse
// kinematics every tick along the arc (the player before issue 29's fourth round), 4 with the arm
// turned in joint space.
TEST(ScriptedTennisSwing, TouchesFirstBallsItCanReach) {
  int touched = 0;
  for (std::uint64_t seed : {3, 11, 12, 21, 32, 77, 87, 90, 97, 99, 100}) {
    ScriptedRacketPlay play("tennis", {"ball_return", seed, 10.0, {}});
    bool over = false, touch = false;
    while (!play.over() && !over) {
      for (const auto& ev : play.tick()) {
        const std::string call = ev.value("call", "");
        if (call == "hit") touch = true;
        if (call == "return_in" || call == "point") over = true;
      }
    }
    touched += touch;
  }
  std::printf("first balls touched: %d of 11\n", touched);
  EXPECT_GE(touched, 3);
}

// A forehand swung in place by a humanoid standing still (stiff ankles), the tennis player's way
// (scripted_racket.cpp): the contact posture solved each tick for the face at the sweet spot, its
// normal ahead, the arm turned about the shoulder's vertical from rest at the backswing to the
// arc's rate at contact (driven `drive` times the planned rate, asked `lead` seconds ahead). The
// face's speed along the arc's tangent at contact over `face_speed`, and how far from the planned
// contact point it was then.
struct SwingAtContact {
  double speed_ratio = 0, off_m = 0;
};
SwingAtContact swing_in_place(double face_speed, double drive = 1.3, double lead = 0.053) {
  const auto racket = sports::racket::tennis_racket();
  core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  sports::equipment::attach_equipment(spec, racket);
  const control::BodyModel model(spec);
  const control::LimbIk ik(model, control::smpl_right_arm(), racket.face_centre,
                           Eigen::Vector3d::UnitZ());
  core::HumanoidScene scene;
  scene.add_humanoid(spec, {{0, 0, 0}, 0});
  StepGains gains;
  gains.balance = {3, 2, 0, 1};
  StepController legs(gains, core::kControlDt);
  std::vector<float> obs(358), act(69);
  control::LimbGoal meet;
  meet.position = {0.55, -0.75, 0.25};
  meet.axis = {1, 0, 0};
  std::vector<Eigen::Matrix3d> posture;
  const double contact_s = 1.5;
  Eigen::Vector3d last_face = Eigen::Vector3d::Zero();
  SwingAtContact at;
  for (int tick = 0;; ++tick) {
    const double t = tick * core::kControlDt;
    const auto bodies = scene.humanoid(0).body_states();
    core::write_self_observation(bodies, obs);
    const control::BodyPose pose = model.pose_from_observation(obs);
    const Eigen::Vector3d face = pose.position[control::kSmplRHand] +
                                 pose.rotation[control::kSmplRHand] * racket.face_centre;
    Eigen::Vector3d radius = meet.position - pose.position[control::kSmplRShoulder];
    radius.z() = 0;
    const Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ().cross(radius).normalized();
    if (t >= contact_s) {
      at.speed_ratio = ((face - last_face) / core::kControlDt).dot(tangent) / face_speed;
      at.off_m = (face - meet.position).norm();
      return at;
    }
    last_face = face;
    std::fill(act.begin(), act.end(), 0.0f);
    legs.balance_centre_of_mass(model.centre_of_mass(pose), -0.03);
    legs.act(obs, {0, 0}, 0, act);
    control::hold_standing_legs(model, pose, act, 2);
    posture = ik.solve(pose, meet, posture, posture.empty() ? 40 : 10).relative;
    const SwingTurn turn =
        swing_turn(t + lead - contact_s, drive * face_speed / radius.norm(), 1.2, 0.5);
    drive_turned_arm(model, ik, pose, posture, turn, 2, act);
    static constexpr int kTrunk[] = {control::kSmplTorso, control::kSmplSpine, control::kSmplChest,
                                     control::kSmplRThorax};
    control::hold_against_gravity(model, pose, kTrunk, act, 2);
    smpl::set_joint(act, smpl::kLShoulder, 0, -1.2);
    scene.set_action(0, act);
    scene.tick();
  }
}

// Swung in place at the player's drive (1.3 times the planned rate, asked 0.053 s ahead), the
// arm overshoots the planned face speed: without the turn's load held the face met the contact
// point at a median 1.20 of the planned speed over 4-8 m/s (1.17-1.24), with it 1.15 (1.13-1.19).
// It comes 0.15-0.23 m from the contact point rather than 0.14-0.15 (docs/racket-sports.md,
// issue 29's arm round).
TEST(ScriptedTennisSwing, WithTheTurnsLoadHeldTheFaceOvershootsThePlannedSpeedLess) {
  std::vector<double> ratios;
  for (double speed : {4.0, 5.0, 6.0, 7.0, 8.0}) {
    const SwingAtContact at = swing_in_place(speed);
    std::printf("planned %.0f m/s: delivered %.3f of it, %.3f m off\n", speed, at.speed_ratio,
                at.off_m);
    ratios.push_back(at.speed_ratio);
  }
  std::sort(ratios.begin(), ratios.end());
  EXPECT_LT(ratios[2], 1.18);
  EXPECT_GT(ratios[2], 1.0);
}

}  // namespace
}  // namespace olympics::client
