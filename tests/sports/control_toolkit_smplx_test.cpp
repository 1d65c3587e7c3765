// The control toolkit on the SMPL-X humanoid (basketball's): the body's pose read from its 778
// float self observation agrees with the model's forward kinematics, joint targets go through
// SMPL-X's action scales, and inverse kinematics reaches palm poses with either arm.
#include <gtest/gtest.h>
#include <ode/ode.h>

#include <cmath>
#include <random>

#include "control/body_model.h"
#include "control/drive_target.h"
#include "control/limb_ik.h"
#include "control/smplx_limbs.h"
#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "core/self_observation.h"
#include "smplx_observation.h"

namespace olympics::client::control {
namespace {

TEST(SmplxBodyModel, PoseFromObservationAgreesWithForwardKinematics) {
  // Arms and fingers moved by random targets for a second, pelvis fixed: every body's observed
  // position is where the model's offsets and the observed rotations put it.
  const core::ModelSpec spec = core::load_humanoid(core::HumanoidKind::SmplX);
  const BodyModel model(spec);
  ASSERT_EQ(model.size(), smplx::kBodies);
  core::HumanoidScene scene;
  scene.add_humanoid(spec, {});
  core::Humanoid& h = scene.humanoid(0);
  dJointID fix = dJointCreateFixed(scene.world().world(), 0);
  dJointAttach(fix, h.ode_body(0), 0);
  dJointSetFixed(fix);
  std::mt19937 rng(3);
  std::vector<float> act(smplx::kActions), obs(smplx::kSelfObservation);
  for (float& a : act) a = std::uniform_real_distribution<float>(-0.3f, 0.3f)(rng);
  for (int tick = 0; tick < 30; ++tick) {
    scene.set_action(0, act);
    scene.tick();
  }
  core::write_self_observation(h.body_states(), obs);
  const BodyPose seen = model.pose_from_observation(obs);
  const BodyPose rebuilt = model.forward(model.relative_rotations(seen));
  double worst = 0;
  for (int b = 0; b < model.size(); ++b)
    worst = std::max(worst, (seen.position[b] - rebuilt.position[b]).norm());
  std::printf("largest body position difference: %.2f mm\n", 1000 * worst);
  EXPECT_LT(worst, 0.01);
}

TEST(SmplxBodyModel, JointTargetsRoundTripThroughTheSmplxActionScales) {
  // A hip (scaled by 1.2 x 90 degrees), a knee's flexion (by 5) and a shoulder (by pi).
  std::vector<float> act(smplx::kActions, 0.0f);
  const Eigen::Matrix3d r = from_euler_xyz({0.3, -0.5, 0.2});
  for (int body : {smplx::kLHip, smplx::kRShoulder}) {
    write_joint(act, body, r);
    EXPECT_LT((read_joint(act, body) - r).norm(), 1e-5) << "body " << body;
  }
  write_joint(act, smplx::kLHip, from_euler_xyz({0, 0.6, 0}));
  EXPECT_NEAR(act[3 * (smplx::kLHip - 1) + 1], 0.6 / (1.2 * M_PI / 2), 1e-6);
}

TEST(SmplxLimbIk, EitherArmReachesReachablePalmPosesWithin1cmAnd3Degrees) {
  const BodyModel model = BodyModel::humanoid(core::HumanoidKind::SmplX);
  const BodyPose rest =
      model.forward(std::vector<Eigen::Matrix3d>(model.size(), Eigen::Matrix3d::Identity()));
  std::mt19937 rng(7);
  for (const bool right : {false, true}) {
    const LimbIk ik(model, smplx_arm(right), smplx_palm_centre(right), smplx_palm_normal());
    int solved = 0;
    for (int trial = 0; trial < 30; ++trial) {
      std::vector<Eigen::Matrix3d> joints;
      for (const LimbJoint& j : ik.joints()) {
        Eigen::Vector3d a;
        for (int k = 0; k < 3; ++k) {
          const double mid = 0.5 * (j.lo[k] + j.hi[k]), half = 0.25 * (j.hi[k] - j.lo[k]);
          a[k] = std::uniform_real_distribution<double>(mid - half, mid + half)(rng);
        }
        joints.push_back(from_euler_xyz(a));
      }
      LimbGoal goal;
      ik.end_of(rest, joints, goal.position, goal.axis);
      goal.axis_either_sign = false;
      const LimbSolution s = ik.solve(rest, goal, {}, 60);
      solved += s.position_error_m < 0.01 && s.axis_error_rad < 3 * M_PI / 180;
    }
    std::printf("%s arm: solved %d of 30\n", right ? "right" : "left", solved);
    EXPECT_GE(solved, 29) << (right ? "right" : "left");
  }
}

}  // namespace
}  // namespace olympics::client::control
