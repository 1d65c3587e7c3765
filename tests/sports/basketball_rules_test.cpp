// The rules without physics. Half court (3x3): points by where the shot was released, clearing
// behind the arc, possession after a basket, the shot clock, out of bounds, the game's end.
// Full court: each side's own basket, 2 and 3 points, throw-ins, no clearing.
#include <gtest/gtest.h>

#include "basketball/basketball_referee.h"

namespace olympics::sports::basketball {
namespace {

const Eigen::Vector2d kInside(-3, 0);    // 3 m from the rim: inside the arc
const Eigen::Vector2d kBehind(-7.5, 1);  // beyond the 6.75 m arc
const Eigen::Vector2d kCorner(-1, 7.0);  // beyond the corner line

// 1v1: slot 0 is side 0, slot 1 side 1; side 0 has the check ball at t = 0.
BasketballReferee one_on_one(TeamPlayRules rules = {}) {
  BasketballReferee r(Court{}, rules, {0, 1});
  const Restart first = r.start(0, 0.0);
  EXPECT_EQ(first.kind, RestartKind::CheckBall);
  EXPECT_EQ(first.team, 0);
  EXPECT_TRUE(Court{}.behind_arc(first.spot)) << "a check ball is taken behind the arc";
  return r;
}

TEST(BasketballRules, ABasketIsWorthOneInsideTheArcAndTwoWhereTheShooterStoodBehindIt) {
  BasketballReferee r = one_on_one();
  EXPECT_TRUE(r.cleared()) << "a check ball needs no clearing";
  r.touch(0, kInside, 1.0);
  auto s = r.update(true, false, 2.0);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->reason, "basket");
  EXPECT_TRUE(s->basket->counted);
  EXPECT_EQ(s->basket->points, 1);
  EXPECT_EQ(s->basket->shooter, 0);
  EXPECT_EQ(r.score()[0], 1);

  // Side 1 takes it under the basket, clears it in the corner, shoots from beyond the arc: the
  // release decides, not where the ball went in.
  EXPECT_EQ(s->restart.kind, RestartKind::AfterBasket);
  EXPECT_EQ(s->restart.team, 1);
  EXPECT_FALSE(Court{}.behind_arc(s->restart.spot));
  r.touch(1, s->restart.spot, 2.5);
  EXPECT_FALSE(r.cleared());
  r.touch(1, kCorner, 4.0);
  EXPECT_TRUE(r.cleared());
  r.touch(1, kBehind, 5.0);
  s = r.update(true, false, 6.0);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->basket->points, 2);
  EXPECT_EQ((std::array<int, 2>{1, 2}), r.score());
  EXPECT_EQ(s->restart.team, 0) << "possession changes after a basket";
}

TEST(BasketballRules, ABasketBeforeClearingDoesNotCountAndTheOtherSideChecksTheBall) {
  BasketballReferee r = one_on_one();
  r.touch(0, kInside, 1.0);
  auto s = r.update(true, false, 1.5);  // 1-0; side 1 takes it under the basket
  ASSERT_TRUE(s);
  r.touch(1, s->restart.spot, 2.0);
  r.touch(1, kInside, 3.0);  // never behind the arc
  s = r.update(true, false, 4.0);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->reason, "not_cleared");
  EXPECT_FALSE(s->basket->counted);
  EXPECT_EQ(s->basket->points, 0);
  EXPECT_EQ((std::array<int, 2>{1, 0}), r.score());
  EXPECT_EQ(s->restart.kind, RestartKind::CheckBall);
  EXPECT_EQ(s->restart.team, 0);
}

TEST(BasketballRules, ADefensiveReboundMustBeClearedAnOffensiveOneNeedNot) {
  BasketballReferee r = one_on_one();
  r.touch(0, kInside, 1.0);
  r.basket_touch();          // a miss off the rim
  r.touch(0, kInside, 2.0);  // offensive rebound: still cleared, the put-back counts
  EXPECT_TRUE(r.cleared());
  EXPECT_EQ(r.possession(), 0);
  r.basket_touch();
  r.touch(1, kInside, 3.0);  // defensive rebound
  EXPECT_EQ(r.possession(), 1);
  EXPECT_FALSE(r.cleared());
  auto s = r.update(true, false, 3.5);  // a put-back without clearing
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "not_cleared");
  EXPECT_EQ((std::array<int, 2>{0, 0}), r.score());
}

TEST(BasketballRules, TheShotClockRunsFromPossessionStopsOnTheRimAndRestartsOnTheNextTouch) {
  BasketballReferee r = one_on_one({.shot_clock_s = 12, .points_to_win = 21});
  r.touch(0, kBehind, 1.0);
  EXPECT_DOUBLE_EQ(r.shot_clock_left(5.0), 7.0) << "from the check ball at t = 0";
  EXPECT_FALSE(r.update(false, false, 11.9));
  r.basket_touch();  // a shot hits the rim at 11.9 s: the clock stops
  EXPECT_FALSE(r.update(false, false, 15.0));
  r.touch(0, kInside, 15.0);  // offensive rebound: a new 12 s
  EXPECT_FALSE(r.update(false, false, 26.9));
  auto s = r.update(false, false, 27.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "shot_clock");
  EXPECT_EQ(s->restart.team, 1);
  EXPECT_EQ(s->restart.kind, RestartKind::CheckBall);
  EXPECT_EQ(r.possession(), 1);
  EXPECT_DOUBLE_EQ(r.shot_clock_left(27.0), 12.0);
}

