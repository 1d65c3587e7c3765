// The control toolkit for scripted players (clients/agent/control): inverse kinematics reaches a
// racket pose, gravity compensation holds an outstretched racket arm, and the predicted ball path
// is the server's through a bounce.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "control/ball_path.h"
#include "control/body_model.h"
#include "control/drive_target.h"
#include "control/limb_control.h"
#include "control/smpl_limbs.h"
#include "control/stroke_plan.h"
#include "core/control_rate.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "core/rotation.h"
#include "core/self_observation.h"
#include "equipment/ball_flight.h"
#include "equipment/swept_ball.h"
#include "match_info.h"
#include "racket/racket_equipment.h"
#include "racket/racket_game.h"
#include "registry.h"
#include "smpl_observation.h"
#include "step_controller.h"

namespace olympics::client::control {
namespace {

const auto kRacket = sports::racket::tennis_racket();

// Random arm poses within the limits, through forward kinematics: reachable by construction.
TEST(LimbIk, ReachesReachableRacketPosesWithin1cmAnd3Degrees) {
  const BodyModel model = BodyModel::humanoid(core::HumanoidKind::Smpl, &kRacket);
  const LimbIk ik(model, smpl_right_arm(), kRacket.face_centre, Eigen::Vector3d::UnitZ());
  const BodyPose rest =
      model.forward(std::vector<Eigen::Matrix3d>(24, Eigen::Matrix3d::Identity()));
  std::mt19937 rng(7);
  int solved = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Eigen::Matrix3d> joints;
    for (const LimbJoint& j : ik.joints()) {
      Eigen::Vector3d a;
      // The middle half of each range: poses a racket player uses, not the joints' extremes.
      for (int k = 0; k < 3; ++k) {
        const double mid = 0.5 * (j.lo[k] + j.hi[k]), half = 0.25 * (j.hi[k] - j.lo[k]);
        a[k] = std::uniform_real_distribution<double>(mid - half, mid + half)(rng);
      }
      joints.push_back(from_euler_xyz(a));
    }
    LimbGoal goal;
    ik.end_of(rest, joints, goal.position, goal.axis);
    const LimbSolution s = ik.solve(rest, goal, {}, 60);
    EXPECT_LT(s.position_error_m, 0.01) << "trial " << trial;
    EXPECT_LT(s.axis_error_rad, 3 * M_PI / 180) << "trial " << trial;
    solved += s.position_error_m < 0.01 && s.axis_error_rad < 3 * M_PI / 180;
  }
  std::printf("solved %d of 50\n", solved);
}

// The largest distance (over seconds 1 to 4) between the racket face and where the arm was asked
// to hold it, for a humanoid standing with the arm out to its front right.
double held_face_error(bool compensate) {
  core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::Smpl);
  sports::equipment::attach_equipment(spec, kRacket);
  const BodyModel model(spec);
  LimbControl arm(model,
                  LimbIk(model, smpl_right_arm(), kRacket.face_centre, Eigen::Vector3d::UnitZ()));
  core::HumanoidScene scene;
  scene.add_humanoid(spec, {{0, 0, 0}, 0});
  StepGains gains;
  gains.balance = {3, 2, 0, 1};  // stiff ankles: the body stands still under the arm's load
  StepController legs(gains, core::kControlDt);
  std::vector<float> obs(358), act(69);
  LimbGoal goal;
  goal.position = {0.45, -0.5, 0.3};  // heading frame: ahead, right, near shoulder height
  goal.axis = {1, 0, 0};
  double worst = 0;
  for (int tick = 0; tick < 4 * 30; ++tick) {
    const auto bodies = scene.humanoid(0).body_states();
    core::write_self_observation(bodies, obs);
    const BodyPose pose = model.pose_from_observation(obs);
    if (tick >= 30) {
      const Eigen::Vector3d face =
          pose.position[kSmplRHand] + pose.rotation[kSmplRHand] * kRacket.face_centre;
      worst = std::max(worst, (face - goal.position).norm());
    }
    std::fill(act.begin(), act.end(), 0.0f);
    legs.balance_centre_of_mass(model.centre_of_mass(pose), -0.03);
    legs.act(obs, {0, 0}, 0, act);
    if (compensate) hold_standing_legs(model, pose, act);
    arm.drive(pose, goal, goal, core::kControlDt, act, compensate);
    static constexpr int kTrunk[] = {kSmplTorso, kSmplSpine, kSmplChest, kSmplRThorax};
    if (compensate) hold_against_gravity(model, pose, kTrunk, act);
    smpl::set_joint(act, smpl::kLShoulder, 0, -1.2);  // the free arm down
    scene.set_action(0, act);
    scene.tick();
  }
  return worst;
}

