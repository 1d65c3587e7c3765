// Each reward term against values computed by hand (SPORTS.md: seed eq. 6 and eq. 8).
#include "racket/racket_rewards.h"

#include <gtest/gtest.h>

#include <cmath>

#include "equipment/landing.h"

namespace olympics::sports::racket {
namespace {

TEST(Landing, Eq6ByHand) {
  // z0 = 2, v0z = 4: T = (4 + sqrt(16 + 2 * 9.81 * 2)) / 9.81 = 1.165378 s.
  const Eigen::Vector2d land = equipment::predict_landing({0, 0, 2}, {3, 1, 4}, 0.0);
  EXPECT_NEAR(land.x(), 3.496134, 1e-5);
  EXPECT_NEAR(land.y(), 1.165378, 1e-5);
  // Table height 0.76: T = (0 + sqrt(2 * 9.81 * 0.24)) / 9.81 = 0.221198 s.
  const Eigen::Vector2d table = equipment::predict_landing({1, 0, 1.0}, {-2, 0, 0}, 0.76);
  EXPECT_NEAR(table.x(), 1 - 2 * 0.221198, 1e-5);
  // Below the height and falling: it stays where it is.
  const Eigen::Vector2d below = equipment::predict_landing({1, 2, 0.5}, {3, 0, -1}, 0.76);
  EXPECT_DOUBLE_EQ(below.x(), 1);
}

TEST(RacketRewards, BeforeTheStrokeOnlyTheRacketTermCounts) {
  RewardInput in;
  in.racket = {1, 0, 1};
  in.ball = {1, 1, 1};
  in.ball_velocity = {-10, 0, 0};
  in.target = {-9, 0};
  const auto t = racket_reward_terms(in);
  EXPECT_NEAR(t[kRacketTerm], std::exp(-1.0), 1e-6);
  EXPECT_EQ(t[kContactTerm], 0);
  EXPECT_EQ(t[kLandingTerm], 0);
  EXPECT_EQ(t[kHitsTerm], 0);
}

TEST(RacketRewards, AfterTheStrokeContactLandingAndHits) {
  RewardInput in;
  in.racket = {0, 0, 0};
  in.ball = {0, 0, 2};
  in.ball_velocity = {3, 1, 4};
  in.target = {3.5, 1.2};
  in.struck = true;
  in.hits = 2;
  auto t = racket_reward_terms(in);
  EXPECT_EQ(t[kRacketTerm], 0);
  EXPECT_EQ(t[kContactTerm], 1);
  // Landing (3.496134, 1.165378): squared miss 0.0000150 + 0.0011987.
  EXPECT_NEAR(t[kLandingTerm], std::exp(-0.0012137), 1e-5);
  EXPECT_EQ(t[kHitsTerm], 0);  // tennis: no hits term
  in.counts_hits = true;       // table tennis
  t = racket_reward_terms(in);
  EXPECT_EQ(t[kHitsTerm], 2);
}

}  // namespace
}  // namespace olympics::sports::racket
