// Series of attempts and the rankings they give (World Athletics TR 25.22, 26.8).
#include "athletics/attempt_series.h"

#include <gtest/gtest.h>

namespace olympics::sports::athletics {
namespace {

HorizontalSeries jumps(std::vector<AttemptResult> results) {
  HorizontalSeries s(static_cast<int>(results.size()));
  for (const auto& r : results) s.record(r);
  return s;
}

TEST(HorizontalSeries, BestMarkRanksFirstAndTiesGoToTheSecondBest) {
  const auto a = jumps({AttemptResult::measured(7.10), AttemptResult::foul("past_the_line"),
                        AttemptResult::measured(6.90)});
  const auto b = jumps(
      {AttemptResult::measured(7.10), AttemptResult::measured(7.00), AttemptResult::foul("time")});
  const auto c = jumps({AttemptResult::foul("past_the_line"), AttemptResult::foul("fell"),
                        AttemptResult::foul("time")});
  EXPECT_TRUE(a.done());
  EXPECT_DOUBLE_EQ(a.best(), 7.10);
  EXPECT_EQ(a.fouls(), 1);
  EXPECT_TRUE(ranks_before(b, a)) << "7.10 then 7.00 beats 7.10 then 6.90";
  EXPECT_FALSE(ranks_before(a, b));
  EXPECT_EQ(places(std::vector<HorizontalSeries>{a, b, c}), (std::vector<int>{2, 1, 3}));
  EXPECT_EQ(places(std::vector<HorizontalSeries>{c, c}), (std::vector<int>{1, 1}))
      << "no valid mark on either side: a shared place";
}

TEST(HeightSeries, ThreeFailuresInARowEndTheSeriesAndTheCountbackBreaksTies) {
  HeightSeries a({1.0, 1.1, 1.2}, 3), b({1.0, 1.1, 1.2}, 3);
  a.record(true);  // 1.0 at the first try
  EXPECT_TRUE(a.waiting());
  EXPECT_DOUBLE_EQ(a.bar_height(), 1.0) << "the bar stays until the round is over";
  a.raise();
  a.record(false), a.record(true), a.raise();         // 1.1 at the second
  a.record(false), a.record(false), a.record(false);  // out at 1.2
  EXPECT_TRUE(a.done());
  EXPECT_DOUBLE_EQ(a.best(), 1.1);
  EXPECT_EQ(a.failures_at_best(), 1);
  EXPECT_EQ(a.total_failures(), 4);
  b.record(false), b.record(true), b.raise();  // 1.0 at the second try
  b.record(true), b.raise();                   // 1.1 at the first
  EXPECT_DOUBLE_EQ(b.bar_height(), 1.2);
  EXPECT_FALSE(b.done());
  b.record(false), b.record(false), b.record(false);
  EXPECT_TRUE(ranks_before(b, a)) << "1.1 at the first try beats 1.1 at the second";
  EXPECT_EQ(places(std::vector<HeightSeries>{a, b}), (std::vector<int>{2, 1}));
}

TEST(HeightSeries, ClearingTheLastHeightEndsTheSeries) {
  HeightSeries s({0.5}, 1);
  s.record(true);
  EXPECT_TRUE(s.done());
  EXPECT_DOUBLE_EQ(s.best(), 0.5);
}

}  // namespace
}  // namespace olympics::sports::athletics
