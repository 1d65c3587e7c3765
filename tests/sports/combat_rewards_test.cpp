// Fencing's and boxing's reward terms (the seed's eq. 9-10) on states built by hand.
#include "combat/combat_rewards.h"

#include <gtest/gtest.h>

#include <cmath>

namespace olympics::sports::combat {
namespace {

core::BodyState root_at(const Eigen::Vector3d& p, double yaw, const Eigen::Vector3d& v) {
  return {p, Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())), v,
          Eigen::Vector3d::Zero()};
}

TEST(CombatRewards, FacingVelocityStrikeAndPointByHand) {
  CombatRewardInput in;
  in.root = root_at({0, 0, 0.9}, 0, {0.5, 0, 0});
  in.opponent_root = {3, 0, 0.9};
  in.strikers = {{1.0, 0.2, 1.2}};
  in.targets = {{1.3, 0.2, 1.2}, {2.9, 0, 1.0}};
  auto t = combat_reward_terms(in);
  EXPECT_FLOAT_EQ(t[kFacing], 1.0f) << "facing it squarely";
  // 0.5 m/s towards it: exp(-4 (1 - 0.5)^2) = exp(-1)
  EXPECT_NEAR(t[kVelocity], std::exp(-1.0), 1e-6);
  // the nearer target 0.3 m away: exp(-10 * 0.09)
  EXPECT_NEAR(t[kStrike], std::exp(-0.9), 1e-6);
  EXPECT_FLOAT_EQ(t[kPoint], 0.0f);

  // Turned 90 degrees away (facing +y with the opponent at +x): d_x = 0, exp(-2).
  in.root = root_at({0, 0, 0.9}, M_PI / 2, {2.0, 0, 0});
  in.scored = true;
  t = combat_reward_terms(in);
  EXPECT_NEAR(t[kFacing], std::exp(-2.0), 1e-6);
  EXPECT_FLOAT_EQ(t[kVelocity], 1.0f) << "faster than 1 m/s towards it";
  EXPECT_FLOAT_EQ(t[kPoint], 1.0f);

  // Moving away earns nothing; a second striker nearer a target counts.
  in.root = root_at({0, 0, 0.9}, 0, {-1, 0, 0});
  in.strikers.push_back({2.9, 0.1, 1.0});
  t = combat_reward_terms(in);
  EXPECT_FLOAT_EQ(t[kVelocity], 0.0f);
  EXPECT_NEAR(t[kStrike], std::exp(-10 * 0.01), 1e-6);
}

TEST(CombatRewards, TheWeightsAreTheSeeds) {
  const auto terms = combat_rewards("the tip");
  ASSERT_EQ(terms.size(), 4u);
  EXPECT_EQ(terms[0].name, "facing");
  EXPECT_DOUBLE_EQ(terms[0].weight, 0.1);
  EXPECT_DOUBLE_EQ(terms[1].weight, 0.1);
  EXPECT_DOUBLE_EQ(terms[2].weight, 0.6);
  EXPECT_DOUBLE_EQ(terms[3].weight, 1.0);
}

}  // namespace
}  // namespace olympics::sports::combat
