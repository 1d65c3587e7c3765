// The long-jump referee by sequences of steps: fouls at the line, the mark to the nearest break
// (official), the seed's mean-x measure (paper).
#include "long_jump/long_jump_referee.h"

#include <gtest/gtest.h>

#include "long_jump/long_jump_rewards.h"

namespace olympics::sports::long_jump {
namespace {

LongJumpRules official() {
  LongJumpRules r;
  r.official = true;
  r.attempt_s = 60;
  return r;
}

JumpStep running(double t, double front) {
  JumpStep s;
  s.t = t;
  s.on_ground = true;
  s.ground_front_x = front - 0.05;
  s.front_x = front;
  s.feet_front_x = front - 0.05;
  return s;
}

JumpStep flying(double t, double front) {
  JumpStep s;
  s.t = t;
  s.front_x = front;
  s.feet_front_x = front;
  return s;
}

JumpStep in_sand(double t, double nearest) {
  JumpStep s = flying(t, nearest + 1.0);
  s.in_pit = true;
  s.pit_near_x = nearest;
  return s;
}

TEST(LongJumpReferee, AnyPartPastTheLineOnTheGroundIsAFoul) {
  LongJumpReferee ref(official());
  EXPECT_FALSE(ref.step(running(1.0, 19.99)));
  const auto r = ref.step(running(1.1, 20.01));  // a toe 1 cm over, still on the board
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->valid);
  EXPECT_EQ(r->reason, "past_the_line");
  EXPECT_FALSE(ref.step(in_sand(1.5, 26.0))) << "decided once";
}

TEST(LongJumpReferee, PastTheLineInTheAirIsNoFoul) {
  LongJumpReferee ref(official());
  EXPECT_FALSE(ref.step(running(1.0, 19.95)));
  EXPECT_FALSE(ref.step(flying(1.1, 20.4)));  // took off behind the line
  EXPECT_FALSE(ref.step(in_sand(1.6, 26.30)));
  EXPECT_TRUE(ref.landed());
}

TEST(LongJumpReferee, TheMarkIsTheNearestBreakToTheLine) {
  LongJumpReferee ref(official());
  ref.step(running(1.0, 19.95));
  ref.step(flying(1.1, 21.0));
  EXPECT_FALSE(ref.step(in_sand(1.5, 26.30)));  // heels first
  EXPECT_FALSE(ref.step(in_sand(1.7, 25.85)));  // then a hand falls back, nearer the line
  EXPECT_FALSE(ref.step(in_sand(2.0, 26.90)));
  const auto r = ref.step(in_sand(2.5, 26.90));  // settled
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->valid);
  EXPECT_NEAR(r->mark, 5.85, 1e-12);
}

TEST(LongJumpReferee, TouchingTheGroundBetweenTheLineAndThePitIsAFoul) {
  LongJumpReferee ref(official());
  ref.step(running(1.0, 19.95));
  ref.step(flying(1.1, 20.5));
  const auto r = ref.step(running(1.4, 20.8));  // came down short of the pit
  ASSERT_TRUE(r);
  EXPECT_EQ(r->reason, "past_the_line");
}

TEST(LongJumpReferee, TouchingOutsideThePitNearerThanTheMarkIsAFoul) {
  LongJumpReferee ref(official());
  ref.step(flying(1.1, 21.0));
  ref.step(in_sand(1.5, 26.0));
  JumpStep beside = in_sand(1.6, 26.0);
  beside.on_ground = true, beside.ground_front_x = 25.0;  // a hand beside the pit
  const auto r = ref.step(beside);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->reason, "outside_the_pit");
}

TEST(LongJumpReferee, TheTimePerAttemptAndAFallBeforeTheJumpAreFailures) {
  LongJumpReferee slow(official());
  EXPECT_EQ(slow.step(running(60.5, 5.0))->reason, "time");
  LongJumpReferee fallen(official());
  JumpStep s = running(2.0, 10.0);
  s.down = true;
  EXPECT_EQ(fallen.step(s)->reason, "fell");
}

TEST(LongJumpReferee, ALowBodyInTheAirPastTheLineIsADiveNotAFall) {
  LongJumpReferee ref(official());
  EXPECT_FALSE(ref.step(running(1.0, 19.9)));
  JumpStep diving = flying(1.2, 21.5);
  diving.down = true;  // the fall detector fires on a body diving feet first into the pit
  EXPECT_FALSE(ref.step(diving));
  const auto r = [&] {
    ref.step(in_sand(1.4, 22.3));
    return ref.step(in_sand(1.4 + official().settle_s, 22.3));
  }();
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->valid) << r->reason;
  EXPECT_NEAR(r->mark, 2.3, 1e-9);
}

TEST(LongJumpReferee, PaperMeasuresTheMeanXAtTheFirstContactPastTheLine) {
  LongJumpRules paper;  // the seed's
  LongJumpReferee ref(paper);
  EXPECT_FALSE(ref.step(running(1.0, 19.9)));
  EXPECT_FALSE(ref.past_line());
  JumpStep air = flying(1.1, 20.3);
  EXPECT_FALSE(ref.step(air));
  EXPECT_TRUE(ref.past_line());
  JumpStep land = running(1.5, 23.0);
  land.mean_body = {22.6, 0, 0.6};
  const auto r = ref.step(land);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->valid);
  EXPECT_NEAR(r->mark, 2.6, 1e-12);
}

TEST(LongJumpReferee, PaperEndsOnLeavingTheOneMetreRunway) {
  LongJumpReferee ref(LongJumpRules{});
  JumpStep s = running(1.0, 5.0);
  s.root_y = 0.51;
  EXPECT_EQ(ref.step(s)->reason, "left_runway");
}

// Eq. 2 by hand: before the line R = r_p + 0.01 r_v; past it + 0.1 r_h + 30 r_l.
TEST(LongJumpRewards, EachTermIsTheSeedsOnAHandComputedState) {
  const Eigen::Vector3d goal{30, 0, 1};
  LongJumpRewardState s{{10, 0, 1}, {10.25, 0, 1}, goal, 7.5, false, false, 0};
  auto t = long_jump_reward_terms(s);
  EXPECT_NEAR(t[0], 0.25, 1e-6);  // 20 - 19.75 m nearer the goal
  EXPECT_NEAR(t[1], 7.5, 1e-6);
  EXPECT_EQ(t[2], 0.0f);
  EXPECT_EQ(t[3], 0.0f);
  // past the line, landing with a 5.2 m mark at a root height of 0.5, moving away (clamped)
  s = {{25, 0, 0.6}, {25, 0, 0.5}, goal, -0.2, true, true, 5.2};
  t = long_jump_reward_terms(s);
  EXPECT_EQ(t[0], 0.0f) << "sqrt(25 + 0.16) - sqrt(25 + 0.25) < 0, clamped to 0";
  EXPECT_NEAR(t[1], -0.2, 1e-6);
  EXPECT_NEAR(t[2], 0.5, 1e-6);
  EXPECT_NEAR(t[3], 5.2, 1e-6);
  const std::vector<RewardTerm> terms = long_jump_rewards();
  EXPECT_EQ(terms[0].weight, 1.0);
  EXPECT_EQ(terms[1].weight, 0.01);
  EXPECT_EQ(terms[2].weight, 0.1);
  EXPECT_EQ(terms[3].weight, 30.0);
}

}  // namespace
}  // namespace olympics::sports::long_jump
