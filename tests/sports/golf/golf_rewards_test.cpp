// The seed's golf reward terms (eqs. 4-6, as SMPLOlympics' compute_ball_reward has them), each by
// name, against values computed by hand.
#include "golf/golf_rewards.h"

#include <gtest/gtest.h>

#include <cmath>

namespace olympics::sports::golf {
namespace {

TEST(GolfRewards, TermsByName) {
  const auto terms = golf_rewards();
  ASSERT_EQ(terms.size(), 4u);
  EXPECT_EQ(terms[0].name, "contact");
  EXPECT_EQ(terms[1].name, "position");
  EXPECT_EQ(terms[2].name, "goal");
  EXPECT_EQ(terms[3].name, "landing");
  for (const auto& t : terms) EXPECT_EQ(t.weight, 1.0) << t.name << ": the code sums them";
}

TEST(GolfRewards, BeforeContactOnlyTheClubTerm) {
  GolfRewardState s;
  s.ball_prev = s.ball = {0, 0, 0.021};
  s.ball_velocity = {0, 0, 0};
  s.head = {0.1, 0.0, 0.021};  // 0.1 m from the ball: exp(-100 * 0.01) = e^-1
  s.target = {0, -5, 0};
  s.contact = false;
  const auto r = golf_reward_terms(s);
  EXPECT_NEAR(r[0], std::exp(-1.0), 1e-6);
  EXPECT_EQ(r[1], 0.0f);
  EXPECT_EQ(r[2], 0.0f);
  EXPECT_EQ(r[3], 0.0f);
}

TEST(GolfRewards, AfterContactTheBallTerms) {
  GolfRewardState s;
  s.ball_prev = {0, -1, 0.5};
  s.ball = {0, -1.3, 0.5};
  s.ball_velocity = {0, -4, 2.0};
  s.head = {5, 5, 5};  // far: contact already made, r_c = 1
  s.target = {0, -5, 0};
  s.contact = true;
  const auto r = golf_reward_terms(s);
  EXPECT_EQ(r[0], 1.0f);
  // r_p: |(0,-1,0.5)-(0,-5,0)| - |(0,-1.3,0.5)-(0,-5,0)| = sqrt(16.25) - sqrt(13.94).
  EXPECT_NEAR(r[1], std::sqrt(16.25) - std::sqrt(13.94), 1e-6);
  // r_g: exp(-0.1 * 3.7), the xy distance unsquared.
  EXPECT_NEAR(r[2], std::exp(-0.37), 1e-6);
  // r_land: t = (2*2 + sqrt(4*4 + 8*9.8*0.5)) / 19.6 = (4 + sqrt(55.2)) / 19.6; landing
  // y = -1.3 - 4 t; error |landing - (-5)|.
  const double t = (4 + std::sqrt(55.2)) / 19.6;
  const double land_y = -1.3 - 4 * t;
  EXPECT_NEAR(seed_landing_point(s.ball, s.ball_velocity).y(), land_y, 1e-12);
  EXPECT_NEAR(r[3], std::exp(-0.1 * std::abs(land_y + 5)), 1e-6);
}

TEST(GolfRewards, ProgressIsClampedAndAnImaginaryRootIsZero) {
  GolfRewardState s;
  s.ball_prev = {0, 0, 0.0};
  s.ball = {0, 3, -0.5};  // moved away (r_p clamps to 0) and below z = 0 (the root is imaginary)
  s.ball_velocity = {1, 0, 0.5};
  s.head = {0, 0, 0};
  s.target = {0, -5, 0};
  s.contact = true;
  const auto r = golf_reward_terms(s);
  EXPECT_EQ(r[1], 0.0f);
  // disc = 4*0.25 + 8*9.8*(-0.5) < 0 -> sqrt taken as 0; t = 2*0.5/19.6.
  const double t = 1.0 / 19.6;
  EXPECT_NEAR(seed_landing_point(s.ball, s.ball_velocity).x(), t, 1e-12);
  s.ball_prev = {0, 5, 0};
  s.ball = {0, 0, 0};  // 10 m closer in one tick: clamped to 1
  EXPECT_EQ(golf_reward_terms(s)[1], 1.0f);
}

}  // namespace
}  // namespace olympics::sports::golf
