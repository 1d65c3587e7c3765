// The high jump's settings read both ways: the seed's (paper) and World Athletics' (official).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

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
  EXPECT_EQ(official.runup_radius, 25.0);
  EXPECT_EQ(sport.rules({{"rules", "official"}, {"runup_radius", 30}}).runup_radius, 30.0);
  try {  // a fan too small for the start mark is refused, saying what to set
    sport.rules({{"rules", "official"}, {"runup_radius", 15}});
    ADD_FAILURE() << "a 15 m fan leaves the start mark 20.9 m away outside";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("runup_radius"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sport.rules({{"runup_radius", 15}}).runup_radius, 15.0) << "paper has no fan";
  for (double h : {0.5, 1.5, 2.0})  // the seed's training heights
    EXPECT_EQ(sport.rules({{"bar_height", h}}).heights, std::vector<double>{h});
}

}  // namespace
}  // namespace olympics::sports::high_jump
