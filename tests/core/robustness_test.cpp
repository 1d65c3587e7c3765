// The physics survives whatever a policy sends, and bodies collide.
#include <cfloat>
#include <cmath>

#include "test_support.h"

namespace olympics::core {
namespace {

struct Extremes {
  double max_linear = 0, max_angular = 0;
  bool finite = true;
};

Extremes extremes(const Humanoid& h) {
  Extremes e;
  for (const auto& s : h.body_states()) {
    e.finite = e.finite && s.position.allFinite() && s.linear_velocity.allFinite() &&
               s.angular_velocity.allFinite() && s.orientation.coeffs().allFinite();
    e.max_linear = std::max(e.max_linear, s.linear_velocity.norm());
    e.max_angular = std::max(e.max_angular, s.angular_velocity.norm());
  }
  return e;
}

// Runaway bounds: a body flung at 50 m/s or spun at 400 rad/s means the solver lost control.
// Measured peaks of these runs (random targets jumping by up to pi every tick, docs/physics.md):
// SMPL 24 m/s and 82 rad/s (hands), SMPL-X 38 m/s and 197 rad/s (fingertips).
constexpr double kMaxLinear = 50, kMaxAngular = 400;

void expect_sane(const HumanoidScene& scene, int tick) {
  for (int i = 0; i < scene.humanoid_count(); ++i) {
    Extremes e = extremes(scene.humanoid(i));
    ASSERT_TRUE(e.finite) << "humanoid " << i << " tick " << tick;
    ASSERT_LT(e.max_linear, kMaxLinear) << "humanoid " << i << " tick " << tick;
    ASSERT_LT(e.max_angular, kMaxAngular) << "humanoid " << i << " tick " << tick;
  }
}

TEST(Robustness, RandomActionsForSixtySecondsStayFiniteAndBounded) {
  for (const ModelSpec* spec : {&testing::smpl(), &testing::smplx()}) {
    HumanoidScene scene;
    scene.add_humanoid(*spec, {{0, 0, 0}, 0.0});
    scene.add_humanoid(*spec, {{1.0, 0, 0}, M_PI});
    std::mt19937 rng(1);
    const int dof = scene.humanoid(0).dof_count();
    for (int tick = 0; tick < 60 * 30; ++tick) {
      for (int i = 0; i < 2; ++i) scene.set_action(i, testing::random_action(rng, dof));
      scene.tick();
      expect_sane(scene, tick);
    }
  }
}

TEST(Robustness, AnyFiniteActionHoweverLargeIsSurvived) {
  for (float magnitude : {10.0f, 1e4f, 1e12f, FLT_MAX}) {
    HumanoidScene scene;
    scene.add_humanoid(testing::smpl());
    std::mt19937 rng(3);
    for (int tick = 0; tick < 5 * 30; ++tick) {
      std::vector<float> a = testing::random_action(rng, 69, 1.0f);
      for (auto& x : a) x = x > 0 ? magnitude : -magnitude;
      scene.set_action(0, a);
      scene.tick();
      expect_sane(scene, tick);
    }
  }
}

TEST(Robustness, TwoHumanoidsCollideWithEachOther) {
  // B is dropped onto A's head: with contacts between them it rests on A, without it falls through.
  HumanoidScene scene;
  scene.add_humanoid(testing::smpl(), {{0, 0, 0}, 0.0});
  scene.add_humanoid(testing::smpl(), {{0, 0, 2.9}, 0.0});
  int touching_ticks = 0;
  for (int tick = 0; tick < 18; ++tick) {  // 0.6 s: free fall would take B 1.8 m down
    scene.tick();
    touching_ticks += scene.world().last_inter_entity_contact_count() > 0;
  }
  EXPECT_GT(touching_ticks, 0);
  EXPECT_GT(scene.humanoid(1).body_state(0).position.z(), 1.6);  // still above A's head
}

TEST(Robustness, HumanoidLandsOnTheGroundAndDoesNotSinkThrough) {
  HumanoidScene scene;
  scene.add_humanoid(testing::smpl(), {{0, 0, 2.0}, 0.0});
  for (int tick = 0; tick < 90; ++tick) scene.tick();
  for (const auto& s : scene.humanoid(0).body_states()) EXPECT_GT(s.position.z(), -0.02);
}

}  // namespace
}  // namespace olympics::core
