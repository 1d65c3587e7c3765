// The humanoid's blocks come from its loaded model, and the self observation's fields are
// described once: the server writes them by that description and the clients' helpers read
// them by it.
#include <gtest/gtest.h>

#include <random>

#include "core/humanoid_assets.h"
#include "core/humanoid_scene.h"
#include "core/rotation.h"
#include "core/self_observation.h"
#include "core/self_observation_layout.h"
#include "registry.h"
#include "smpl_observation.h"
#include "smplx_observation.h"

namespace olympics::sports {
namespace {

TEST(ObservationLayout, TheHumanoidsBlocksComeFromItsLoadedModel) {
  for (const auto kind : {core::HumanoidKind::Smpl, core::HumanoidKind::SmplX}) {
    const core::ModelSpec model = core::load_humanoid(kind);
    const int bodies = static_cast<int>(model.bodies.size());
    const LayoutBlock self = self_observation_block(kind);
    EXPECT_EQ(self.size, core::self_observation_size(bodies));
    EXPECT_EQ(joint_targets_block(kind).size, model.dof_count());
    // The fields tile the block in order.
    int at = 0;
    for (const auto& f : self.fields) {
      EXPECT_EQ(f.offset, at) << f.name;
      at += f.size;
    }
    EXPECT_EQ(at, self.size);
  }
  EXPECT_EQ(self_observation_block(core::HumanoidKind::Smpl).size, 358);
  EXPECT_EQ(joint_targets_block(core::HumanoidKind::Smpl).size, 69);
  EXPECT_EQ(self_observation_block(core::HumanoidKind::SmplX).size, 778);
  EXPECT_EQ(joint_targets_block(core::HumanoidKind::SmplX).size, 153);
}

TEST(ObservationLayout, TheServerWritesEachFieldWhereTheDescriptionSaysItIs) {
  core::HumanoidScene scene;
  scene.add_humanoid(core::load_humanoid(core::HumanoidKind::Smpl), {{1, 2, 0}, 0.7});
  std::mt19937_64 rng(5);
  std::vector<float> action(69);
  for (int tick = 0; tick < 10; ++tick) {  // moving, turned: every field non-trivial
    for (auto& a : action) a = std::uniform_real_distribution<float>(-0.3f, 0.3f)(rng);
    scene.set_action(0, action);
    scene.tick();
  }
  const auto bodies = scene.humanoid(0).body_states();
  std::vector<float> obs(358);
  core::write_self_observation(bodies, obs);
  const core::SelfObservationLayout at = core::SelfObservationLayout::for_size(358);
  const Eigen::Quaterniond heading_inv = core::inverse_heading(bodies[0].orientation);
  auto read = [&](int k) { return Eigen::Vector3d(obs[k], obs[k + 1], obs[k + 2]); };
  // What the server writes there: the value in the heading frame, clamped to +-5.
  auto heading = [&](const Eigen::Vector3d& v) -> Eigen::Vector3d {
    return (heading_inv * v).cwiseMax(-core::kObservationClamp).cwiseMin(core::kObservationClamp);
  };
  EXPECT_NEAR(obs[at.root_height()], bodies[0].position.z(), 1e-5);
  const int hand = client::smpl::kRHand;
  EXPECT_TRUE(read(at.body_position(hand))
                  .isApprox(heading(bodies[hand].position - bodies[0].position), 1e-5));
  EXPECT_TRUE(
      read(at.body_rotation(hand))
          .isApprox(heading_inv * bodies[hand].orientation * Eigen::Vector3d::UnitX(), 1e-5));
  EXPECT_TRUE(read(at.linear_velocity(0)).isApprox(heading(bodies[0].linear_velocity), 1e-5));
  EXPECT_TRUE(
      read(at.angular_velocity(hand)).isApprox(heading(bodies[hand].angular_velocity), 1e-5));
  // The clients' helpers read the same places.
  EXPECT_TRUE(client::smpl::body_position(obs, hand).isApprox(read(at.body_position(hand))));
  EXPECT_TRUE(client::smpl::root_velocity(obs).isApprox(read(at.linear_velocity(0))));
}

TEST(ObservationLayout, TheClientsHumanoidsAreTheOnesEverySportAnnounces) {
  for (const auto& name : sport_names()) {
    const Sport& sport = sport_or_throw(name);
    for (const auto& mode : sport.modes().names()) {
      const Layout l = sport.layout(mode);
      const LayoutBlock& self = l.observation.front();
      ASSERT_EQ(self.name, kSelfBlock);
      const auto at = core::SelfObservationLayout::for_size(self.size);
      ASSERT_EQ(self.fields.size(), at.fields().size());
      for (size_t i = 0; i < self.fields.size(); ++i) {
        EXPECT_EQ(self.fields[i].name, at.fields()[i].name);
        EXPECT_EQ(self.fields[i].offset, at.fields()[i].offset);
      }
      if (name == "basketball" || name == "javelin") {  // the sports of the SMPL-X (fingers)
        EXPECT_EQ(self.size, client::smplx::kSelfObservation) << mode;
        EXPECT_EQ(l.action_size(), client::smplx::kActions) << mode;
      } else {
        EXPECT_EQ(self.size, client::smpl::kSelfObservation) << name << " " << mode;
        EXPECT_EQ(l.action_size(), client::smpl::kActions) << name << " " << mode;
      }
    }
  }
}

TEST(ObservationLayout, ASizeNoHumanoidHasAndAnUnknownFieldAreRefusedByName) {
  try {
    core::SelfObservationLayout::for_size(357);
    FAIL() << "357 floats accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("357"), std::string::npos) << e.what();
  }
  try {
    core::SelfObservationLayout{24}.field("joint_angles");
    FAIL() << "an unknown field accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("body_rotations"), std::string::npos) << e.what();
  }
  EXPECT_EQ(core::SelfObservationLayout{24}.field("linear_velocities").offset, 214);
}

}  // namespace
}  // namespace olympics::sports