TEST(BasketballRules, AStealRestartsTheShotClockForTheOtherSide) {
  BasketballReferee r = one_on_one();
  r.touch(0, kBehind, 10.0);
  r.touch(1, kInside, 11.0);
  EXPECT_EQ(r.possession(), 1);
  EXPECT_DOUBLE_EQ(r.shot_clock_left(12.0), 11.0);
  EXPECT_FALSE(r.update(false, false, 22.9));
  EXPECT_TRUE(r.update(false, false, 23.0));
}

TEST(BasketballRules, OutOfBoundsGivesTheOtherSideTheBallAtTheArc) {
  BasketballReferee r = one_on_one();
  r.touch(0, kInside, 1.0);
  r.touch(1, kInside, 1.2);  // side 1 knocks it out
  auto s = r.update(false, true, 1.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->reason, "out");
  EXPECT_EQ(s->last_touch, 1);
  EXPECT_EQ(s->restart.team, 0);
  EXPECT_EQ(s->restart.kind, RestartKind::CheckBall);
  EXPECT_TRUE(r.cleared());
}

TEST(BasketballRules, TheBallUpThroughTheRimFromBelowIsAViolationAndTheOtherSidesBall) {
  BasketballReferee r = one_on_one();
  r.touch(0, kInside, 1.0);  // side 0 throws it up through the ring from under the basket
  const Stoppage s = r.from_below(1.4);
  EXPECT_EQ(s.reason, "from_below");
  EXPECT_FALSE(s.basket) << "no basket";
  EXPECT_EQ(s.last_touch, 0);
  EXPECT_EQ(s.restart.team, 1);
  EXPECT_EQ(s.restart.kind, RestartKind::CheckBall);
  EXPECT_EQ(r.score(), (std::array<int, 2>{0, 0}));
}

TEST(BasketballRules, ABallNobodyTouchedSinceTheRestartScoresNothing) {
  BasketballReferee r = one_on_one();
  auto s = r.update(true, false, 1.0);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->basket->shooter, -1);
  EXPECT_FALSE(s->basket->counted);
  EXPECT_EQ((std::array<int, 2>{0, 0}), r.score());
}

TEST(BasketballRules, TheGameEndsWhenASideReachesThePointsToWin) {
  BasketballReferee r = one_on_one({.shot_clock_s = 12, .points_to_win = 3});
  r.touch(0, kBehind, 1.0);
  ASSERT_TRUE(r.update(true, false, 2.0));
  EXPECT_EQ(r.winner(), -1);
  r.touch(1, kBehind, 3.0);  // side 1 clears and misses; side 0 rebounds, clears, scores
  r.touch(0, kBehind, 4.0);
  ASSERT_TRUE(r.update(true, false, 5.0));
  EXPECT_EQ(r.score()[0], 4);
  EXPECT_EQ(r.winner(), 0);
}

TEST(BasketballRules, OnTheFullCourtEachSideScoresOnItsOwnBasketWithTwoAndThreePoints) {
  Court full;
  full.full = true;
  BasketballReferee r(full, {}, {0, 1});
  const Restart first = r.start(1, 0.0);
  EXPECT_EQ(first.kind, RestartKind::Centre);
  EXPECT_NEAR(first.spot.x(), full.centre_x(), 1e-12);
  EXPECT_LT(first.facing.x(), -0.99) << "side 1 faces basket 1, at the far (-x) end";
  EXPECT_EQ(r.attacks(0), 0);
  EXPECT_EQ(r.attacks(1), 1);

  const Eigen::Vector2d far_rim = full.rim_centre(1).head<2>();
  r.touch(1, far_rim + Eigen::Vector2d(7.5, 0), 1.0);  // behind basket 1's arc
  auto s = r.update(true, false, 2.0, 1);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->basket->team, 1);
  EXPECT_EQ(s->basket->points, 3);
  EXPECT_EQ(r.score()[1], 3);
  // Side 0 throws in under basket 1, the one it defends, facing basket 0 (+x).
  EXPECT_EQ(s->restart.kind, RestartKind::ThrowIn);
  EXPECT_EQ(s->restart.team, 0);
  EXPECT_LT((s->restart.spot - far_rim).norm(), 1.5);
  EXPECT_GT(s->restart.facing.x(), 0.99);
  EXPECT_TRUE(r.cleared()) << "nothing to clear on the full court";

  // Side 1 steals it (no clearing needed) and scores inside the arc: 2.
  r.touch(0, s->restart.spot, 2.5);
  r.touch(1, far_rim + Eigen::Vector2d(2, 0), 3.0);
  EXPECT_TRUE(r.cleared());
  s = r.update(true, false, 3.5, 1);
  ASSERT_TRUE(s && s->basket);
  EXPECT_EQ(s->basket->points, 2);
  EXPECT_EQ((std::array<int, 2>{0, 5}), r.score());

  // Out of bounds and the shot clock give the other side a throw-in under the basket it defends.
  r.touch(0, {0, 0}, 4.0);
  s = r.update(false, true, 4.5);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->restart.kind, RestartKind::ThrowIn);
  EXPECT_EQ(s->restart.team, 1);
  EXPECT_LT(s->restart.spot.norm(), 1.5) << "side 1 defends basket 0";
}

}  // namespace
}  // namespace olympics::sports::basketball
