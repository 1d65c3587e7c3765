// The referee's calls on made-up sequences of touches (no physics).
#include "racket/rally_referee.h"

#include <gtest/gtest.h>

namespace olympics::sports::racket {
namespace {

const Eigen::Vector3d kTeam0Court(-6, 1, 0), kTeam1Court(6, -1, 0), kWide(6, 5, 0);
// Where the racket meets the ball when the call does not depend on it: 1 m up behind team 0's
// end line (table tennis, 1.37 m; a table-tennis serve must be struck there, ITTF 2.6.4).
const Eigen::Vector3d kBehindTeam0sEnd(-1.6, 0, 1.0);

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
  r.racket_hit(1, 0.8, kBehindTeam0sEnd);
  EXPECT_EQ(r.striker_team(), 1);
  r.surface_contact(kGround, Eigen::Vector3d(-13, 0, 0), 1.5);  // past team 0's baseline
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "out");
  EXPECT_EQ(r.call()->winner_team, 0);
  EXPECT_EQ(r.call()->culprit_slot, 1);

  r.start_point(1, 1, 2);
  r.surface_contact(kGround, kTeam1Court, 2.5);
  r.racket_hit(1, 2.8, kBehindTeam0sEnd);
  r.surface_contact(kNet, Eigen::Vector3d(0, 0, 0.9), 3.0);
  r.surface_contact(kGround, Eigen::Vector3d(1, 0, 0), 3.2);  // fell back on its own side
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "net");
}

TEST(RallyReferee, NetCordThatFallsInIsGoodAndVolleysAreAllowedInTennis) {
  auto r = tennis_singles();
  r.start_point(0, 0, 0);
  r.surface_contact(kGround, kTeam0Court, 0.3);
  r.racket_hit(0, 0.6, kBehindTeam0sEnd);
  r.surface_contact(kNet, Eigen::Vector3d(0, 0, 0.98), 0.9);
  r.surface_contact(kGround, Eigen::Vector3d(1, 0, 0), 1.1);
  EXPECT_FALSE(r.call());
  r.racket_hit(1, 1.4, kBehindTeam0sEnd);  // after the bounce
  r.racket_hit(0, 1.9, kBehindTeam0sEnd);  // a volley, before any bounce: legal in tennis
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
  r.racket_hit(0, 0.60, kBehindTeam0sEnd);
  r.racket_hit(0, 0.65, kBehindTeam0sEnd);  // still the same stroke
  EXPECT_FALSE(r.call());
  r.racket_hit(0, 0.90, kBehindTeam0sEnd);  // a second stroke on the same crossing
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
  r.racket_hit(1, 0.2, kBehindTeam0sEnd);  // before the ball bounced on the table
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "volley");

  r.start_point(1, 1, 1);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.2, 0.76), 1.2);
  r.racket_hit(1, 1.5, kBehindTeam0sEnd);
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
  r.racket_hit(1, 0.4, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.2, 0.76), 0.6);
  r.racket_hit(3, 0.8, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.8, 0.2, 0.76), 1.0);
  r.racket_hit(1, 1.2, kBehindTeam0sEnd);  // slot 1 again: its partner, slot 0, had to play
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "wrong_hitter");
  EXPECT_EQ(r.call()->winner_team, 1);
}

// Served points (`start: "serve"`). Team 0 serves from -x; its deuce serve lands in the box at
// 0 < x <= 6.40, 0 <= y <= 4.115 (the receiver's right), its ad serve at y <= 0.
ServeRule tennis_serve(bool second, int receiver_y_sign = 1) {
  ServeRule r;
  r.server_slot = 0;
  r.receiver_y_sign = receiver_y_sign;
  r.second_serve = second;
  return r;
}

TEST(RallyReferee, TennisServeInTheDiagonalBoxStartsTheRally) {
  auto r = tennis_singles();
  r.start_serve(0, tennis_serve(false), 0);
  EXPECT_TRUE(r.serving());
  r.racket_hit(0, 0.5, kBehindTeam0sEnd);
  r.surface_contact(kGround, Eigen::Vector3d(5, 2, 0), 1.2);
  EXPECT_FALSE(r.call());
  EXPECT_EQ(r.replay(), RallyReferee::Replay::None);
  EXPECT_FALSE(r.serving());
  ASSERT_FALSE(r.events().empty());
  EXPECT_EQ(r.events().back().value("call", ""), "serve_in");  // what the bench counts
  EXPECT_EQ(r.bounces(), 1);
  r.racket_hit(1, 1.5, kBehindTeam0sEnd);  // returned after the bounce
  EXPECT_FALSE(r.call());
  EXPECT_EQ(r.striker_team(), 1);
}