TEST(GravityCompensation, HoldsAnOutstretchedRacketArmWithin2cmFor3s) {
  const double with = held_face_error(true), without = held_face_error(false);
  std::printf("face error: %.1f mm compensated, %.1f mm without\n", 1000 * with, 1000 * without);
  EXPECT_LT(with, 0.02);
  EXPECT_GT(without, 2 * with) << "compensation should matter";
}

// A fed ball's path, predicted from the first observation, against the server's ball as the
// observations show it, through its bounce on the table or court.
double path_error(const std::string& sport, std::uint64_t seed, int* bounced) {
  auto match = sports::sport_or_throw(sport).create({"ball_return", seed, 30.0, {}});
  const auto layout = ObservationLayout::from_blocks(match->layout().observation);
  const int ball = layout.offset("ball_position", "position"),
            velocity = layout.offset("ball_velocity", "velocity"),
            court_x = layout.offset("court_position", "x"),
            court_y = layout.offset("court_position", "y"),
            heading_cos = layout.offset("court_heading", "cos"),
            heading_sin = layout.offset("court_heading", "sin"),
            bounces = layout.offset("rally", "bounces");
  std::vector<float> obs(match->obs_size()), zero(match->action_size(), 0.0f);
  auto frame_of = [&] {
    CourtFrame f;
    f.root = {obs[court_x], obs[court_y], client::smpl::root_height(obs)};
    f.yaw = std::atan2(obs[heading_sin], obs[heading_cos]);
    return f;
  };
  match->observe(0, obs);
  CourtFrame f = frame_of();
  const BallPath path(sport == "tennis" ? sports::racket::tennis_game(1.0)
                                        : sports::racket::table_tennis_game());
  const auto predicted =
      path.predict(f.point({obs[ball], obs[ball + 1], obs[ball + 2]}),
                   f.vector({obs[velocity], obs[velocity + 1], obs[velocity + 2]}), 3.0);
  double worst = 0;
  const int per_tick = static_cast<int>(std::lround(core::kControlDt / BallPath::kStep_s));
  for (int tick = 1; tick * per_tick <= static_cast<int>(predicted.size()); ++tick) {
    match->step({std::span<const float>(zero)});
    if (match->outcome().match_over) break;
    match->observe(0, obs);
    f = frame_of();
    const Eigen::Vector3d seen = f.point({obs[ball], obs[ball + 1], obs[ball + 2]});
    const BallSample& p = predicted[tick * per_tick - 1];
    if (p.own_bounces > 1 || p.other_bounces > 0) break;  // on to where the player stands
    if ((seen - f.root).head<2>().norm() < 1.0) break;    // the body may be in the way
    *bounced = std::max(*bounced, static_cast<int>(obs[bounces]));
    worst = std::max(worst, (seen - p.position).norm());
  }
  return worst;
}

TEST(BallPath, MatchesTheServersBallThroughABounceWithin1cm) {
  for (const std::string sport : {"table_tennis", "tennis"}) {
    int bounced = 0;
    double worst = 0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed)
      worst = std::max(worst, path_error(sport, seed, &bounced));
    std::printf("%s: worst %.2f mm\n", sport.c_str(), 1000 * worst);
    EXPECT_EQ(bounced, 1) << sport << ": the comparison should follow the ball past its bounce";
    EXPECT_LT(worst, 0.01) << sport;
  }
}

// The face motion solved for a wanted outgoing velocity gives it through the server's bounce.
TEST(StrokePlan, FaceMotionGivesTheWantedBallVelocity) {
  const Eigen::Vector3d in(-3, 0.2, 1.5), out(4, -0.3, 2.5);
  const FaceMotion f = face_motion_for(in, out, 0.85, 0.8);
  EXPECT_NEAR((f.ball_out - out).norm(), 0, 1e-4);
  EXPECT_NEAR(f.normal.norm(), 1, 1e-9);
  EXPECT_GT(f.normal.x(), 0);
}

