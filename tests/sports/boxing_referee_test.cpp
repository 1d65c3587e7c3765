// The boxing referee by made-up sequences: rounds and rests, the count, knock-outs, the cards.
#include "boxing/boxing_referee.h"

#include <gtest/gtest.h>

namespace olympics::sports::boxing {
namespace {

constexpr std::array<bool, 2> kUp{false, false};

// Ticks the clock from `from` to `to` with the given boxers down.
void run(BoxingReferee& r, double from, double to, std::array<bool, 2> down = kUp) {
  for (double t = from; t <= to + 1e-9; t += 1.0 / 30) r.update(t, down);
}

TEST(BoxingReferee, RoundsRestsAndTenPointMustCards) {
  BoxingRules rules;
  rules.rounds = 2, rules.round_s = 10, rules.rest_s = 5;
  BoxingReferee r(rules);
  r.punch(0, 1), r.punch(0, 2), r.punch(1, 3);
  run(r, 0, 9.9);
  EXPECT_TRUE(r.in_round());
  EXPECT_EQ(r.totals(), (std::array<int, 2>{10, 9})) << "the round scored as it stands";
  run(r, 10.0, 10.0);
  EXPECT_TRUE(r.resting());
  ASSERT_EQ(r.cards().size(), 1u);
  EXPECT_EQ(r.cards()[0], (std::array<int, 2>{10, 9}));
  r.punch(1, 12);  // in the rest: does not count
  run(r, 10.1, 15.1);
  EXPECT_TRUE(r.in_round());
  EXPECT_EQ(r.round(), 2);
  r.punch(1, 16), r.punch(1, 17);
  run(r, 15.2, 25.3);
  ASSERT_TRUE(r.over());
  EXPECT_EQ(r.cards()[1], (std::array<int, 2>{9, 10}));
  EXPECT_EQ(r.reason(), "decision_draw") << "19-19";
  EXPECT_EQ(r.winner(), -1);
  EXPECT_EQ(r.punches(), (std::array<int, 2>{2, 3}));
}

TEST(BoxingReferee, AKnockDownCostsAPointAndBeatingTheCountResumes) {
  BoxingRules rules;
  rules.rounds = 1, rules.round_s = 30;
  BoxingReferee r(rules);
  r.punch(0, 1);
  run(r, 0, 2);
  run(r, 2.1, 6, {false, true});  // boxer 1 down for 4 s
  EXPECT_TRUE(r.counting(1));
  EXPECT_NEAR(r.down_for(1, 6), 3.9, 0.05);
  run(r, 6.1, 10.0);  // up from 6.1 s, but the count of eight runs to 10.1 s
  EXPECT_TRUE(r.counting(1));
  run(r, 10.05, 10.2);
  EXPECT_FALSE(r.counting(1)) << "up, and counted to eight: the count is beaten";
  EXPECT_EQ(r.knockdowns()[1], 1);
  run(r, 7.3, 30.1);
  ASSERT_TRUE(r.over());
  EXPECT_EQ(r.cards()[0], (std::array<int, 2>{10, 8})) << "9 for fewer punches, -1 knock-down";
  EXPECT_EQ(r.reason(), "decision");
  EXPECT_EQ(r.winner(), 0);
}

TEST(BoxingReferee, AKnockedDownBoxerIsCountedToEightEvenIfUpAtOnce) {
  BoxingRules rules;
  rules.rounds = 1, rules.round_s = 60;
  BoxingReferee r(rules);
  run(r, 0, 1);
  run(r, 1.0, 1.2, {true, false});  // down for a moment at 1 s
  run(r, 1.25, 8.9);                // up at once, and stays up
  EXPECT_TRUE(r.counting(0)) << "the mandatory eight count runs to 9 s";
  run(r, 8.95, 9.1);
  EXPECT_FALSE(r.counting(0)) << "counted to eight, up: the count is beaten";
  EXPECT_FALSE(r.over());
  // The count can be set off (0): then up for up_s beats it.
  rules.mandatory_count_s = 0;
  BoxingReferee quick(rules);
  run(quick, 0, 1);
  run(quick, 1.0, 1.2, {true, false});
  run(quick, 1.25, 2.4);
  EXPECT_FALSE(quick.counting(0));
}

TEST(BoxingReferee, StillDownWhenTheCountEndsIsAKnockOut) {
  BoxingReferee r(BoxingRules{});
  run(r, 0, 1);
  run(r, 1.0, 10.9, {true, false});
  EXPECT_FALSE(r.over());
  run(r, 11.0, 11.1, {true, false});
  ASSERT_TRUE(r.over());
  EXPECT_EQ(r.reason(), "knockout");
  EXPECT_EQ(r.winner(), 1);
  bool called = false;
  for (const auto& c : r.take_calls()) called = called || (c.call == "knockout" && c.boxer == 0);
  EXPECT_TRUE(called);
}

TEST(BoxingReferee, BothCountedOutTogetherIsADraw) {
  BoxingReferee r(BoxingRules{});
  run(r, 0, 12, {true, true});
  ASSERT_TRUE(r.over());
  EXPECT_EQ(r.reason(), "double_knockout");
  EXPECT_EQ(r.winner(), -1);
}

TEST(BoxingReferee, TheTimeLimitDecidesOnTheCardsSoFar) {
  BoxingReferee r(BoxingRules{});
  r.punch(1, 1);
  run(r, 0, 20);
  r.decide_now(20);
  ASSERT_TRUE(r.over());
  EXPECT_EQ(r.winner(), 1);
  ASSERT_EQ(r.cards().size(), 1u);
  EXPECT_EQ(r.totals(), (std::array<int, 2>{9, 10})) << "counted once";
}

}  // namespace
}  // namespace olympics::sports::boxing