TEST(RallyReferee, TennisServeOutsideTheBoxIsAFaultAndTwoLoseThePoint) {
  auto r = tennis_singles();
  // Past the service line, in the wrong (ad) box, and short of the net: faults on a first serve.
  for (const Eigen::Vector3d& where :
       {Eigen::Vector3d(8, 2, 0), Eigen::Vector3d(4, -2, 0), Eigen::Vector3d(-3, 0, 0)}) {
    r.start_serve(0, tennis_serve(false), 0);
    r.racket_hit(0, 0.5, kBehindTeam0sEnd);
    r.surface_contact(kGround, where, 1.2);
    EXPECT_FALSE(r.call()) << where.transpose();
    EXPECT_EQ(r.replay(), RallyReferee::Replay::Fault) << where.transpose();
    EXPECT_EQ(r.events().back()["call"], "fault");
    r.racket_hit(1, 1.5, kBehindTeam0sEnd);  // nothing more is called till the serve is taken again
    EXPECT_FALSE(r.call());
  }
  // The same serve on the second serve loses the point.
  r.start_serve(0, tennis_serve(true), 2);
  r.racket_hit(0, 2.5, kBehindTeam0sEnd);
  r.surface_contact(kGround, Eigen::Vector3d(8, 2, 0), 3.2);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "double_fault");
  EXPECT_EQ(r.call()->winner_team, 1);
  EXPECT_EQ(r.call()->culprit_slot, 0);
  // The ad court's box is the other one.
  r.start_serve(0, tennis_serve(true, -1), 4);
  r.racket_hit(0, 4.5, kBehindTeam0sEnd);
  r.surface_contact(kGround, Eigen::Vector3d(4, -2, 0), 5.2);
  EXPECT_FALSE(r.call());
  EXPECT_FALSE(r.serving());
}

TEST(RallyReferee, TennisNetCordServeInIsALetAndAMissedTossAFault) {
  auto r = tennis_singles();
  r.start_serve(0, tennis_serve(true), 0);
  r.racket_hit(0, 0.5, kBehindTeam0sEnd);
  r.surface_contact(kNet, Eigen::Vector3d(0, 1, 0.99), 0.9);
  r.surface_contact(kGround, Eigen::Vector3d(3, 1, 0), 1.1);
  EXPECT_FALSE(r.call());  // not even on the second serve
  EXPECT_EQ(r.replay(), RallyReferee::Replay::Let);
  EXPECT_EQ(r.events().back()["call"], "let");

  r.start_serve(0, tennis_serve(false), 2);  // the toss falls untouched
  r.surface_contact(kGround, Eigen::Vector3d(-11.3, -1, 0), 3);
  EXPECT_EQ(r.replay(), RallyReferee::Replay::Fault);
  EXPECT_EQ(r.events().back()["reason"], "not_struck");

  r.start_serve(0, tennis_serve(true), 4);  // never struck within the limit
  r.check_stall(6.9, 10);
  EXPECT_FALSE(r.call());
  r.check_stall(7.1, 10);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "double_fault");

  r.start_serve(0, tennis_serve(false), 8);  // the receiver may not volley the serve
  r.racket_hit(0, 8.5, kBehindTeam0sEnd);
  r.racket_hit(1, 9.0, kBehindTeam0sEnd);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "volley");
  EXPECT_EQ(r.call()->winner_team, 0);
}

// A fall on the tick of a first fault or a let still loses the point (the match concedes the
// tick's falls before it tosses again): the ball was in play when the player fell.
TEST(RallyReferee, AFallOnTheTickOfAFaultOrALetLosesThePoint) {
  auto r = tennis_singles();
  r.start_serve(0, tennis_serve(false), 0);
  r.racket_hit(0, 0.5, kBehindTeam0sEnd);
  r.surface_contact(kGround, Eigen::Vector3d(8, 2, 0), 1.2);  // long: a first fault
  ASSERT_EQ(r.replay(), RallyReferee::Replay::Fault);
  r.concede(1, 1, "fall");  // the receiver fell on that tick
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fall");
  EXPECT_EQ(r.call()->winner_team, 0);
  EXPECT_EQ(r.call()->culprit_slot, 1);
  EXPECT_EQ(r.replay(), RallyReferee::Replay::None);

  r.start_serve(0, tennis_serve(true), 2);  // a net-cord let, and the server fell
  r.racket_hit(0, 2.5, kBehindTeam0sEnd);
  r.surface_contact(kNet, Eigen::Vector3d(0, 1, 0.99), 2.9);
  r.surface_contact(kGround, Eigen::Vector3d(3, 1, 0), 3.1);
  ASSERT_EQ(r.replay(), RallyReferee::Replay::Let);
  r.concede(0, 0, "fall");
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->winner_team, 1);
}

// Both sides fallen on the tick of a fault: a let, the point played again.
TEST(RallyReferee, BothSidesFallenOnTheTickOfAFaultIsALet) {
  auto r = tennis_singles();
  r.start_serve(0, tennis_serve(false), 4);
  r.surface_contact(kGround, Eigen::Vector3d(-11.3, -1, 0), 5);
  r.let("both sides fell", 5);
  EXPECT_FALSE(r.call());
  EXPECT_EQ(r.replay(), RallyReferee::Replay::Let);
  EXPECT_EQ(r.events().back()["call"], "let");
  EXPECT_EQ(r.events().back()["reason"], "both sides fell");
}

