// Sensor geoms report each contact pair with the normal force the solver applied to that contact
// (ODE joint feedback): the figure fencing and boxing score touches by.
#include <gtest/gtest.h>

#include <memory>

#include "core/physics_world.h"

namespace olympics::core {
namespace {

// A free sphere with a tagged geom.
struct Probe {
  dBodyID body;
  GeomTag tag;
  Probe(PhysicsWorld& world, const Eigen::Vector3d& at, double radius, double mass, bool sensor,
        int entity = 1) {
    body = dBodyCreate(world.world());
    dMass m;
    dMassSetSphereTotal(&m, mass, radius);
    dBodySetMass(body, &m);
    dBodySetPosition(body, at.x(), at.y(), at.z());
    dGeomID g = dCreateSphere(world.space(), radius);
    dGeomSetBody(g, body);
    tag.entity = entity, tag.body = 0, tag.geom = 0, tag.sensor = sensor;
    dGeomSetData(g, &tag);
  }
};

const SensedContact* only_contact(const PhysicsWorld& world) {
  return world.sensed_contacts().size() == 1 ? &world.sensed_contacts()[0] : nullptr;
}

TEST(ContactSensor, WeightOnTheGroundIsMeasured) {
  PhysicsWorld world;
  world.add_entity([](int, int) { return true; });
  world.add_entity([](int, int) { return true; });
  const double mass = 2.0;
  Probe ball(world, {0, 0, 0.05}, 0.05, mass, /*sensor=*/true);
  for (int i = 0; i < 240; ++i) world.step(1.0 / 120);  // settle
  const SensedContact* c = only_contact(world);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->sensor, &ball.tag);
  EXPECT_EQ(c->other, nullptr) << "the ground has no tag";
  EXPECT_NEAR(c->normal.z(), 1.0, 1e-6) << "from the ground towards the sensor";
  EXPECT_NEAR(c->normal_force, mass * 9.81, 0.1 * mass * 9.81);
  EXPECT_NEAR(c->position.z(), 0.0, 0.01);
}

TEST(ContactSensor, AKnownPushOnATargetIsMeasuredWithinTenPercent) {
  for (double push : {10.0, 60.0, 300.0}) {
    WorldSettings settings;
    settings.gravity = 0;
    PhysicsWorld world(settings);
    world.add_entity([](int, int) { return true; });
    world.add_entity([](int, int) { return true; });
    world.add_entity([](int, int) { return true; });
    // The target: a heavy body held in place by a fixed joint, as a torso is held by its joints.
    Probe target(world, {0.3, 0, 1}, 0.1, 30.0, /*sensor=*/false, /*entity=*/2);
    target.tag.body = 11;
    dJointID hold = dJointCreateFixed(world.world(), nullptr);
    dJointAttach(hold, target.body, nullptr);
    dJointSetFixed(hold);
    Probe tip(world, {0.19, 0, 1}, 0.01, 0.05, /*sensor=*/true);
    for (int i = 0; i < 120; ++i) {
      dBodyAddForce(tip.body, push, 0, 0);
      world.step(1.0 / 120);
    }
    const SensedContact* c = only_contact(world);
    ASSERT_NE(c, nullptr) << push << " N";
    ASSERT_NE(c->other, nullptr);
    EXPECT_EQ(c->other->entity, 2);
    EXPECT_EQ(c->other->body, 11);
    EXPECT_NEAR(c->normal.x(), -1.0, 1e-3) << "from the target towards the tip";
    EXPECT_NEAR(c->normal_force, push, 0.1 * push) << push << " N";
  }
}

TEST(ContactSensor, OnlySensorGeomsAreReportedAndTwoSensorsBothSee) {
  PhysicsWorld world;
  for (int e = 0; e < 3; ++e) world.add_entity([](int, int) { return true; });
  Probe plain(world, {0, 0, 0.05}, 0.05, 1.0, /*sensor=*/false);
  for (int i = 0; i < 60; ++i) world.step(1.0 / 120);
  EXPECT_TRUE(world.sensed_contacts().empty()) << "a plain geom on the ground is not reported";

  WorldSettings settings;
  settings.gravity = 0;
  PhysicsWorld pair(settings);
  for (int e = 0; e < 3; ++e) pair.add_entity([](int, int) { return true; });
  Probe a(pair, {0, 0, 1}, 0.05, 1.0, true, 1), b(pair, {0.095, 0, 1}, 0.05, 1.0, true, 2);
  pair.step(1.0 / 120);
  ASSERT_EQ(pair.sensed_contacts().size(), 2u);
  const auto& first = pair.sensed_contacts()[0];
  const auto& second = pair.sensed_contacts()[1];
  EXPECT_EQ(first.other, second.sensor);
  EXPECT_EQ(second.other, first.sensor);
  EXPECT_NE(first.sensor, second.sensor);
  EXPECT_NEAR(first.normal.dot(second.normal), -1.0, 1e-9) << "each normal points to its sensor";
  EXPECT_DOUBLE_EQ(first.normal_force, second.normal_force);
}

}  // namespace
}  // namespace olympics::core
