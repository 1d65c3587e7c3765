// The long jump's settings read both ways: the seed's (paper) and World Athletics' (official).
#include <gtest/gtest.h>

#include "long_jump/long_jump_sport.h"

namespace olympics::sports::long_jump {
namespace {

TEST(LongJumpRules, PaperIsTheSeedsAndOfficialTheRulebooks) {
  const LongJumpSport sport;
  const LongJumpRules paper = sport.rules({}), official = sport.rules({{"rules", "official"}});
  EXPECT_FALSE(paper.official);
  EXPECT_EQ(paper.line_x, 20.0);
  EXPECT_EQ(paper.runway_width, 1.0);
  EXPECT_EQ(paper.attempts, 1);
  EXPECT_TRUE(official.official);
  EXPECT_EQ(official.line_x, 20.0);
  EXPECT_EQ(official.runway_width, 1.22);
  EXPECT_EQ(official.board_depth, 0.20);
  EXPECT_EQ(official.attempts, 3);
  EXPECT_EQ(official.attempt_s, 60.0);
  EXPECT_EQ(sport.rules({{"rules", "official"}, {"attempts", 6}}).attempts, 6)
      << "a setting beside the preset wins";
  EXPECT_THROW(sport.rules({{"attempts", 9}}), std::invalid_argument);
}

}  // namespace
}  // namespace olympics::sports::long_jump
