// Per-surface contact softness: a geom that declares its own spring and damper (a landing mat,
// a sand pit) gives under a body that lands on it, while every other contact keeps the world's
// stiff contact, to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/physics_world.h"

namespace olympics::core {
namespace {

constexpr double kDt = 1.0 / 120;
constexpr double kRadius = 0.1;
// A foam mat: 1 cm of give under a 10 kg ball at rest, damped past critical.
const ContactSoftness kMat{10000.0, 800.0};

struct Ball {
  dBodyID body;
  GeomTag tag;
  Ball(PhysicsWorld& world, const Eigen::Vector3d& at) {
    body = dBodyCreate(world.world());
    dMass m;
    dMassSetSphereTotal(&m, 10.0, kRadius);
    dBodySetMass(body, &m);
    dBodySetPosition(body, at.x(), at.y(), at.z());
    dGeomID g = dCreateSphere(world.space(), kRadius);
    dGeomSetBody(g, body);
    tag.entity = 0, tag.body = 0, tag.geom = 0;
    dGeomSetData(g, &tag);
  }
  Eigen::Vector3d position() const {
    const dReal* p = dBodyGetPosition(body);
    return {p[0], p[1], p[2]};
  }
  double vz() const { return dBodyGetLinearVel(body)[2]; }
};

// What a drop from 0.5 m onto a surface whose top is at `top` did: how far the ball's bottom went
// below the top, and its largest deceleration (m/s^2).
struct Drop {
  double sink = 0;
  double peak_deceleration = 0;
};

Drop drop(PhysicsWorld& world, Ball& ball, double top) {
  Drop d;
  double vz = ball.vz();
  for (int i = 0; i < 240; ++i) {
    world.step(kDt);
    d.sink = std::max(d.sink, top - (ball.position().z() - kRadius));
    d.peak_deceleration = std::max(d.peak_deceleration, (ball.vz() - vz) / kDt);
    vz = ball.vz();
  }
  return d;
}

TEST(ContactSoftness, ErpAndCfmAreTheSpringDampersForTheStep) {
  const ContactSoftness s{2500.0, 300.0};
  EXPECT_NEAR(s.erp(kDt), kDt * 2500 / (kDt * 2500 + 300), 1e-15);
  EXPECT_NEAR(s.cfm(kDt), 1 / (kDt * 2500 + 300), 1e-15);
}

TEST(ContactSoftness, ABodyDroppedOnASoftMatSinksAndSlowsMoreThanOnTheGround) {
  const double mat_top = 0.3;
  PhysicsWorld on_ground, on_mat;
  on_ground.add_entity([](int, int) { return true; });
  on_mat.add_entity([](int, int) { return true; });
  dGeomID mat = on_mat.add_static_box({0, 0, mat_top / 2}, {2, 2, mat_top / 2}, 1.0, 0.0);
  PhysicsWorld::tag_of(mat).softness = kMat;
  Ball a(on_ground, {0, 0, kRadius + 0.5});
  Ball b(on_mat, {0, 0, mat_top + kRadius + 0.5});
  const Drop ground = drop(on_ground, a, 0.0);
  const Drop soft = drop(on_mat, b, mat_top);
  EXPECT_LT(ground.sink, 0.01) << "the ground stays stiff";
  EXPECT_GT(soft.sink, 0.03) << "the mat gives";
  EXPECT_LT(soft.sink, 0.2) << "and holds the ball up";
  EXPECT_LT(soft.peak_deceleration, 0.5 * ground.peak_deceleration)
      << "the mat slows the landing over a longer way";
  EXPECT_NEAR(b.vz(), 0.0, 0.05) << "and comes to rest on it";
}

TEST(ContactSoftness, ContactsAwayFromTheSoftSurfaceAreBitIdentical) {
  PhysicsWorld plain, with_mat;
  plain.add_entity([](int, int) { return true; });
  with_mat.add_entity([](int, int) { return true; });
  dGeomID mat = with_mat.add_static_box({5, 0, 0.15}, {1, 1, 0.15}, 1.0, 0.0);
  PhysicsWorld::tag_of(mat).softness = kMat;
  Ball a(plain, {0, 0, 1.0});
  Ball b(with_mat, {0, 0, 1.0});
  dBodySetLinearVel(a.body, 0.5, 0.2, 0);
  dBodySetLinearVel(b.body, 0.5, 0.2, 0);
  for (int i = 0; i < 240; ++i) {
    plain.step(kDt);
    with_mat.step(kDt);
    ASSERT_EQ(a.position(), b.position()) << "step " << i;
  }
}

TEST(ContactSoftness, OfTwoSoftSurfacesTheSofterHolds) {
  PhysicsWorld world;
  world.add_entity([](int, int) { return true; });
  dGeomID mat = world.add_static_box({0, 0, 0.15}, {2, 2, 0.15}, 1.0, 0.0);
  PhysicsWorld::tag_of(mat).softness = kMat;
  Ball ball(world, {0, 0, 0.3 + kRadius + 0.5});
  ball.tag.softness = ContactSoftness{1e7, 1e3};  // a hard ball on the mat: the mat yields
  EXPECT_GT(drop(world, ball, 0.3).sink, 0.03);
}

}  // namespace
}  // namespace olympics::core
