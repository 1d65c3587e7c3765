// The touch rule piece: a striking sensor geom on a target body of another team's player, with
// that contact's own force at or above the threshold, is a touch; the floor, non-target bodies,
// teammates and light contacts never are.
#include "framework/touch_sensor.h"

#include <gtest/gtest.h>

namespace olympics::sports {
namespace {

// A sphere body with a tagged geom, as a tip (sensor) or a body part.
struct Part {
  dBodyID body;
  core::GeomTag tag;
  Part(core::PhysicsWorld& world, const Eigen::Vector3d& at, double radius, int entity,
       int body_index, bool sensor) {
    body = dBodyCreate(world.world());
    dMass m;
    dMassSetSphereTotal(&m, 1.0, radius);
    dBodySetMass(body, &m);
    dBodySetPosition(body, at.x(), at.y(), at.z());
    dGeomID g = dCreateSphere(world.space(), radius);
    dGeomSetBody(g, body);
    tag.entity = entity, tag.body = body_index, tag.geom = 0, tag.sensor = sensor;
    dGeomSetData(g, &tag);
  }
  void hold() {
    dJointID j = dJointCreateFixed(dBodyGetWorld(body), nullptr);
    dJointAttach(j, body, nullptr);
    dJointSetFixed(j);
  }
};

// Entity i is slot i; slots 0 and 2 are teammates. Body 5 is a target, body 7 is not.
struct Arena {
  core::PhysicsWorld world{[] {
    core::WorldSettings s;
    s.gravity = 0;
    return s;
  }()};
  Arena() {
    for (int e = 0; e < 3; ++e) world.add_entity([](int, int) { return true; });
  }
  TouchSensor sensor(double min_force, double refractory = 0) {
    return TouchSensor(
        {0, 1, 2}, {0, 1, 0}, [](int body, int) { return body == 5; }, min_force, refractory);
  }
  // Pushes `tip` into its target along +x with `force` for `steps`; the touches of each step.
  std::vector<std::vector<Touch>> press(Part& tip, TouchSensor& sensor, double force, int steps) {
    std::vector<std::vector<Touch>> out;
    for (int i = 0; i < steps; ++i) {
      dBodyAddForce(tip.body, force, 0, 0);
      world.step(1.0 / 120);
      out.push_back(sensor.collect(world, (i + 1) / 120.0));
    }
    return out;
  }
};

TEST(TouchSensor, ATipOnATargetOfTheOtherTeamIsATouchWithItsForce) {
  Arena a;
  Part target(a.world, {0.3, 0, 1}, 0.1, 1, 5, false);
  target.hold();
  Part tip(a.world, {0.19, 0, 1}, 0.01, 0, 23, true);
  auto sensor = a.sensor(50);
  auto steps = a.press(tip, sensor, 100, 60);
  int touches = 0;
  for (const auto& s : steps)
    for (const auto& t : s) {
      ++touches;
      EXPECT_EQ(t.attacker, 0);
      EXPECT_EQ(t.defender, 1);
      EXPECT_EQ(t.target_body, 5);
      EXPECT_EQ(t.striker_body, 23);
      EXPECT_GE(t.force, 50);
    }
  EXPECT_GT(touches, 0);
  EXPECT_NEAR(steps.back().front().force, 100, 10) << "the push, measured within 10%";
}

TEST(TouchSensor, TheFloorANonTargetATeammateAndALightContactNeverCount) {
  {  // the floor: gravity presses a heavy tip onto the ground plane
    core::PhysicsWorld world;
    for (int e = 0; e < 2; ++e) world.add_entity([](int, int) { return true; });
    Part tip(world, {0, 0, 0.01}, 0.01, 0, 23, true);
    dMass m;
    dMassSetSphereTotal(&m, 20.0, 0.01);  // 196 N on the floor
    dBodySetMass(tip.body, &m);
    TouchSensor sensor(
        {0, 1}, {0, 1}, [](int, int) { return true; }, 50, 0);
    for (int i = 0; i < 60; ++i) {
      world.step(1.0 / 120);
      EXPECT_TRUE(sensor.collect(world, i / 120.0).empty());
    }
    ASSERT_FALSE(world.sensed_contacts().empty()) << "the contact was there, and heavy";
    EXPECT_GT(world.sensed_contacts()[0].normal_force, 150);
  }
  auto none = [](Arena& a, Part& tip, double force) {
    auto sensor = a.sensor(50);
    int touches = 0;
    for (const auto& s : a.press(tip, sensor, force, 60)) touches += static_cast<int>(s.size());
    return touches;
  };
  Arena non_target;
  Part arm(non_target.world, {0.3, 0, 1}, 0.1, 1, 7, false);
  arm.hold();
  Part tip1(non_target.world, {0.19, 0, 1}, 0.01, 0, 23, true);
  EXPECT_EQ(none(non_target, tip1, 200), 0) << "body 7 is not a target";
  Arena teammate;
  Part mate(teammate.world, {0.3, 0, 1}, 0.1, 2, 5, false);
  mate.hold();
  Part tip2(teammate.world, {0.19, 0, 1}, 0.01, 0, 23, true);
  EXPECT_EQ(none(teammate, tip2, 200), 0) << "slot 2 is on the tip's team";
  Arena light;
  Part target(light.world, {0.3, 0, 1}, 0.1, 1, 5, false);
  target.hold();
  Part tip3(light.world, {0.19, 0, 1}, 0.01, 0, 23, true);
  EXPECT_EQ(none(light, tip3, 20), 0) << "20 N is under the 50 N threshold";
}

TEST(TouchSensor, AStrikerHeldOnTheTargetTouchesOnceUntilItLetsGo) {
  Arena a;
  Part target(a.world, {0.3, 0, 1}, 0.1, 1, 5, false);
  target.hold();
  Part tip(a.world, {0.19, 0, 1}, 0.01, 0, 23, true);
  auto sensor = a.sensor(50, /*refractory=*/0.3);
  int touches = 0;
  for (const auto& s : a.press(tip, sensor, 100, 120)) touches += static_cast<int>(s.size());
  EXPECT_EQ(touches, 1) << "one second pressed: one touch";
  sensor.reset();
  for (const auto& s : a.press(tip, sensor, 100, 2)) touches += static_cast<int>(s.size());
  EXPECT_EQ(touches, 2) << "after a reset (play restarted) it counts again";
}

}  // namespace
}  // namespace olympics::sports
