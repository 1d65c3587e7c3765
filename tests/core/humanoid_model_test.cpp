// The bundled humanoids and the public files users bring: sizes, masses, heights.
#include <ode/ode.h>

#include "core/mjcf_loader.h"
#include "test_support.h"

namespace olympics::core {
namespace {
using testing::fixture;
using testing::have_fixtures;

struct Measured {
  int bodies, dof;
  double mass, height;
};

Measured measure(const ModelSpec& spec) {
  PhysicsWorld world;
  Humanoid h(world, spec);
  return {h.body_count(), h.dof_count(), h.total_mass(), h.rest_height()};
}

TEST(HumanoidModel, SmplHas24Bodies69DofAndTheTableMassAndHeight) {
  Measured m = measure(testing::smpl());
  EXPECT_EQ(m.bodies, 24);
  EXPECT_EQ(m.dof, 69);
  EXPECT_NEAR(m.mass, 71.8, 0.3);      // HUMANOID.md: 71.8 kg derived
  EXPECT_NEAR(m.height, 1.716, 0.01);  // sole to top of the head box
}

TEST(HumanoidModel, SmplxHas52Bodies153DofAndTheTableMassAndHeight) {
  Measured m = measure(testing::smplx());
  EXPECT_EQ(m.bodies, 52);
  EXPECT_EQ(m.dof, 153);
  EXPECT_NEAR(m.mass, 73.56, 0.3);
  EXPECT_NEAR(m.height, 1.6706, 0.01);
}

TEST(HumanoidModel, SmplGainsComeFromTheAsset) {
  const ModelSpec& s = testing::smpl();
  const BodySpec& hip = s.bodies[s.body_index("L_Hip")];
  EXPECT_EQ(hip.hinges[0].kp, 800);
  EXPECT_EQ(hip.hinges[0].kd, 80);
  const BodySpec& chest = s.bodies[s.body_index("Chest")];
  EXPECT_EQ(chest.hinges[2].kp, 1000);
  EXPECT_EQ(s.hinge_names().front(), "L_Hip_x");
}

TEST(HumanoidModel, PublicSmplBoxingFileLoadsUpright) {
  if (!have_fixtures()) GTEST_SKIP() << "no ../shared/fixtures here";
  ModelSpec spec = load_mjcf_file(fixture("smpl_humanoid_neutral_boxing.xml"));
  Measured m = measure(spec);
  EXPECT_EQ(m.bodies, 24);
  EXPECT_EQ(m.dof, 69);
  EXPECT_GT(m.height, 1.6);  // z-up file: tall along z
  EXPECT_LT(m.height, 1.8);
}

TEST(HumanoidModel, PublicYUpSmplFileIsTurnedZUp) {
  if (!have_fixtures()) GTEST_SKIP() << "no ../shared/fixtures here";
  ModelSpec spec = load_mjcf_file(fixture("smpl_0_humanoid.xml"));
  Measured m = measure(spec);
  EXPECT_EQ(m.bodies, 24);
  EXPECT_EQ(m.dof, 69);
  EXPECT_NEAR(m.height, 1.716, 0.03);  // would be ~0.3 (body depth) if left y-up
  // The head ends up above the pelvis along +z.
  PhysicsWorld world;
  Humanoid h(world, spec);
  EXPECT_GT(h.body_state(spec.body_index("Head")).position.z(), h.body_state(0).position.z() + 0.4);
}

TEST(HumanoidModel, PublicSmplxFileLoadsWithGainsFromUserField) {
  if (!have_fixtures()) GTEST_SKIP() << "no ../shared/fixtures here";
  ModelSpec spec = load_mjcf_file(fixture("smplx_humanoid.xml"));
  Measured m = measure(spec);
  EXPECT_EQ(m.bodies, 52);
  EXPECT_EQ(m.dof, 153);
  EXPECT_NEAR(m.mass, 73.56, 0.3);
  EXPECT_NEAR(m.height, 1.6706, 0.02);
  const BodySpec& hip = spec.bodies[spec.body_index("L_Hip")];
  EXPECT_EQ(hip.hinges[0].kp, 250);
  EXPECT_EQ(hip.hinges[0].kd, 2.5);
  EXPECT_EQ(spec.contact_excludes.size(), 10u);
}

TEST(HumanoidModel, StandsOnTheGroundWhenPlacedAtStandingHeight) {
  HumanoidScene scene;
  int i = scene.add_humanoid(testing::smpl());
  double start = scene.humanoid(i).body_state(0).position.z();
  EXPECT_NEAR(start, 0.937, 0.02);  // pelvis origin above the soles (HUMANOID.md)
  for (int t = 0; t < 15; ++t) scene.tick();
  // Half a second later the feet carry it: it has not sunk into the ground.
  EXPECT_GT(scene.humanoid(i).body_state(0).position.z(), start - 0.05);
  EXPECT_GT(scene.world().last_contact_count(), 0);
}

}  // namespace
}  // namespace olympics::core
