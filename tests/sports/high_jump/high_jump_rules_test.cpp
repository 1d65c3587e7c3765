// The high jump's settings read both ways: the seed's (paper) and World Athletics' (official).
#include <gtest/gtest.h>

#include "high_jump/high_jump_sport.h"

namespace olympics::sports::high_jump {
namespace {

TEST(HighJumpRules, PaperIsTheSeedsAndOfficialTheRulebooks) {
  const HighJumpSport sport;
  const HighJumpRules paper = sport.rules({}), official = sport.rules({{"rules", "official"}});
  EXPECT_FALSE(paper.official);
  EXPECT_EQ(paper.bar_mass, 8.0);
  EXPECT_EQ(paper.bar_length, 4.1);
  EXPECT_FALSE(paper.landing_mat);
  EXPECT_EQ(paper.heights, std::vector<double>{1.0});
  EXPECT_EQ(paper.tries_per_height, 1);
  EXPECT_TRUE(official.official);
  EXPECT_EQ(official.bar_mass, 2.0);
  EXPECT_EQ(official.bar_radius, 0.015);
  EXPECT_EQ(official.bar_length, 4.0);
  EXPECT_EQ(official.upright_gap, 4.0);
  EXPECT_TRUE(official.landing_mat);
  EXPECT_EQ(official.tries_per_height, 3);
  ASSERT_EQ(official.heights.size(), 10u);
  EXPECT_NEAR(official.heights[1] - official.heights[0], 0.05, 1e-12);
  for (double h : {0.5, 1.5, 2.0})  // the seed's training heights
    EXPECT_EQ(sport.rules({{"bar_height", h}}).heights, std::vector<double>{h});
}

}  // namespace
}  // namespace olympics::sports::high_jump
