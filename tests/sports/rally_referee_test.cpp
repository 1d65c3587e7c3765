// The referee's calls on made-up sequences of touches (no physics).
#include "racket/rally_referee.h"

#include <gtest/gtest.h>

namespace olympics::sports::racket {
namespace {

const Eigen::Vector3d kTeam0Court(-6, 1, 0), kTeam1Court(6, -1, 0), kWide(6, 5, 0);

RallyReferee tennis_singles() { return RallyReferee(tennis_game(1.0), {0, 1}, false, false); }

TEST(RallyReferee, FedBallMustBeReturnedBeforeTheSecondBounce) {
  auto r = tennis_singles();
  r.start_point(1, 1, 0);
  r.surface_contact(kGround, kTeam1Court, 0.5);
  EXPECT_FALSE(r.call());
  r.surface_contact(kGround, kTeam1Court + Eigen::Vector3d(3, 0, 0), 1.0);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->winner_team, 0);
  EXPECT_EQ(r.call()->reason, "double_bounce");
}

TEST(RallyReferee, ReturnOutOrShortLosesForTheStriker) {
  auto r = tennis_singles();
  r.start_point(1, 1, 0);
  r.surface_contact(kGround, kTeam1Court, 0.5);
  r.racket_hit(1, 0.8);
  EXPECT_EQ(r.striker_team(), 1);
  r.surface_contact(kGround, Eigen::Vector3d(-13, 0, 0), 1.5);  // past team 0's baseline
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "out");
  EXPECT_EQ(r.call()->winner_team, 0);
  EXPECT_EQ(r.call()->culprit_slot, 1);

  r.start_point(1, 1, 2);
  r.surface_contact(kGround, kTeam1Court, 2.5);
  r.racket_hit(1, 2.8);
  r.surface_contact(kNet, Eigen::Vector3d(0, 0, 0.9), 3.0);
  r.surface_contact(kGround, Eigen::Vector3d(1, 0, 0), 3.2);  // fell back on its own side
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "net");
}

TEST(RallyReferee, NetCordThatFallsInIsGoodAndVolleysAreAllowedInTennis) {
  auto r = tennis_singles();
  r.start_point(0, 0, 0);
  r.surface_contact(kGround, kTeam0Court, 0.3);
  r.racket_hit(0, 0.6);
  r.surface_contact(kNet, Eigen::Vector3d(0, 0, 0.98), 0.9);
  r.surface_contact(kGround, Eigen::Vector3d(1, 0, 0), 1.1);
  EXPECT_FALSE(r.call());
  r.racket_hit(1, 1.4);  // after the bounce
  r.racket_hit(0, 1.9);  // a volley, before any bounce: legal in tennis
  EXPECT_FALSE(r.call());
  r.surface_contact(kGround, kWide, 2.5);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "out");
  EXPECT_EQ(r.call()->winner_team, 1);
}

TEST(RallyReferee, DoubleHitBodyTouchAndOneStrokeOnTheStrings) {
  auto r = tennis_singles();
  r.start_point(0, 0, 0);
  r.surface_contact(kGround, kTeam0Court, 0.3);
  r.racket_hit(0, 0.60);
  r.racket_hit(0, 0.65);  // still the same stroke
  EXPECT_FALSE(r.call());
  r.racket_hit(0, 0.90);  // a second stroke on the same crossing
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "double_hit");
  EXPECT_EQ(r.call()->winner_team, 1);

  r.start_point(0, 0, 1);
  r.body_touch(1, 1.2);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "body_touch");
  EXPECT_EQ(r.call()->winner_team, 0);
}

TEST(RallyReferee, BallThatStopsCountsAsBouncingAgain) {
  auto r = tennis_singles();
  r.start_point(1, 1, 0);
  double t = 0.5;
  r.surface_contact(kGround, kTeam1Court, t);
  for (int i = 0; i < 60 && !r.call(); ++i) r.surface_contact(kGround, kTeam1Court, t += 1 / 120.0);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "double_bounce");
}

TEST(RallyReferee, StallLosesForTheSideToPlay) {
  auto r = tennis_singles();
  r.start_point(1, 1, 0);
  r.check_stall(5, 10);
  EXPECT_FALSE(r.call());
  r.check_stall(10.5, 10);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->winner_team, 0);
}

TEST(RallyReferee, TableTennisForbidsVolleysAndTheFloorIsOut) {
  RallyReferee r(table_tennis_game(), {0, 1}, false, false);
  r.start_point(1, 1, 0);
  r.racket_hit(1, 0.2);  // before the ball bounced on the table
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "volley");

  r.start_point(1, 1, 1);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.2, 0.76), 1.2);
  r.racket_hit(1, 1.5);
  r.surface_contact(kGround, Eigen::Vector3d(-2.5, 0, 0), 1.9);  // over the table, no bounce
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "out");
  EXPECT_EQ(r.call()->winner_team, 0);

  r.start_point(1, 1, 2);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.2, 0.76), 2.2);
  r.surface_contact(kGround, Eigen::Vector3d(2.5, 0, 0), 2.6);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "missed");
  EXPECT_EQ(r.call()->winner_team, 0);
}

TEST(RallyReferee, TableTennisDoublesPartnersAlternate) {
  RallyReferee r(table_tennis_game(), {0, 0, 1, 1}, true, true);
  r.start_point(0, /*first_hitter=*/1, 0);
  r.surface_contact(kTable, Eigen::Vector3d(-0.8, 0.2, 0.76), 0.2);
  r.racket_hit(1, 0.4);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.2, 0.76), 0.6);
  r.racket_hit(3, 0.8);
  r.surface_contact(kTable, Eigen::Vector3d(-0.8, 0.2, 0.76), 1.0);
  r.racket_hit(1, 1.2);  // slot 1 again: its partner, slot 0, had to play
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "wrong_hitter");
  EXPECT_EQ(r.call()->winner_team, 1);
}

}  // namespace
}  // namespace olympics::sports::racket
