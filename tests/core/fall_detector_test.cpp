#include "core/fall_detector.h"

#include "core/rotation.h"
#include "test_support.h"

namespace olympics::core {
namespace {

TEST(FallDetector, StandingIsNotAFallLyingIs) {
  HumanoidScene scene;
  scene.add_humanoid(testing::smpl());
  FallDetector detector(testing::smpl());
  for (int t = 0; t < 6; ++t) {  // feet on the ground are allowed
    scene.tick();
    EXPECT_FALSE(detector.fallen(scene.humanoid(0))) << "tick " << t;
  }
  // Lay it on its back: the pelvis is below 0.15 m and the back touches the ground.
  Eigen::Quaterniond on_back(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()));
  scene.humanoid(0).reset({{0, 0, 0.12}, 0.0});
  for (int b = 0; b < scene.humanoid(0).body_count(); ++b) {
    dBodyID body = scene.humanoid(0).ode_body(b);
    const dReal* p = dBodyGetPosition(body);
    Eigen::Vector3d rotated = on_back * Eigen::Vector3d(p[0], p[1], p[2] - 0.12);
    dBodySetPosition(body, rotated.x(), rotated.y(), rotated.z() + 0.12);
    Eigen::Quaterniond q = on_back * from_ode_quat(dBodyGetQuaternion(body));
    dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
    dBodySetQuaternion(body, dq);
  }
  detector.reset();
  scene.tick();
  EXPECT_FALSE(detector.fallen(scene.humanoid(0)));  // the first two ticks are not checked
  scene.tick();
  EXPECT_FALSE(detector.fallen(scene.humanoid(0)));
  scene.tick();
  EXPECT_TRUE(detector.fallen(scene.humanoid(0)));
  EXPECT_FALSE(detector.culprit().empty());
}

TEST(FallDetector, EquipmentHandMayTouchTheGround) {
  HumanoidScene scene;
  // The right hand pinned below 0.15 m: a fall, unless that hand holds equipment.
  FallDetector with_hand(testing::smpl(), {"R_Hand"});
  FallDetector without(testing::smpl());
  scene.add_humanoid(testing::smpl());
  dBodyID hand = scene.humanoid(0).ode_body(testing::smpl().body_index("R_Hand"));
  for (int t = 0; t < 3; ++t) {
    const dReal* p = dBodyGetPosition(hand);
    dBodySetPosition(hand, p[0], p[1], 0.05);  // hand pinned below 0.15 m
    scene.tick();
    dBodySetPosition(hand, p[0], p[1], 0.05);
    bool a = with_hand.fallen(scene.humanoid(0));
    scene.humanoid(0).clear_ground_contacts();
    bool b = without.fallen(scene.humanoid(0));
    if (t == 2) {
      EXPECT_FALSE(a);
      EXPECT_TRUE(b);
      EXPECT_EQ(without.culprit(), "R_Hand");
    }
  }
}

}  // namespace
}  // namespace olympics::core