TEST(RallyReferee, TableTennisServeMustBounceOnTheServersCourtFirst) {
  RallyReferee r(table_tennis_game(), {0, 1}, false, false);
  ServeRule rule;  // singles: anywhere on each court
  const double z = 0.78;
  r.start_serve(0, rule, 0);
  r.racket_hit(0, 0.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.6, 0.1, z), 0.5);
  EXPECT_FALSE(r.call());
  EXPECT_TRUE(r.serving());
  r.surface_contact(kTable, Eigen::Vector3d(0.8, -0.2, z), 0.9);
  EXPECT_FALSE(r.call());
  EXPECT_FALSE(r.serving());
  r.racket_hit(1, 1.2, kBehindTeam0sEnd);  // returned after its bounce
  EXPECT_FALSE(r.call());

  // Straight onto the receiver's court: a fault, and in table tennis the point.
  r.start_serve(0, rule, 2);
  r.racket_hit(0, 2.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, -0.2, z), 2.7);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fault");
  EXPECT_EQ(r.call()->winner_team, 1);
  EXPECT_EQ(r.events()[r.events().size() - 2]["reason"], "no_bounce_on_own_court");

  // Twice on its own court, or off the end of the receiver's: faults.
  r.start_serve(0, rule, 4);
  r.racket_hit(0, 4.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.9, 0, z), 4.5);
  r.surface_contact(kTable, Eigen::Vector3d(-0.2, 0, z), 4.7);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fault");
  r.start_serve(0, rule, 6);
  r.racket_hit(0, 6.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.9, 0, z), 6.5);
  r.surface_contact(kGround, Eigen::Vector3d(2.0, 0, 0.02), 6.9);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fault");

  // A net cord that then lands in: a let.
  r.start_serve(0, rule, 8);
  r.racket_hit(0, 8.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.6, 0, z), 8.5);
  r.surface_contact(kNet, Eigen::Vector3d(0, 0, 0.9), 8.7);
  r.surface_contact(kTable, Eigen::Vector3d(0.3, 0, z), 8.8);
  EXPECT_FALSE(r.call());
  EXPECT_EQ(r.replay(), RallyReferee::Replay::Let);
}

// ITTF 2.6.4: the serve is struck behind the server's end line and above the playing surface.
TEST(RallyReferee, TableTennisServeStruckOverTheTableOrBelowItIsAFault) {
  for (const Eigen::Vector3d& ball :
       {Eigen::Vector3d(-1.2, 0, 1.0), Eigen::Vector3d(-1.5, 0, 0.7)}) {
    RallyReferee r(table_tennis_game(), {0, 1}, false, false);
    r.start_serve(0, ServeRule{}, 0);
    r.racket_hit(0, 0.3, ball);
    ASSERT_TRUE(r.call()) << ball.transpose();
    EXPECT_EQ(r.call()->reason, "fault");
    EXPECT_EQ(r.call()->winner_team, 1);
    EXPECT_EQ(r.events()[r.events().size() - 2]["reason"], "struck_over_table");
  }
  // Tennis has no such line for the ball (a foot fault is not called).
  RallyReferee tennis = tennis_singles();
  tennis.start_serve(0, tennis_serve(false), 0);
  tennis.racket_hit(0, 0.3, Eigen::Vector3d(-5, 0, 2.5));
  EXPECT_FALSE(tennis.call());
}

TEST(RallyReferee, TableTennisDoublesServeGoesRightHalfToRightHalf) {
  RallyReferee r(table_tennis_game(), {0, 0, 1, 1}, true, true);
  ServeRule rule;
  rule.server_slot = 1;
  rule.receiver_y_sign = 1;  // team 0 faces +x: its right half is y < 0, the receiver's y > 0
  const double z = 0.78;
  r.start_serve(0, rule, 0);
  r.racket_hit(1, 0.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.6, -0.3, z), 0.5);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, 0.3, z), 0.9);
  EXPECT_FALSE(r.call());
  EXPECT_FALSE(r.serving());

  r.start_serve(0, rule, 2);  // from the left half: a fault
  r.racket_hit(1, 2.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.6, 0.3, z), 2.5);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fault");

  r.start_serve(0, rule, 4);  // to the receiver's left half: a fault
  r.racket_hit(1, 4.3, kBehindTeam0sEnd);
  r.surface_contact(kTable, Eigen::Vector3d(-0.6, -0.3, z), 4.5);
  r.surface_contact(kTable, Eigen::Vector3d(0.8, -0.3, z), 4.9);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "fault");

  r.start_serve(0, rule, 6);  // the partner may not serve
  r.racket_hit(0, 6.3, kBehindTeam0sEnd);
  ASSERT_TRUE(r.call());
  EXPECT_EQ(r.call()->reason, "wrong_hitter");
}

}  // namespace
}  // namespace olympics::sports::racket
