#include "core/self_observation.h"

#include "test_support.h"

namespace olympics::core {
namespace {

std::vector<float> observe(const Humanoid& h) {
  std::vector<float> obs(self_observation_size(h.body_count()));
  write_self_observation(h.body_states(), obs);
  return obs;
}

TEST(SelfObservation, SizesAre358And778) {
  EXPECT_EQ(self_observation_size(24), 358);
  EXPECT_EQ(self_observation_size(52), 778);
  EXPECT_EQ(self_observation_names(testing::smpl()).size(), 358u);
  EXPECT_EQ(self_observation_names(testing::smplx()).size(), 778u);
}

TEST(SelfObservation, RestPoseValues) {
  PhysicsWorld world;
  Humanoid h(world, testing::smpl(), {{2, 3, 0}, 0.0});
  auto obs = observe(h);
  EXPECT_NEAR(obs[0], h.standing_root_height(), 1e-6);
  // L_Hip relative to the root is its offset from the asset.
  const auto& hip = testing::smpl().bodies[1];
  EXPECT_NEAR(obs[1], hip.pos.x(), 1e-6);
  EXPECT_NEAR(obs[3], hip.pos.z(), 1e-6);
  // Tan-norm of an unrotated body: x axis (1,0,0), z axis (0,0,1).
  const int rot = 1 + 3 * 23;
  EXPECT_NEAR(obs[rot + 0], 1, 1e-6);
  EXPECT_NEAR(obs[rot + 5], 1, 1e-6);
  for (int k = rot + 6 * 24; k < 358; ++k) EXPECT_EQ(obs[k], 0.0f);  // at rest
}

TEST(SelfObservation, InvariantToHeadingAndPosition) {
  PhysicsWorld w1, w2;
  Humanoid a(w1, testing::smpl(), {{0, 0, 0}, 0.0});
  Humanoid b(w2, testing::smpl(), {{5, -2, 0}, 2.0});
  auto oa = observe(a), ob = observe(b);
  for (size_t k = 0; k < oa.size(); ++k) EXPECT_NEAR(oa[k], ob[k], 1e-5) << k;
}

TEST(SelfObservation, ClampedToFive) {
  PhysicsWorld world;
  Humanoid h(world, testing::smpl());
  dBodySetLinearVel(h.ode_body(0), 40, -40, 0);
  auto obs = observe(h);
  const int linvel = 1 + 3 * 23 + 6 * 24;
  EXPECT_EQ(obs[linvel + 0], 5.0f);
  EXPECT_EQ(obs[linvel + 1], -5.0f);
  for (float v : obs) EXPECT_LE(std::abs(v), 5.0f);
}

}  // namespace
}  // namespace olympics::core