// The planner's bounce is the server's: the face motion planned for a return, swept through the
// ball as the server's racket disc (sports/equipment/ball_flight.h) and met at the face's centre,
// sends the ball off at the planned velocity (issue 29: traced because the returns left the face
// with more sideways speed than the plan; the contact was not the cause, docs/racket-sports.md).
TEST(StrokePlan, TheServersRacketDiscGivesThePlannedBounce) {
  const auto game = sports::racket::tennis_game(1.0);
  const double e = game.equipment.restitution, mu = game.equipment.friction;
  const sports::equipment::Disc face = game.equipment.face;
  const double dt = 1.0 / 120, r = game.ball.radius;
  const Eigen::Vector3d in(-14, 1.5, 2), out(12, -2.5, 7);
  for (const Eigen::Vector3d& swing : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.8, 0.6, 0)}) {
    const FaceMotion f = face_motion_for(in, out, e, mu, swing);
    ASSERT_NEAR((f.ball_out - out).norm(), 0, 1e-4);
    // The ball's centre meets the face's centre half-way through a step, 1 m up.
    const Eigen::Vector3d meet(-11, 0, 1);
    const Eigen::Vector3d centre = meet - f.normal * (face.half_thickness + r);
    const Eigen::Vector3d face_velocity = f.speed * f.direction;
    const Eigen::Quaterniond facing =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), f.normal);
    sports::equipment::MovingDisc disc{0, face, {}, {}, e, mu};
    disc.from = {centre - 0.5 * dt * face_velocity, facing};
    disc.to = {centre + 0.5 * dt * face_velocity, facing};
    sports::equipment::BallFlight flight(game.ball, game.ball.restitution, game.ball.friction);
    flight.set_state(meet - 0.5 * dt * in, in);
    std::vector<sports::equipment::BallContact> contacts;
    flight.step(dt, {}, std::span(&disc, 1), contacts);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_EQ(contacts[0].kind, sports::equipment::SurfaceKind::Disc);
    EXPECT_GT(contacts[0].normal.dot(f.normal), std::cos(1 * M_PI / 180));  // a face hit
    // Within what gravity and drag change over the half step before the contact.
    EXPECT_LT((contacts[0].v_after - out).norm(), 0.1);
  }
}

// A bounced tennis ball met at the baseline: a face swung at 4 m/s (what the arm delivers) has a
// normal that returns it over the net into the far half, checked by stepping the server's own
// flight from the bounce; a face held still has none (the ball keeps too little of its speed).
TEST(StrokePlan, AtTheSpeedTheArmDeliversTheReturnLandsIn) {
  const BallPath path(sports::racket::tennis_game(1.0));
  const Eigen::Vector3d from(-11.5, -0.5, 1.0), in(-11, 1, 2);
  const Eigen::Vector3d face_velocity = 4 * Eigen::Vector3d(0.9, 0.44, 0).normalized();
  const auto shot = plan_shot_at_speed(path, from, in, face_velocity, {7.5, 0}, 0.3, 0.5);
  ASSERT_TRUE(shot.has_value());
  EXPECT_NEAR(shot->face.speed, 4, 1e-9);
  const double e = path.game().equipment.restitution, mu = path.game().equipment.friction;
  const Eigen::Vector3d out =
      sports::equipment::bounce(in, face_velocity, shot->face.normal, e, mu,
                                sports::equipment::BallFlight::kHollowBallRollingLoss);
  EXPECT_NEAR((out - shot->ball_out).norm(), 0, 1e-9);
  std::optional<Eigen::Vector3d> first_bounce;
  for (const BallSample& s : path.predict(from, out, 4.0))
    if (s.own_bounces + s.other_bounces > 0) {
      first_bounce = s.position;
      break;
    }
  ASSERT_TRUE(first_bounce.has_value()) << "the return never came down";
  EXPECT_GT(first_bounce->x(), 0.5) << "it should clear the net";
  EXPECT_LT(first_bounce->x(), path.game().half_length);
  EXPECT_LT(std::abs(first_bounce->y()), path.game().half_width(false));
  EXPECT_FALSE(
      plan_shot_at_speed(path, from, in, Eigen::Vector3d::Zero(), {7.5, 0}, 0.3, 0.5).has_value());
}

}  // namespace
}  // namespace olympics::client::control
