// A vertical event's competition by rounds, stepped by hand: the bar rises only when every
// athlete still in has cleared it or is out, tries go round in start order, the countback ranks,
// and a tie for first goes to a jump-off.
#include "athletics/height_rounds.h"

#include <gtest/gtest.h>

namespace olympics::sports::athletics {
namespace {

const std::vector<double> kHeights{1.0, 1.1, 1.2};

TEST(HeightRounds, TheBarRisesOnlyWhenEveryoneStillInHasHadTheirTriesAtIt) {
  HeightRounds r(2, kHeights, 3, 0.0);
  EXPECT_TRUE(r.due(0) && r.due(1)) << "both take their first try at 1.0";
  r.record(0, true);
  EXPECT_FALSE(r.due(0));
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.0) << "B has not jumped yet";
  r.record(1, false);
  EXPECT_FALSE(r.due(0)) << "A waits at 1.0 while B takes its second try";
  EXPECT_TRUE(r.due(1));
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.0);
  r.record(0, true);  // not due: ignored
  EXPECT_EQ(r.series(0).attempts(), 1);
  r.record(1, false);
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.0) << "B's third try is still at 1.0";
  r.record(1, true);  // B clears 1.0 at its third try: the round is over
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.1);
  EXPECT_TRUE(r.due(0) && r.due(1));
  r.record(0, true), r.record(1, false);  // A clears 1.1; B fails three times
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.1);
  r.record(1, false);
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.1);
  r.record(1, false);
  EXPECT_TRUE(r.series(1).done());
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.2) << "B out: A alone goes on";
  EXPECT_TRUE(r.due(0));
  EXPECT_FALSE(r.due(1));
  r.record(0, false), r.record(0, false), r.record(0, false);
  EXPECT_TRUE(r.over());
  EXPECT_DOUBLE_EQ(r.series(0).best(), 1.1);
  EXPECT_DOUBLE_EQ(r.series(1).best(), 1.0);
  EXPECT_EQ(r.places(), (std::vector<int>{1, 2}));
}

TEST(HeightRounds, TheCountbackRanksEqualHeightsByFailures) {
  HeightRounds r(3, {1.0, 1.1}, 3, 0.0);
  r.record(0, true), r.record(1, false), r.record(2, false);  // C fails 1.0 three times
  r.record(1, true), r.record(2, false);
  r.record(2, false);
  ASSERT_DOUBLE_EQ(r.bar_height(), 1.1);
  for (int t = 0; t < 3; ++t) r.record(0, false), r.record(1, false);
  EXPECT_TRUE(r.over());
  EXPECT_EQ(r.places(), (std::vector<int>{1, 2, 3}))
      << "1.0 at the first try beats 1.0 at the second; no height last";
}

TEST(HeightRounds, AnUnbreakableTieForFirstIsSharedWithoutAJumpOff) {
  HeightRounds r(2, {1.0, 1.1}, 1, 0.0);
  r.record(0, true), r.record(1, true);
  r.record(0, false), r.record(1, false);
  EXPECT_TRUE(r.over());
  EXPECT_FALSE(r.in_jump_off());
  EXPECT_EQ(r.places(), (std::vector<int>{1, 1}));
}

TEST(HeightRounds, AJumpOffLowersTheBarWhenAllFailAndRaisesItWhileSeveralClear) {
  HeightRounds r(3, {1.0, 1.1}, 1, 0.05);
  r.record(0, true), r.record(1, true), r.record(2, true);
  r.record(0, false), r.record(1, false), r.record(2, false);  // all tied at 1.0, no failures
  ASSERT_FALSE(r.over());
  ASSERT_TRUE(r.in_jump_off());
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.05) << "one try at the next height";
  r.record(0, false), r.record(1, false), r.record(2, false);
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.0) << "all failed: lowered by the step";
  EXPECT_TRUE(r.due(0) && r.due(1) && r.due(2));
  r.record(0, true), r.record(1, true), r.record(2, false);  // C leaves the jump-off third
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.05) << "two cleared: raised by the step";
  EXPECT_FALSE(r.due(2));
  EXPECT_FALSE(r.over());
  r.record(0, false), r.record(1, true);
  EXPECT_TRUE(r.over());
  EXPECT_EQ(r.places(), (std::vector<int>{2, 1, 3}));
  EXPECT_DOUBLE_EQ(r.series(1).best(), 1.0) << "the jump-off decides places, not best heights";
}

TEST(HeightRounds, AJumpOffBarComesNoLowerThanTheFirstHeight) {
  HeightRounds r(2, {1.0}, 1, 0.05);
  r.record(0, true), r.record(1, true);
  ASSERT_TRUE(r.in_jump_off());
  for (int round = 0; round < 5; ++round) r.record(0, false), r.record(1, false);
  EXPECT_DOUBLE_EQ(r.bar_height(), 1.0);
  EXPECT_FALSE(r.over());
  EXPECT_EQ(r.places(), (std::vector<int>{1, 1})) << "undecided: first place shared so far";
}

TEST(HeightRounds, ThoseBehindTheTieKeepTheirCountbackPlaces) {
  HeightRounds r(3, {1.0, 1.1}, 1, 0.05);
  r.record(0, true), r.record(1, false), r.record(2, true);
  r.record(0, false), r.record(2, false);
  ASSERT_TRUE(r.in_jump_off());
  EXPECT_FALSE(r.due(1));
  r.record(0, false), r.record(2, true);
  EXPECT_TRUE(r.over());
  EXPECT_EQ(r.places(), (std::vector<int>{2, 3, 1}));
}

}  // namespace
}  // namespace olympics::sports::athletics
